"""exactsym: the leader-election and gathering algorithms of Gan Chaudhuri and
Mukhopadhyaya, *Leader Election and Gathering for Asynchronous Transparent Fat Robots
without Chirality*, made executable with exact arithmetic and checked against the truth."""

__version__ = "0.1.0"

# The public API (docs/api.md).  Note: this binds the name ``exactsym.plot`` to the
# function; the package's modules are reached as ``from exactsym.plot import run``.
from .plot import plot  # noqa: E402

__all__ = ["plot", "__version__"]
