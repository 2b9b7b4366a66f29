"""``armkit._progress.Progress``: nothing for a quick job; on a terminal one line rewritten
in place and ended; elsewhere whole lines, the final count last."""

from __future__ import annotations

import io

import pytest

import armkit._progress as progress
from armkit._progress import Progress


class Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


@pytest.fixture
def eager(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every update shows (no waiting for the first second or between lines); no time passes."""
    monkeypatch.setattr(progress, "_now", lambda: 100.0)
    monkeypatch.setattr(progress, "SHOW_AFTER", 0.0)
    monkeypatch.setattr(progress, "EVERY", 0.0)
    monkeypatch.setattr(progress, "REDRAW", 0.0)


def test_a_quick_job_shows_nothing(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(progress, "_now", lambda: 100.0)
    out = io.StringIO()
    with Progress("drawing", 3, "strokes", stream=out) as bar:
        for k in range(4):
            bar.update(k)
    assert out.getvalue() == ""


@pytest.mark.usefixtures("eager")
def test_lines_when_the_stream_is_no_terminal() -> None:
    out = io.StringIO()
    with Progress("drawing", 3, "strokes", stream=out) as bar:
        bar.update(1)
        bar.update(2, "method ccd")
        bar.update(3)
    lines = out.getvalue().splitlines()
    assert lines == ["drawing: 1/3 strokes, 0 s", "drawing: 2/3 strokes, method ccd, 0 s", "drawing: 3/3 strokes, 0 s"]  # fmt: skip


@pytest.mark.usefixtures("eager")
def test_one_line_rewritten_on_a_terminal_and_ended_however_the_job_ends() -> None:
    out = Terminal()
    with pytest.raises(KeyboardInterrupt), Progress("compare-ik", 10, "calls", stream=out) as bar:
        bar.update(4)
        bar.update(5)
        raise KeyboardInterrupt
    text = out.getvalue()
    assert text == "\rcompare-ik: 4/10 calls, 0 s\x1b[K\rcompare-ik: 5/10 calls, 0 s\x1b[K\n"


def test_between_lines_it_waits(monkeypatch: pytest.MonkeyPatch) -> None:
    clock = iter(range(1000))
    monkeypatch.setattr(progress, "_now", lambda: float(next(clock)))  # a second a look
    monkeypatch.setattr(progress, "SHOW_AFTER", 1.0)
    monkeypatch.setattr(progress, "EVERY", 30.0)
    out = io.StringIO()
    with Progress("drawing", 100, "strokes", stream=out) as bar:
        for k in range(1, 101):
            bar.update(k)
    lines = out.getvalue().splitlines()
    assert lines[0].startswith("drawing: 1/100 strokes, ")
    assert lines[-1].startswith("drawing: 100/100 strokes, ")
    assert 3 <= len(lines) <= 5  # about 200 s of looks, a line at most every 30 s


def test_every_line_written_matches_line() -> None:
    for text in ("drawing two.svg: 0/2 strokes, 0 s", "compare-ik: 5/10 calls, method ccd, 3 s",
                 "screenshot: 4/4 steps, done, 12 s"):  # fmt: skip
        assert progress.LINE.match(text)
    for text in ("draw two.svg on A5 with pen: 2 strokes, pen down 1.0 mm", "armkit: error: x"):
        assert not progress.LINE.match(text)
