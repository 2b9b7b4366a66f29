"""Every console command and Python snippet of every page runs as written: README.md
and each page of the documentation site (docs/**/*.md), one test per page.

A page's console blocks run in order in a scratch directory of its own that holds the repository's
files (``src``, ``benchmarks``, ``examples``, the Makefile, the virtual
environment) through symlinks, with a fresh ``ARMKIT_CONFIG_DIR``. ``armkit``
lines run in-process through ``armkit.cli.main``; a ``$`` line's output shown
below it must be what the command prints (stdout and stderr; the progress lines
of a long job, ``armkit._progress.LINE``, left out: how many there are depends on
the machine's speed). Other lines run
in a shell. ``make`` targets are checked with ``make --dry-run`` (running them
would rebuild this environment), and what they run is run directly.

Nothing is skipped silently: the commands that are not run are listed in
NOT_RUN with the reason, and each must still be on some page; benchmark runs
(``.venv/bin/python benchmarks/NAME.py``: timing runs of make bench, some
installing peers from the network) are compiled, not run. Commands that serve
until Ctrl-C (``armkit view``) are started, awaited and interrupted.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import shlex
import signal
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path

import pytest

from armkit._progress import LINE
from armkit.cli import main
from armkit.viz.web import find_chromium

ROOT = Path(__file__).resolve().parents[1]
PAGES = sorted(
    [ROOT / "README.md", *(ROOT / "docs").rglob("*.md")], key=lambda p: str(p.relative_to(ROOT))
)
PAGE_IDS = [str(p.relative_to(ROOT)) for p in PAGES]
LINKED = (
    "src",
    "benchmarks",
    "examples",
    "docs",
    "Makefile",
    "pyproject.toml",
    "setup.py",
    "mkdocs.yml",
    ".venv",
)

NOT_RUN = {  # command (as on its page) -> why this test does not run it
    "make test": "it is this test suite: `make --dry-run test` is checked instead",
    "make demo": "it installs into .venv: `make --dry-run demo` is checked (`armkit demo` itself runs in tests/viz/test_demo.py)",
    "make docs": "it installs the docs extra and builds the site: `make --dry-run docs` is checked (CI builds it)",
    "armkit --arm openmanipulator_x compare-ik --n 1000 --seed 0 --repeats 3":
        "a timing run of about a minute; compare-ik itself is run with --n 20 below",
}  # fmt: skip
INSTEAD = {
    "make test": ["make --dry-run test"],
    "make demo": ["make --dry-run demo"],
    "make docs": ["make --dry-run docs"],
    "armkit --arm openmanipulator_x compare-ik --n 1000 --seed 0 --repeats 3": [
        "armkit --arm openmanipulator_x compare-ik --n 20 --seed 0"
    ],
}


@dataclass
class Command:
    line: str
    expected: list[str] | None = None  # the output shown under a '$' line


@dataclass
class Block:
    kind: str
    start: int
    commands: list[Command] = field(default_factory=list)
    code: str = ""


def blocks(page: Path) -> list[Block]:
    """The page's console and python blocks, in order."""
    found, current, lines = [], None, page.read_text(encoding="utf-8").splitlines()
    for n, text in enumerate(lines, 1):
        fence = re.match(r"^```(\w*)\s*$", text)
        if fence and current is None:
            current = Block(fence.group(1), n)
        elif fence and current is not None:
            if current.kind in ("console", "python"):
                found.append(current)
            current = None
        elif current is not None and current.kind == "python":
            current.code += text + "\n"
        elif current is not None and current.kind == "console":
            _add_console_line(current, text)
    return found


def _add_console_line(block: Block, text: str) -> None:
    prompt = any(c.expected is not None for c in block.commands) or text.startswith("$ ")
    if text.startswith("$ "):  # a comment after the command is set off by 2+ spaces
        block.commands.append(Command(re.split(r"\s{2,}#", text[2:])[0].strip(), []))
    elif prompt and block.commands:
        expected = block.commands[-1].expected
        assert expected is not None
        expected.append(text)
    elif text.strip():
        block.commands.append(Command(" ".join(shlex.split(text, comments=True))))


@pytest.fixture
def scratch(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    for name in LINKED:
        (tmp_path / name).symlink_to(ROOT / name)
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path / "config"))
    return tmp_path


# Commands that serve until Ctrl-C: run as a process, wait until it says it is
# ready (the text), then press Ctrl-C; it must stop cleanly.
SERVES = {"view": "http://127.0.0.1:"}
ONE_SHOT = ("--screenshot", "--gif")


def serves(words: list[str]) -> str | None:
    """The readiness text of a serving command, None for a command that ends by itself."""
    command = next((w for w in words[1:] if w in SERVES), None)
    if words[0] != "armkit" or command is None or any(w in words for w in ONE_SHOT):
        return None
    return SERVES[command]


