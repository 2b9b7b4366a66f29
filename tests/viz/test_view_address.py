"""``armkit view``'s --host and --port are checked before anything opens: a host that is no
address of this computer and a busy port the user chose are refused in one line (the
server would otherwise try port after port and never be ready); a busy default port is
swapped for the next free one, said in a line; Ctrl-C stops the page without a traceback."""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from armkit import InputError
from armkit.cli import main
from armkit.viz import serve_address


@pytest.fixture
def busy() -> Iterator[int]:
    """A port on 127.0.0.1 that another program listens on."""
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        sock.listen(1)
        yield int(sock.getsockname()[1])


@pytest.mark.parametrize(
    ("host", "words"),
    [
        ("999.1.1.1", "--host 999.1.1.1 is no address of this computer"),
        ("no-such-host.invalid", "is no address of this computer"),
        ("192.0.2.1", "--host 192.0.2.1 is no address of this computer; use 127.0.0.1"),
        ("127.0.0.1 ", "is no address of this computer"),
    ],
)
def test_a_host_that_is_no_address_here_is_refused_in_one_line(
    host: str, words: str, config_dir: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["view", "--host", host, "--port", "0"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("armkit: error: ") and words in err and err.count("\n") == 1
    assert not config_dir.exists()  # no simulated arm was opened


def test_a_busy_port_the_user_chose_is_refused(
    busy: int, config_dir: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["view", "--port", str(busy)]) == 2
    err = capsys.readouterr().err
    assert err == (
        f"armkit: error: --port {busy} is busy on 127.0.0.1 (another program serves there); "
        "choose another port, or 0 for any free one\n"
    )
    assert not config_dir.exists()


def test_a_busy_default_port_gives_way_to_the_next_free_one_and_says_so(busy: int) -> None:
    address = serve_address("127.0.0.1", busy, exact=False)
    assert address.port > busy and address.note == f"port {busy} is busy; serving on {address.port}"
    assert serve_address("127.0.0.1", 0) == serve_address("127.0.0.1", 0, exact=False)
    with pytest.raises(InputError, match=r"--view-port must be 0\.\.65535"):
        serve_address("127.0.0.1", 70000, flag="--view-port")


def test_ctrl_c_stops_the_page_without_a_traceback(config_dir: Path) -> None:
    code = "from armkit.cli import main; raise SystemExit(main())"
    env = dict(os.environ, ARMKIT_CONFIG_DIR=str(config_dir))
    proc = subprocess.Popen(
        [sys.executable, "-c", code, "view", "--port", "0"],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        env=env,
    )
    try:
        assert proc.stdout is not None
        assert proc.stdout.readline().startswith("armkit view: http://127.0.0.1:")
        proc.send_signal(signal.SIGINT)
        out, _ = proc.communicate(timeout=20)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == 0
    assert out.strip() == "armkit view: stopped", out
