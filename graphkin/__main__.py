"""``python -m graphkin``: the same command line as ``graphkin``."""

import sys

from graphkin.cli import main

sys.exit(main())
