"""``python -m pendulab.cli``: the ``pendulab`` command."""

from . import main

if __name__ == "__main__":  # not when a worker process imports the main module (multiprocessing spawn)
    main()
