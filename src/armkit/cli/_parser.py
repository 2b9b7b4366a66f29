"""An ArgumentParser whose mistakes are one line on stderr, never a usage dump."""

from __future__ import annotations

import argparse
import re
import sys
from typing import NoReturn


class Parser(argparse.ArgumentParser):
    """Prints ``armkit: error: ...`` on one line and exits with status 2; the hint
    names the help of the command that was being parsed (``armkit draw circle --help``)."""

    def error(self, message: str) -> NoReturn:
        program = self.prog.split()[0] if self.prog else "armkit"
        message = _did_you_mean(" ".join(message.split()))
        print(f"{program}: error: {message} (see '{self.prog} --help')", file=sys.stderr)
        raise SystemExit(2)


def _did_you_mean(message: str) -> str:
    """argparse's "invalid choice: 'mvoe' (choose from 'a', 'b', ...)" as "invalid choice:
    'mvoe'; did you mean 'move'?" where a choice is close, else as it was."""
    import difflib

    found = re.match(r"(.*invalid choice: '([^']*)') \(choose from (.*)\)$", message)
    if found is None:
        return message
    head, word, listed = found.groups()
    close = difflib.get_close_matches(word, re.findall(r"'([^']*)'", listed), n=1, cutoff=0.6)
    return f"{head}; did you mean '{close[0]}'?" if close else message