def serve_then_interrupt(words: list[str], ready: str, scratch: Path) -> tuple[int, str]:
    """Start the server with a free port, wait for ``ready``, Ctrl-C it; (status, output)."""
    argv = [sys.executable, "-m", "armkit.cli", *words[1:], "--port", "0"]
    proc = subprocess.Popen(
        argv, cwd=scratch, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True
    )
    assert proc.stdout is not None
    seen = []
    for text in proc.stdout:
        seen.append(text)
        if ready in text:
            break
    proc.send_signal(signal.SIGINT)
    rest, _ = proc.communicate(timeout=60)
    code = 0 if proc.returncode in (0, 130) and any(ready in t for t in seen) else 1
    return code, "".join(seen) + rest


@contextlib.contextmanager
def _stdin(replacement: io.StringIO):  # type: ignore[no-untyped-def]
    saved, sys.stdin = sys.stdin, replacement
    try:
        yield
    finally:
        sys.stdin = saved


def run(line: str, scratch: Path) -> tuple[int, str]:
    """Run one line of a page; (exit status, what it printed)."""
    words = shlex.split(line)
    ready = serves(words)
    if ready is not None:
        return serve_then_interrupt(words, ready, scratch)
    if words[0] == "armkit":
        out = io.StringIO()
        typed = io.StringIO("where\nquit\n")  # what a person types into `armkit shell`
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(out), _stdin(typed):
            code = main(words[1:])
        return code, out.getvalue()
    env = dict(os.environ, PATH=f"{ROOT / '.venv' / 'bin'}{os.pathsep}{os.environ['PATH']}")
    done = subprocess.run(
        line, shell=True, cwd=scratch, env=env, capture_output=True, text=True, timeout=600
    )
    return done.returncode, done.stdout + done.stderr


BENCHMARK = re.compile(r"^(?:\w+=\S+\s+)*\.venv/bin/python (benchmarks/\w+\.py)\b")


def needs_missing_browser(line: str) -> bool:
    """A command that needs Chromium (``view --screenshot``) on a machine without it: not run
    there (the page's test is then skipped, naming it); under CI=true a failure (.ci/run
    installs Chromium first)."""
    if "--screenshot" not in shlex.split(line) or find_chromium() is not None:
        return False
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail(f"Chromium is missing in CI for {line!r}: .ci/run installs it first")
    return True


def run_page(page: Path, scratch: Path, without: list[str] | None = None) -> tuple[int, set[str]]:
    """Run every console command of ``page`` in order; (commands run, NOT_RUN lines met).
    Commands that need a browser this machine lacks are not run but added to ``without``."""
    ran, skipped, name = 0, set(), page.relative_to(ROOT)
    for block in [b for b in blocks(page) if b.kind == "console"]:
        for command in block.commands:
            if needs_missing_browser(command.line):
                (without if without is not None else []).append(command.line)
                continue
            bench = BENCHMARK.match(command.line)
            if bench:  # timing runs (make bench; some install peers): compiled, not run
                source = (ROOT / bench.group(1)).read_text()
                compile(source, bench.group(1), "exec")
                continue
            if command.line in NOT_RUN:
                skipped.add(command.line)
                lines = INSTEAD.get(command.line, [])
            else:
                lines = [command.line]
            for line in lines:
                code, printed = run(line, scratch)
                where = f"{name} line {block.start}: {line}\n{printed}"
                expected = command.expected if line == command.line else None
                if expected and any(t.startswith("armkit: error:") for t in expected):
                    assert code == 2, where
                else:
                    assert code == 0, where
                if expected:
                    shown = [t for t in printed.rstrip("\n").splitlines() if not LINE.match(t)]
                    assert shown == expected, where
                ran += 1
    return ran, skipped


@pytest.mark.parametrize("page", PAGES, ids=PAGE_IDS)
def test_every_console_command_runs_as_written(page: Path, scratch: Path) -> None:
    without: list[str] = []
    ran, _ = run_page(page, scratch, without)
    commands = [c for b in blocks(page) if b.kind == "console" for c in b.commands]
    if without:  # every other command of the page ran and passed
        pytest.skip(
            f"{ran} commands ran; not run, no Chromium here (apt-get install chromium; CI runs "
            f"them): {'; '.join(without)}"
        )
    assert ran or all(BENCHMARK.match(c.line) for c in commands)


def test_the_pages_hold_what_is_not_run_and_enough_is_run() -> None:
    lines = {c.line for p in PAGES for b in blocks(p) if b.kind == "console" for c in b.commands}
    assert set(NOT_RUN) <= lines, f"NOT_RUN lists commands no page has: {set(NOT_RUN) - lines}"
    assert len(lines - set(NOT_RUN)) >= 100


@pytest.mark.parametrize("page", PAGES, ids=PAGE_IDS)
def test_every_python_snippet_runs_as_written(page: Path, scratch: Path) -> None:
    for block in [b for b in blocks(page) if b.kind == "python"]:
        namespace: dict[str, object] = {"__name__": "__docs__"}
        name = page.relative_to(ROOT)
        try:
            exec(compile(block.code, f"{name}:{block.start}", "exec"), namespace)
        except Exception as exc:
            pytest.fail(f"{name} line {block.start}: {type(exc).__name__}: {exc}")


def test_the_pages_have_python_snippets() -> None:
    assert sum(b.kind == "python" for p in PAGES for b in blocks(p)) >= 8
