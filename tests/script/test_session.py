"""The shell's session without a terminal: statements, blocks, completion, teach and repeat."""

from __future__ import annotations

import io
import re
from pathlib import Path

import numpy as np
import pytest
from script_arms import CountingDriver, counting_arm

from armkit import Arm
from armkit.script import Source, run_source
from armkit.script._session import Session
from armkit.script._shell import Shell, completions


def test_statements_run_and_errors_do_not_move(
    arm: tuple[Arm, CountingDriver], tmp_path: Path
) -> None:
    a, driver = arm
    s = Session(a, base_dir=tmp_path)
    assert s.handle("pose above = xyz 180 0 80 pitch -90").text == ""
    assert s.handle("move above").text == ""
    sent = driver.sent
    reply = s.handle("move abve")
    assert reply.text.startswith("<shell>:3:6: error: undefined pose 'abve'")
    assert "did you mean 'above'?" in reply.text and "\n    move abve\n         ^" in reply.text
    assert driver.sent == sent
    assert re.match(
        r"gripper at x 180\.\d y -?0\.\d z 80\.\d mm, pitch -(89|90)\.\d deg\njoints waist",
        s.handle("where").text,
    )


def test_blocks_continue_until_end(arm: tuple[Arm, CountingDriver], tmp_path: Path) -> None:
    a, _ = arm
    s = Session(a, base_dir=tmp_path)
    assert s.handle("define nod(d)").more
    assert s.handle("  turn wrist by d").more
    assert s.handle("  turn wrist by -d").more
    assert not s.handle("end").more
    assert s.handle("repeat 2").more
    assert s.handle("nod 10").more
    assert s.handle("end").text == ""
    assert s.handle("define nod(d)").more  # a procedure may be defined again in the shell
    assert s.handle("  turn wrist by d").more
    assert s.handle("end").text == ""


def test_headers_belong_on_the_command_line(
    arm: tuple[Arm, CountingDriver], tmp_path: Path
) -> None:
    a, _ = arm
    assert (
        "armkit --arm NAME --driver NAME shell"
        in Session(a, base_dir=tmp_path).handle("arm lynx6").text
    )


def test_completion_of_commands_poses_and_joints(
    arm: tuple[Arm, CountingDriver], tmp_path: Path
) -> None:
    a, _ = arm
    s = Session(a, base_dir=tmp_path)
    s.handle("pose above = xyz 180 0 80 pitch -90")
    s.handle("pose abyss = joints 0 0 0 0")
    assert completions(s, "", "mo") == ["move", "move-item"]
    assert completions(s, "move ", "ab") == ["above", "abyss"]
    assert completions(s, "turn ", "w") == ["waist", "wrist"]
    assert completions(s, "", "wr") == ["write"]


def test_teach_write_and_run_reach_the_same_poses(tmp_path: Path) -> None:
    a, _ = counting_arm()
    s = Session(a, base_dir=tmp_path)
    taught: list[np.ndarray] = []
    for step in ("jog iiijjjff", "save grab", "jog kkkkkkuuuuv", "grip 30", "move grab",
                 "turn elbow by -10", "move xyz 150 -60 70 pitch -45"):  # fmt: skip
        if step.startswith("jog"):
            s.jog(iter(step[4:] + "\n"), 5.0, lambda _text: None)
        else:
            reply = s.handle(step).text
            assert not reply.startswith(("error", "<shell>")), reply
        taught.append(a.driver.read())
    assert s.handle("write taught.arm").text.startswith("wrote")
    a.close()

    b, _ = counting_arm()
    replayed: list[np.ndarray] = []
    path = tmp_path / "taught.arm"
    hook = lambda _st, _fr: replayed.append(b.driver.read())  # noqa: E731  before each statement
    run_source(b, Source(str(path), path.read_text()), on_step=hook)
    replayed.append(b.driver.read())
    for want in taught:  # every taught pose is reached again, within 0.1 deg on every joint
        assert min(float(np.max(np.abs(np.degrees(got - want)))) for got in replayed) < 0.1
    assert float(np.max(np.abs(np.degrees(replayed[-1] - taught[-1])))) < 0.1
    b.close()


def test_jog_on_the_owi_runs_the_motors_250_ms(tmp_path: Path) -> None:
    a, driver = counting_arm("owi535")
    s = Session(a, base_dir=tmp_path)
    before = a.angles()["shoulder"]
    shown: list[str] = []
    s.jog(iter("jjls\n"), 5.0, shown.append)
    assert a.angles()["shoulder"] > before
    assert driver.sent == 4
    assert s.teaching.lines[-3].startswith("joints 0.000 ")
    assert s.teaching.lines[-2:] == ["light on", "grip open"]
    a.close()


def test_the_shell_loop_reads_lines_and_quits(
    arm: tuple[Arm, CountingDriver], tmp_path: Path
) -> None:
    a, _ = arm
    out = io.StringIO()
    stdin = io.StringIO("move xyz 180 0 80 pitch -90\nmvoe\nturn waist by 10\nwhere\nquit\nhome\n")
    assert Shell(Session(a, base_dir=tmp_path), stdin=stdin, stdout=out).loop() == 1  # mvoe
    text = out.getvalue()
    assert "armkit x 180 y 0 z 80 p -90> " in text
    assert "unknown command 'mvoe'" in text
    assert a.angles()["waist"] == pytest.approx(10, abs=0.2)  # and 'home' after quit never ran


