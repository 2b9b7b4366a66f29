"""Fixtures for the regression tests of issue 10: a private config directory (the root conftest) and
a way to run the CLI in-process and see exactly what it printed."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import pytest

from armkit.cli import main


@pytest.fixture(autouse=True)
def _in_tmp_path(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Run in the test's own folder (files written to the working directory land there)."""
    monkeypatch.chdir(tmp_path)


@dataclass
class Outcome:
    code: int
    out: str
    err: str

    @property
    def one_line_refusal(self) -> bool:
        """Exit 2, exactly one line on stderr, in armkit's form, no traceback."""
        lines = self.err.splitlines()
        return (
            self.code == 2
            and len(lines) == 1
            and lines[0].startswith("armkit: error: ")
            and "Traceback" not in self.err
        )


@pytest.fixture
def cli(capsys: pytest.CaptureFixture[str]):  # type: ignore[no-untyped-def]
    def run(*argv: str) -> Outcome:
        capsys.readouterr()
        code = main(list(argv))
        got = capsys.readouterr()
        return Outcome(code, got.out, got.err)

    return run
