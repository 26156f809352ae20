"""``python -m pendulab``: the ``pendulab`` command, as ``python -m pendulab.cli`` (docs/cli.md)."""

if __name__ == "__main__":  # not when a worker process imports the main module (multiprocessing spawn)
    from pendulab.cli import main

    main()
