"""The 3D view's server under garbage (issue 33, item 5): on 127.0.0.1, malformed HTTP
(random bytes, broken request lines, huge headers, requests cut short) and malformed
websocket messages (text frames, random bytes, messages of no kind viser knows,
frames broken on the wire) leave it serving the page, accepting a new websocket
client that gets the scene, and updating; and no traceback reaches the terminal.
Seeded, the same on every run."""

from __future__ import annotations

import random
import socket
import urllib.request
from collections.abc import Iterator

import pytest

import armkit
from armkit.viz import ArmSource

websockets_sync = pytest.importorskip("websockets.sync.client")
viser = pytest.importorskip("viser")
from armkit.viz.web import View  # noqa: E402

HTTP = [
    b"GET / HTTP/1.1\r\nHost: x\r\n",  # never ends its headers
    b"GET /" + b"a" * 100_000 + b" HTTP/1.1\r\n\r\n",
    b"GET / HTTP/1.1\r\n" + b"X: " + b"y" * 200_000 + b"\r\n\r\n",
    b"POST / HTTP/1.1\r\nContent-Length: 99999999\r\n\r\nabc",
    b"GET /../../../../etc/passwd HTTP/1.1\r\nHost: x\r\n\r\n",
    b"GET /%2e%2e/%2e%2e/etc/passwd HTTP/1.1\r\n\r\n",
    b"BREW / HTCPCP/1.0\r\n\r\n",
    b"\x16\x03\x01\x02\x00\x01\x00\x01\xfc\x03\x03",  # a TLS hello
    b"GET / HTTP/1.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n\r\n",
    b"GET / HTTP/1.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Key: x\r\n"
    b"Sec-WebSocket-Version: 99\r\n\r\n",
    b"\r\n\r\n\r\n",
    b"",
]


@pytest.fixture
def view() -> Iterator[View]:
    with (
        armkit.Arm("openmanipulator_x") as arm,
        View(ArmSource(arm), port=0) as v,
    ):
        yield v


def _raw(view: View, data: bytes) -> None:
    """Send ``data`` on a new connection, read what comes back for a moment, close."""
    with socket.create_connection((view.host, view.server.get_port()), timeout=2.0) as sock:
        sock.settimeout(0.05)
        try:
            sock.sendall(data)
            sock.recv(65536)
        except OSError:
            pass  # the server may close or reset it: that is its right


def _client(view: View) -> websockets_sync.ClientConnection:
    url = view.url.replace("http://", "ws://")
    return websockets_sync.connect(
        url, subprotocols=[f"viser-v{viser.__version__}"], open_timeout=10
    )


def _page_served(view: View) -> bool:
    with urllib.request.urlopen(view.url, timeout=10) as reply:
        return reply.status == 200 and b"<html" in reply.read(4000).lower()


def test_malformed_http_leaves_the_page_served(
    view: View, capfd: pytest.CaptureFixture[str], caplog: pytest.LogCaptureFixture
) -> None:
    rng = random.Random("view http")
    for data in [
        *HTTP,
        *(bytes(rng.randrange(256) for _ in range(rng.randint(1, 300))) for _ in range(100)),
    ]:
        _raw(view, data)
    assert _page_served(view)
    _one_line_each(capfd, caplog)


def test_malformed_websocket_messages_leave_it_serving(
    view: View, capfd: pytest.CaptureFixture[str], caplog: pytest.LogCaptureFixture
) -> None:
    rng = random.Random("view websocket")
    messages: list[bytes | str] = [
        "a text frame", b"", b"\x00" * 8, b"\xff" * 64, b"\x81\xa4type\xa9NotAKind", b"\x90",
        b"\xc1", b"\xdd\xff\xff\xff\xff", b"x" * 2_000_000,
    ]  # fmt: skip
    messages += [bytes(rng.randrange(256) for _ in range(rng.randint(1, 200))) for _ in range(60)]
    for message in messages:
        try:
            with _client(view) as ws:
                ws.send(message)
                ws.recv(timeout=0.05)
        except Exception:
            pass
    with socket.create_connection((view.host, view.server.get_port()), timeout=2.0) as sock:
        key = "dGhlIHNhbXBsZSBub25jZQ=="
        sock.sendall(
            b"GET / HTTP/1.1\r\nHost: x\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
            + f"Sec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n".encode()
            + f"Sec-WebSocket-Protocol: viser-v{viser.__version__}\r\n\r\n".encode()
        )
        sock.settimeout(2.0)
        sock.recv(4096)  # the handshake's answer
        sock.sendall(bytes(rng.randrange(256) for _ in range(5000)))  # frames broken on the wire
    with _client(view) as ws:
        assert ws.recv(timeout=10)  # a new client gets the scene
    assert view.update() is not None and _page_served(view)
    _one_line_each(capfd, caplog)


def _one_line_each(capfd: pytest.CaptureFixture[str], caplog: pytest.LogCaptureFixture) -> None:
    """What the terminal of ``armkit view`` shows of the garbage: one line a connection
    (the server's log records, which pytest catches, turned so), never a traceback."""
    assert "Traceback" not in capfd.readouterr().err
    for record in caplog.records:
        assert record.exc_info is None and "\n" not in record.getMessage(), record.getMessage()
