"""``python -m pendulab.cli``: the ``pendulab`` command."""

import sys

from . import main

sys.exit(main())
