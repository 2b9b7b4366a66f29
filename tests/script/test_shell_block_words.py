"""Shell words typed while a block is open (after 'repeat 3') are never part of it. Was:
they joined the block, so 'quit' did not quit and 'where' made the block fail at 'end'
('unknown command')."""

from __future__ import annotations

import io
from pathlib import Path

import pytest
from script_arms import CountingDriver

from armkit import Arm
from armkit.script._session import Session
from armkit.script._shell import Shell


def test_quit_inside_a_block_quits_and_drops_the_block(
    arm: tuple[Arm, CountingDriver], tmp_path: Path
) -> None:
    a, driver = arm
    out = io.StringIO()
    stdin = io.StringIO("repeat 3\n  turn wrist by 5\nquit\nend\nhome\n")
    assert Shell(Session(a, base_dir=tmp_path), stdin=stdin, stdout=out).loop() == 0
    said = out.getvalue().splitlines()
    assert said[-1].endswith(
        "> ... ... quit: the repeat block opened at line 1 was dropped: nothing of it ran"
    )
    assert driver.sent == 0  # neither the block nor the lines after quit ran


def test_where_poses_and_help_are_answered_and_the_block_goes_on(
    arm: tuple[Arm, CountingDriver], tmp_path: Path
) -> None:
    a, _ = arm
    s = Session(a, base_dir=tmp_path)
    assert s.handle("repeat 2").more
    for word, start in (
        ("where", "gripper at x "),
        ("poses", "no poses yet"),
        ("help turn", "turn JOINT"),
    ):
        reply = s.handle(word)
        assert reply.more and not reply.failed and reply.text.startswith(start), reply
    assert s.handle("  turn waist by 5").more
    reply = s.handle("end")
    assert (reply.text, reply.failed) == ("", False)
    assert a.angles()["waist"] == pytest.approx(10, abs=0.2)
    assert s.teaching.lines == ["repeat 2", "  turn waist by 5", "end"]


def test_the_block_keeps_the_line_numbers_it_was_typed_on(
    arm: tuple[Arm, CountingDriver], tmp_path: Path
) -> None:
    a, _ = arm
    s = Session(a, base_dir=tmp_path)
    for line in ("repeat 2", "where", "  turn waist by 500"):
        s.handle(line)
    assert s.handle("end").text.startswith("<shell>:3:3: error: waist ")


@pytest.mark.parametrize("line", ["save p", "write x.arm", "jog", "limp", "hold", "run x.arm"])
def test_other_shell_words_are_refused_inside_a_block_and_it_stays_open(
    arm: tuple[Arm, CountingDriver], tmp_path: Path, line: str
) -> None:
    a, driver = arm
    s = Session(a, base_dir=tmp_path)
    s.handle("repeat 2")
    reply = s.handle(line)
    word = "run FILE" if line.startswith("run") else line.split()[0]
    assert reply.more and reply.failed and reply.jog is None and not reply.quit
    assert reply.text == (
        f"<shell>:2:1: error: {word} is a shell word, not a statement a block can hold, and the repeat "
        "block opened at line 1 is open: nothing done; finish the block with end, or quit "
        "to drop it"
    )
    assert list(tmp_path.iterdir()) == [] and not s.resolver.poses and not s.limp
    assert s.handle("  turn waist by 5").more
    assert s.handle("end").text == ""
    assert driver.sent == 2
