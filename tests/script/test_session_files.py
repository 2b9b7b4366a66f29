"""The shell's run and write say in words why a file cannot be used (they printed
'[Errno 21] Is a directory: ...' and 'No such file or directory')."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from script_arms import counting_arm

from armkit.script._session import Session


@pytest.mark.parametrize(
    ("line", "says"),
    [
        ("run .", "<shell>:1:1: error: cannot run {d}: it is a directory; give a script file (.arm) in it"),
        ("run none.arm", "<shell>:1:1: error: cannot run {d}/none.arm: no such file; give a script file (.arm)"),
        ("run bin.arm", "<shell>:1:1: error: cannot run {d}/bin.arm: it is not a text file (UTF-8); give a script file (.arm)"),
        ("write .", "<shell>:1:1: error: cannot write {d}: it is a directory; give a file name in it, such as {d}/taught.arm"),
        ("write /proc/x.arm", "<shell>:1:1: error: cannot write /proc/x.arm: the folder /proc does not take new files ("),
    ],
)  # fmt: skip
def test_run_and_write_refuse_in_words(tmp_path: Path, line: str, says: str) -> None:
    if line.endswith("/proc/x.arm") and not os.path.isdir("/proc"):
        pytest.skip("no /proc here")
    (tmp_path / "bin.arm").write_bytes(b"\x7fELF\x02\x01\x01\x00\xff\xfe")
    a, _ = counting_arm()
    reply = Session(a, base_dir=tmp_path).handle(line).text
    assert reply.startswith(says.format(d=tmp_path)), reply
    assert "Errno" not in reply and reply.count("\n") == 0
    a.close()


def test_write_counts_its_lines_in_words(tmp_path: Path) -> None:
    a, _ = counting_arm()
    s = Session(a, base_dir=tmp_path)
    assert s.handle("write none.arm").text.startswith("wrote 0 lines to ")
    assert s.handle("save p").text.startswith("saved: ")
    assert s.handle("write one.arm").text.startswith("wrote 1 line to ")
    a.close()
