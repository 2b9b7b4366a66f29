"""Every input language armkit reads, fuzzed (issue 33): shipped files mutated (byte
flips, truncation, huge numbers, NaN, unicode, deep nesting, very long lines, CRLF,
a BOM, UTF-16, splices) and hand-written nasty cases, each run through the command
that reads it (and, when refused, the one that moves) on a fresh simulated arm.

Per case: no traceback or Python error word on stderr, exit status 0, 1 or 2, a
refusal in one ``armkit: error:`` line, no hang (processor time, a generous bound:
a hang detector, not a speed test), and nothing moved or written before a refusal.
``ARMKIT_FUZZ_BUDGET`` cases per language (a few in ``make test``; ``.ci/run`` and
benchmarks/fuzz.py run 1,000)."""

from __future__ import annotations

import pytest
from fuzz_engine import budget, failures, run_cases
from fuzz_languages import LANGUAGES


@pytest.mark.parametrize("name", list(LANGUAGES))
def test_every_case_is_refused_or_accepted_and_nothing_moves_before_a_refusal(name: str) -> None:
    cases = LANGUAGES[name].cases(budget())
    outcomes = run_cases(cases)
    bad = [" ".join(str(o).split())[:600] for o in failures(outcomes)]
    assert bad == [], "\n".join(bad)
    assert len(outcomes) == len(cases)


def test_case_numbers_name_the_same_case_on_every_run() -> None:
    for lang in LANGUAGES.values():
        assert lang.case(5) == lang.case(5)
        assert lang.case(6).label.startswith(f"{lang.name} #6 ")
