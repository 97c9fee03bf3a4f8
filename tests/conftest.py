"""Test-wide settings.

Under CI (the environment variable CI is set, as `.ci/run` runs) hypothesis is derandomized:
a submission's verdict must not depend on the draw. Locally the examples stay random, so
repeated runs keep exploring.
"""

import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")
