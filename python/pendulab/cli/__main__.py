"""``python -m pendulab.cli``: the ``pendulab`` command."""

import sys

from . import main

if __name__ == "__main__":  # not when a worker process imports the main module (multiprocessing spawn)
    sys.exit(main())
