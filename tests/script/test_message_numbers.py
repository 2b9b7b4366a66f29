"""A huge number in a script is shown compactly in its message. Was: 'turn waist by
1e308' printed the angle with all its 309 digits ('waist 1000000000000000010979...00
deg is outside its limits'), and 'repeat 1e308' the count the same way."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from armkit.script import Source, check_source
from armkit.script._diagnostics import compact_numbers
from armkit.script._session import Session

LONG = re.compile(r"\d{10,}")


@pytest.mark.parametrize(
    ("text", "shown"),
    [
        ("turn waist by 1e9\n", "waist 1e+09 deg is outside its limits -180.00..180.00 deg"),
        ("turn waist 1e9\n", "waist 1e+09 deg is outside its limits"),
        ("joints 1e9 0 0 0\n", "waist 1e+09 deg is outside its limits"),
        ("repeat 1e9\n  home\nend\n", "got 1e+09"),
        ("turn waist by 1e308\n", "1e308 is larger than 1e+09"),  # as written: MAX_NUMBER
    ],
)
def test_check_shows_huge_numbers_in_three_digits(text: str, shown: str) -> None:
    result = check_source(Source("b.arm", text))
    (message,) = [d.message for d in result.diagnostics if d.severity == "error"]
    assert shown in message and not LONG.search(message), message


def test_the_shell_shows_them_so_too(tmp_path: Path) -> None:
    from script_arms import counting_arm

    a, driver = counting_arm()
    reply = Session(a, base_dir=tmp_path).handle("turn waist by 1e9")
    assert reply.text.startswith("<shell>:1:1: error: waist 1e+09 deg is outside its limits")
    assert not LONG.search(reply.text) and reply.failed and driver.sent == 0
    a.close()


@pytest.mark.parametrize(
    ("text", "compact"),
    [
        ("got 123456789.00 deg", "got 123456789.00 deg"),  # nine digits: as written
        ("got 1234567890.50 deg.", "got 1.23e+09 deg."),
        ("(-12345678901, 0)", "(-1.23e+10, 0)"),
        ("cannot read /tmp/12345678901234/x.arm", "cannot read /tmp/12345678901234/x.arm"),
        ("pose p_12345678901", "pose p_12345678901"),
    ],
)
def test_only_numbers_standing_alone_are_shortened(text: str, compact: str) -> None:
    assert compact_numbers(text) == compact
