"""``armkit shell``: the session at a terminal, with readline history, Tab
completion of commands, pose names and joints, the arm's position in the prompt,
and jog mode reading one key at a time (000's basic mode; refused when the input is
not a terminal, so piped lines stay commands).

Exit status: at a terminal 0 (a mistake typed is answered and the shell reads on); with
lines piped or from a file, 1 if any line failed (its error printed; the lines after it
still ran), else 0. As for every command, 2 if the shell could not start (a bad option,
an arm that cannot be opened)."""

from __future__ import annotations

import io
import os
import sys
from collections.abc import Iterator
from contextlib import suppress
from pathlib import Path
from typing import Any, TextIO

from .._terminal import cbreak
from ._grammar import BLOCKS, COMMANDS, KEYWORDS
from ._jobs import JOBS
from ._session import SHELL_WORDS, Session
from ._teach import JOG_HELP

HISTORY_LENGTH = 1000


def completions(session: Session, before: str, text: str) -> list[str]:
    """Words that complete ``text``, given the line ``before`` it."""
    words = before.split()
    if not words:
        pool = [*COMMANDS, *JOBS, *BLOCKS, *SHELL_WORDS, *session.walker.procs]
    elif words[0] in ("turn", "run") and len(words) == 1:
        pool = list(session.arm.model.joint_names)
    else:
        pool = [*session.names, *sorted(KEYWORDS)]
    return sorted({w for w in pool if w.startswith(text)})


class Shell:
    """The interactive loop around a ``Session``."""

    def __init__(
        self, session: Session, *, stdin: TextIO | None = None, stdout: TextIO | None = None,
        history: Path | None = None,
    ) -> None:  # fmt: skip
        self.session, self.history = session, history
        self.stdin, self.stdout = stdin or sys.stdin, stdout or sys.stdout
        self._matches: list[str] = []
        self.failed = False  # a line failed (its error was printed)

    def prompt(self) -> str:
        """``armkit x 180 y 0 z 80 p -90> ``: where the gripper is [mm, deg] (``limp>``
        while the torque is off)."""
        x, y, z, pitch = self.session.arm.position()
        limp = " limp" if self.session.limp else ""
        return f"armkit x {round(x)} y {round(y)} z {round(z)} p {round(pitch)}{limp}> "

    def loop(self) -> int:
        """Read, check, run, until ``quit`` or end of input; the exit status (see the
        module doc: 1 if a line failed and the input is not a terminal, else 0)."""
        readline = self._readline()
        if isinstance(self.stdin, io.TextIOWrapper):  # bytes not UTF-8: refused line by line
            self.stdin.reconfigure(errors="surrogateescape")
        self._say(f"armkit shell on {self.session.arm.model.name}; help for the commands")
        more = False
        try:
            while True:
                try:
                    line = self._input("... " if more else self.prompt())
                except EOFError:
                    end = self.session.end_of_input()
                    if end.text:  # a block with no 'end'
                        self._say(("\n" if self.stdin.isatty() else "") + end.text)
                    self.failed |= end.failed
                    break
                except KeyboardInterrupt:
                    self.session.cancel()
                    self._say("^C")
                    more = False
                    continue
                reply = self.session.handle(line)
                self.failed |= reply.failed
                if reply.text:
                    self._say(reply.text)
                if reply.quit:
                    break
                if reply.jog is not None:
                    self._jog(reply.jog)
                more = reply.more
        finally:
            if readline is not None and self.history is not None:
                _save_history(readline, self.history)
        return 1 if self.failed and not self.stdin.isatty() else 0

    def _input(self, prompt: str) -> str:
        if self.stdin is sys.stdin and self.stdout is sys.stdout:
            return input(prompt)
        self.stdout.write(prompt)
        self.stdout.flush()
        line = self.stdin.readline()
        if not line:
            raise EOFError
        return line.rstrip("\n")

    def _say(self, text: str) -> None:
        self.stdout.write(text + "\n")
        self.stdout.flush()

    def _jog(self, step: float) -> None:
        if not self.stdin.isatty():  # piped lines would be eaten as keys: refuse, move nothing
            self._say(self._no_jog())
            self.failed = True
            return
        self._say(JOG_HELP)

        def show(text: str) -> None:
            self.stdout.write("\r\x1b[K" + text)
            self.stdout.flush()

        try:
            with cbreak(self.stdin):
                self.session.jog(self._keys(), step, show)
        except KeyboardInterrupt:
            self.session.arm.stop()
            self._say("\nstopped")
        self._say("")

    def _no_jog(self) -> str:
        """Why ``jog`` is refused on input that is not a terminal, and what to write."""
        joint = self.session.arm.model.joint_names[0]
        return (
            "error: jog reads single keys from a terminal and this input is not one (lines "
            "piped or from a file), so nothing moved; write the moves as lines instead: "
            f"turn {joint} by 5, joints A1 ... An, move xyz X Y Z [pitch P], grip open|close"
        )

    def _keys(self) -> Iterator[str]:
        fd = self.stdin.fileno()
        while data := os.read(fd, 1):
            yield data.decode("latin-1")

    def _readline(self) -> Any:
        if not (self.stdin is sys.stdin and self.stdin.isatty()):
            return None
        try:
            import readline
        except ImportError:  # not on every platform
            return None
        readline.set_completer_delims(" \t\n=(),")
        readline.set_completer(self._complete)
        readline.parse_and_bind("tab: complete")
        readline.set_history_length(HISTORY_LENGTH)
        if self.history is not None and self.history.is_file():
            with suppress(OSError):
                readline.read_history_file(str(self.history))
        return readline

    def _complete(self, text: str, state: int) -> str | None:
        if state == 0:
            import readline

            before = readline.get_line_buffer()[: readline.get_begidx()]
            self._matches = completions(self.session, before, text)
        return self._matches[state] if state < len(self._matches) else None


def _save_history(readline: Any, path: Path) -> None:
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        readline.write_history_file(str(path))
    except OSError:
        pass  # history is a convenience; never fail the shell over it