def test_jog_on_piped_input_is_refused_and_the_next_line_is_a_command(
    arm: tuple[Arm, CountingDriver], tmp_path: Path
) -> None:
    """Piped lines are commands, never jog keys: 'jog' says why not and what to write,
    sends nothing, saves no pose, records nothing; the shell reads on (was: the next
    line was eaten as keys, 'v' of 'move' saving p1 and 'e' of 'xyz' turning the wrist)."""
    a, driver = arm
    s = Session(a, base_dir=tmp_path)
    lines, sent = list(s.teaching.lines), driver.sent
    out = io.StringIO()
    assert Shell(s, stdin=io.StringIO("jog\njog 10\n"), stdout=out).loop() == 1
    said = [t for t in out.getvalue().split("\n") if "jog" in t]
    assert len(said) == 2 and said[0] == said[1]  # one line each, the same
    assert said[0].endswith(
        "error: jog reads single keys from a terminal and this input is not one (lines piped "
        "or from a file), so nothing moved; write the moves as lines instead: turn waist by 5, "
        "joints A1 ... An, move xyz X Y Z [pitch P], grip open|close"
    )
    assert "jog keys:" not in out.getvalue()
    assert driver.sent == sent and s.teaching.lines == lines and not s.resolver.poses

    out = io.StringIO()
    stdin = io.StringIO("jog\nmove xyz 200 0 100 pitch -45\nwhere\n")
    assert Shell(s, stdin=stdin, stdout=out).loop() == 1  # the refused jog
    assert "gripper at x 200.0 y 0.0 z 100.0 mm, pitch -45.0 deg" in out.getvalue()
    assert not s.resolver.poses  # no 'v' key saved a pose
    assert s.teaching.lines == [*lines, "move xyz 200 0 100 pitch -45"]


@pytest.mark.parametrize(
    ("line", "said"),
    [
        ("where extra", "<shell>:1:1: error: where takes no argument, got 'extra'"),
        ("poses x", "<shell>:1:1: error: poses takes no argument, got 'x'"),
        ("quit now", "<shell>:1:1: error: quit takes no argument, got 'now'"),
        ("exit 0 1", "<shell>:1:1: error: exit takes no argument, got '0 1'"),
        ("limp please", "<shell>:1:1: error: limp takes no argument, got 'please'"),
        ("hold it", "<shell>:1:1: error: hold takes no argument, got 'it'"),
        (
            "help move x",
            "<shell>:1:1: error: help takes at most one WORD (help [WORD]), got 'move x'",
        ),
        (
            "jog 5 6",
            "<shell>:1:1: error: jog takes at most one STEP_DEG (jog [STEP_DEG]), got '5 6'",
        ),
        ("save", "<shell>:1:1: error: save takes one NAME (save NAME), got none"),
        ("save a b", "<shell>:1:1: error: save takes one NAME (save NAME), got 'a b'"),
        ("write", "<shell>:1:1: error: write takes one FILE (write FILE), got none"),
        ("write a.arm b", "<shell>:1:1: error: write takes one FILE (write FILE), got 'a.arm b'"),
        (
            "run a.arm b",
            "<shell>:1:1: error: run takes one FILE (run FILE), got 'a.arm b'; "
            "a timed motor is run JOINT forward|backward|left|right TIME",
        ),
    ],
)
def test_shell_words_refuse_extra_words_and_do_nothing(
    arm: tuple[Arm, CountingDriver], tmp_path: Path, line: str, said: str
) -> None:
    """A shell word with too many (or, for save and write, no) words says so in one line and
    does nothing else (was: 'where extra' printed where, 'quit now' quit, 'jog 5 6' jogged)."""
    a, driver = arm
    s = Session(a, base_dir=tmp_path)
    lines, sent = list(s.teaching.lines), driver.sent
    reply = s.handle(line)
    assert (reply.text, reply.quit, reply.jog, reply.more) == (said, False, None, False)
    assert driver.sent == sent and s.teaching.lines == lines and not s.resolver.poses
    assert list(tmp_path.iterdir()) == [] and not s.limp
    assert s.handle("where").text.startswith("gripper at")  # the next line is read as usual


def test_a_block_with_no_end_when_the_input_ends_says_nothing_of_it_ran(
    arm: tuple[Arm, CountingDriver], tmp_path: Path
) -> None:
    """Was: the half-typed block was dropped without a word. Piped, the exit status is 1,
    as for any line that fails."""
    a, driver = arm
    s = Session(a, base_dir=tmp_path)
    out = io.StringIO()
    stdin = io.StringIO("where\nrepeat 3\n  turn wrist by 5\n  repeat 2\n  end\n")
    assert Shell(s, stdin=stdin, stdout=out).loop() == 1
    assert driver.sent == 0
    assert out.getvalue().endswith(
        "... ... ... ... <shell>:2:1: error: the repeat block opened at line 2 has no 'end' before the "
        "input ended; nothing of it ran\n"
    )
    assert s.end_of_input().text == ""  # said once, the block dropped
    out = io.StringIO()  # a closed block: no such line
    assert Shell(s, stdin=io.StringIO("define f\nturn wrist by 5\nend\n"), stdout=out).loop() == 0
    assert "error" not in out.getvalue()
