"""How many random cases a fuzz or property test tries: the full budget under
``ARMKIT_PROFILE=ci`` (``.ci/run``), a quick one otherwise (``make test``, a developer's
run). The cases are the same on every run of a profile (the tests derandomize), and the
quick cases are the first ones of the full run's kind, so ``make test`` runs every check
``.ci/run`` runs, on fewer inputs. Hypothesis' own default (tests that give no number)
follows the same switch through the profiles registered in tests/conftest.py."""

from __future__ import annotations

import os

FULL = os.environ.get("ARMKIT_PROFILE") == "ci"


def cases(full: int, quick: int) -> int:
    """``full`` under ``ARMKIT_PROFILE=ci``, else ``quick`` (a test's number of cases)."""
    return full if FULL else quick
