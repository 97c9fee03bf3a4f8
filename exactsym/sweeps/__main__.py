"""``python -m exactsym.sweeps ...`` (the guard matters: Dask's worker processes are
spawned and import the main module again)."""

import sys

from .cli import main

if __name__ == "__main__":
    sys.exit(main())
