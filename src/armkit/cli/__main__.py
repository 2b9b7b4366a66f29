"""``python -m armkit.cli``: the ``armkit`` command."""

import sys

from ._app import main

sys.exit(main())
