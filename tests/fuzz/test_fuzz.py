"""Every input language armkit reads, fuzzed (issue 33): shipped files mutated (byte
flips, truncation, huge numbers, NaN, unicode, deep nesting, very long lines, CRLF,
a BOM, UTF-16, splices) and hand-written nasty cases, each run through the command
that reads it (and, when refused, the one that moves) on a fresh simulated arm.

Per case: no traceback or Python error word on stderr, exit status 0, 1 or 2, a
refusal in one ``armkit: error:`` line, no hang (processor time, a generous bound:
a hang detector, not a speed test), and nothing moved or written before a refusal.
A few cases per language in ``make test``, 1,000 under ``ARMKIT_PROFILE=ci`` (``.ci/run``)
and in benchmarks/fuzz.py (its table is in docs/limits.md); ``ARMKIT_FUZZ_BUDGET=N`` for N.
The cases are run in chunks, so that the suite's workers share a large budget."""

from __future__ import annotations

import pytest
from fuzz_engine import budget, failures, run_cases
from fuzz_languages import LANGUAGES

CHUNK = 100  # cases of one language in one test
CHUNKS = [(name, first) for name in LANGUAGES for first in range(0, budget(), CHUNK)]


@pytest.mark.parametrize(("name", "first"), CHUNKS)
def test_every_case_is_refused_or_accepted_and_nothing_moves_before_a_refusal(
    name: str, first: int
) -> None:
    numbers = range(first, min(first + CHUNK, budget()))
    cases = [LANGUAGES[name].case(k) for k in numbers]
    outcomes = run_cases(cases)
    bad = [" ".join(str(o).split())[:600] for o in failures(outcomes)]
    assert bad == [], "\n".join(bad)
    assert len(outcomes) == len(cases)


def test_case_numbers_name_the_same_case_on_every_run() -> None:
    for lang in LANGUAGES.values():
        assert lang.case(5) == lang.case(5)
        assert lang.case(6).label.startswith(f"{lang.name} #6 ")
