"""Random and mutated scripts: the check never crashes or hangs, and a script that
fails its check moves nothing (the driver receives no command, the pose is unchanged)."""

from __future__ import annotations

from contextlib import suppress

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from script_arms import counting_arm

from armkit import ArmkitError
from armkit.script import ScriptCheckError, Source, check_source, run_source
from budget import cases

SEEDS = [
    "pose above = xyz 180 0 80 pitch -90\npose rest = joints 0 -60 20 40\nmove above\n"
    "line 180 0 40mm\nmove rest\ngrip open\nwait 250ms\nhome\n",
    "define dip(spot, depth)\n  move spot\n  line xyz 180 0 depth pitch -90\n  move spot\nend\n"
    "pose a = xyz 180 0 80 pitch -90\nrepeat 3\n  dip a 30\n  turn waist by 10\nend\n",
    "speed 50%\nspeed 40 mm/s\njoints 10 -30 20 10\nturn elbow by -5deg\nturn wrist 0.5rad\n",
    "pose p = xyz 150 0 30 pitch -90\npick p\nplace xyz 150 60 30\nmove-item p to here\n",
]
WORDS = [
    "move", "line", "joints", "turn", "grip", "home", "wait", "speed", "light", "run", "pose",
    "repeat", "define", "end", "xyz", "pitch", "by", "open", "close", "here", "above", "rest",
    "waist", "wrist", "=", "(", ")", ",", "#", '"', "mm", "cm", "deg", "s", "%", "mm/s", "pick",
    "draw", "stack", "a", "f", "-x", "on", "to",
]  # fmt: skip
NUMBERS = st.one_of(
    st.integers(-400, 400).map(str),
    st.floats(-1e6, 1e6, allow_nan=False).map(lambda v: f"{v:g}"),
    st.sampled_from(["1.5s", "20mm", "-90", "1e400", "0", "3cm", "90deg", "1000000", "2x"]),
)
TOKEN = st.one_of(st.sampled_from(WORDS), NUMBERS, st.text(max_size=4))
LINE = st.lists(TOKEN, max_size=8).map(" ".join)
SOUP = st.lists(LINE, max_size=12).map("\n".join)


@st.composite
def mutated(draw: st.DrawFn) -> str:
    """A seed script with characters or lines deleted, inserted, swapped or repeated."""
    text = draw(st.sampled_from(SEEDS))
    for _ in range(draw(st.integers(1, 4))):
        k = draw(st.integers(0, max(0, len(text) - 1)))
        how = draw(st.sampled_from(["delete", "insert", "line", "dup"]))
        if how == "delete":
            text = text[:k] + text[k + 1 :]
        elif how == "insert":
            text = text[:k] + draw(st.sampled_from([*WORDS, "9", " ", "\n", "x"])) + text[k:]
        else:
            lines = text.splitlines()
            j = draw(st.integers(0, len(lines) - 1))
            lines = lines[:j] + lines[j + 1 :] if how == "line" else lines[: j + 1] + lines[j:]
            text = "\n".join(lines)
    return text


def _exercise(text: str) -> None:
    result = check_source(Source("fuzz.arm", text))  # never raises
    assert all(d.loc.line >= 1 and d.loc.col >= 1 for d in result.diagnostics)
    arm, driver = counting_arm()
    try:
        before = arm.driver.read()
        if not result.ok:
            try:
                run_source(arm, Source("fuzz.arm", text))
            except ScriptCheckError:
                pass
            else:
                raise AssertionError("a script that failed its check ran")
            assert driver.sent == 0
            assert np.array_equal(arm.driver.read(), before)
        elif result.plan.unknown == 0 and result.plan.total < 5.0:
            with suppress(ArmkitError):  # refused or failed with a message: allowed; a crash is not
                run_source(arm, Source("fuzz.arm", text))
    finally:
        arm.close()


FUZZ = settings(
    max_examples=cases(full=80, quick=25),
    derandomize=True,  # a fixed sequence of examples: the same run every time
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)


@FUZZ
@given(SOUP)
def test_random_scripts(text: str) -> None:
    _exercise(text)


@FUZZ
@given(mutated())
def test_mutated_scripts(text: str) -> None:
    _exercise(text)
