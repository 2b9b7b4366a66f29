"""`armkit ... | head`: a reader that leaves early ends armkit quietly (exit 141, as a
shell reports SIGPIPE), with nothing on stderr and no motion left running."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest


@pytest.mark.parametrize("argv", [["arms"], ["--arm", "lynx6", "show"]])
def test_a_closed_pipe_ends_quietly(argv: list[str], tmp_path: object) -> None:
    env = {**os.environ, "ARMKIT_CONFIG_DIR": str(tmp_path)}
    proc = subprocess.Popen(
        [sys.executable, "-m", "armkit.cli", *argv],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        env=env,
    )
    assert proc.stdout is not None and proc.stderr is not None
    proc.stdout.close()
    err = proc.stderr.read().decode()
    assert proc.wait() == 141
    assert err == ""
