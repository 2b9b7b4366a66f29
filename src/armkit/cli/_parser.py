"""An ArgumentParser whose mistakes are one line on stderr, never a usage dump."""

from __future__ import annotations

import argparse
import sys
from typing import NoReturn


class Parser(argparse.ArgumentParser):
    """Prints ``armkit: error: ...`` on one line and exits with status 2; the hint
    names the help of the command that was being parsed (``armkit draw circle --help``)."""

    def error(self, message: str) -> NoReturn:
        program = self.prog.split()[0] if self.prog else "armkit"
        message = " ".join(message.split())
        print(f"{program}: error: {message} (see '{self.prog} --help')", file=sys.stderr)
        raise SystemExit(2)
