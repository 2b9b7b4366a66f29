"""The bench modules of the device tests (their tables copied from the makers' manuals)
are imported here too."""

from __future__ import annotations

import sys
from pathlib import Path

for folder in ("dynamixel", "servo"):
    sys.path.insert(0, str(Path(__file__).parent.parent / folder))
