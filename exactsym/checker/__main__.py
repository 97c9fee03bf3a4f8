"""``python -m exactsym.checker CERT.json``: the standalone checker."""

import sys

from . import main

sys.exit(main())
