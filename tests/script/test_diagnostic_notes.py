"""Diagnostics say each failure once: recursion's notes collapsed, the same failure
at several lines reported at the first with the others named."""

from __future__ import annotations

from pathlib import Path

import pytest

from armkit.cli import main
from armkit.script import Source, check_source
from armkit.script._ast import Loc
from armkit.script._diagnostics import Diagnostic, collapse

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "scripts"


def test_a_procedure_calling_itself_is_one_note_with_a_count() -> None:
    """It printed 'note: in f called at line 2' 50 times."""
    result = check_source(Source("r.arm", "define f\n  f\nend\nf\n"))
    (d,) = result.diagnostics
    assert "f must not call itself" in d.message
    assert d.notes == ("in f called at line 2 (49 times)", "in f called at line 4")
    assert d.format(result.program.source).count("note:") == 2


def test_procedures_calling_each_other_repeat_as_a_block() -> None:
    text = "define f\n  g\nend\ndefine g\n  f\nend\nf\n"
    (d,) = check_source(Source("r.arm", text)).diagnostics
    assert d.notes[0] == "in g called at line 2; in f called at line 5 (24 times)"
    assert len(d.notes) == 3


def test_collapse_keeps_single_notes_and_order() -> None:
    assert collapse(["a", "b", "a"]) == ("a", "b", "a")
    assert collapse(["a", "a", "b", "c", "b", "c", "d"]) == ("a (2 times)", "b; c (2 times)", "d")
    assert collapse([]) == ()
    assert Diagnostic(Loc(1, 1), "m", notes=("x",) * 3).notes == ("x (3 times)",)


def test_the_same_failure_at_two_lines_counts_once(
    capsys: pytest.CaptureFixture[str],
) -> None:
    """On the Lynx6, 06_dip's pose is out of reach at both 'move spot' lines: one error,
    with 'the same at line 5'; the line between them is checked from where the refused
    move left the arm (unmoved), and is out of reach too; and line 10's joint name."""
    assert main(["--arm", "lynx6", "check", str(EXAMPLES / "06_dip.arm")]) == 2
    err = capsys.readouterr().err
    assert err.count(": error: lynx6 cannot reach") == 1
    assert "note: the same at line 5" in err
    assert "06_dip.arm:4:3: error: point 0 of 93" in err
    assert "(3 errors in" in err


def test_the_same_failure_at_a_hundred_thousand_lines_names_twenty() -> None:
    """A script of 100,000 stray 'end' lines (found by the fuzzer: its check hung,
    comparing each place with every other) is one error naming 20 places and the count."""
    result = check_source(Source("ends.arm", "home\n" + "end\n" * 100_000))
    (error,) = result.diagnostics
    assert error.loc == Loc(2, 1)
    (note,) = error.notes
    assert note == "the same at lines " + ", ".join(map(str, range(3, 23))) + " and 99979 more"
