"""Headless Chromium driven over the DevTools protocol: pictures of the page, and tests.

Chromium (Debian's ``chromium`` package) is started with its own empty
profile and no background networking, with software WebGL (SwiftShader) so
it renders with no GPU and no screen. The DevTools protocol (JSON over a
websocket, the ``websockets`` package viser already needs) loads the page,
evaluates JavaScript, records network requests and websocket frames, and
captures screenshots.
"""

from __future__ import annotations

import base64
import json
import os
import shutil
import subprocess
import tempfile
import threading
import time
import urllib.request
from collections.abc import Callable
from concurrent.futures import Future
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from websockets.sync.client import ClientConnection, connect

from ..._errors import ArmkitError

NAMES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
FLAGS = (
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--enable-unsafe-swiftshader",
    "--use-angle=swiftshader",
    "--disable-quic",
    "--no-first-run",
    "--no-default-browser-check",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-extensions",
    "--hide-scrollbars",
    "--mute-audio",
    "--remote-debugging-address=127.0.0.1",
    "--remote-debugging-port=0",
)
START_TIMEOUT = 20.0  # [s]


def find_chromium() -> str | None:
    """Path of a Chromium executable ($ARMKIT_CHROMIUM, else on PATH), or None."""
    given = os.environ.get("ARMKIT_CHROMIUM")
    if given:
        return given if Path(given).exists() else None
    for name in NAMES:
        path = shutil.which(name)
        if path:
            return path
    return None


@dataclass(frozen=True)
class Frame:
    """A websocket frame the page received: ``time`` [s] on Chromium's monotonic
    clock (CLOCK_MONOTONIC, as ``time.monotonic``), ``size`` of its payload
    (base64 characters for binary frames) and the ``payload`` as CDP gives it."""

    time: float
    size: int
    payload: str


class Chromium:
    """One headless Chromium with one page (see the module doc).

    Args:
        width, height: the page's size [px].
        executable: the browser (default ``find_chromium()``).
        record_frames: keep every websocket frame the page receives (``frames``).
    """

    def __init__(
        self,
        width: int = 1280,
        height: int = 800,
        executable: str | None = None,
        record_frames: bool = False,
    ) -> None:
        exe = executable or find_chromium()
        if exe is None:
            raise ArmkitError(
                "a picture of the page needs Chromium; install it "
                "(Debian: apt-get install chromium) or set ARMKIT_CHROMIUM to its path"
            )
        self._profile = tempfile.TemporaryDirectory(
            prefix="armkit-chromium-", ignore_cleanup_errors=True
        )
        args = [exe, *FLAGS, f"--user-data-dir={self._profile.name}", "about:blank"]
        self._proc = subprocess.Popen(
            args, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
        )
        self.requests: list[str] = []
        self.console: list[str] = []
        self.frames: list[Frame] = []
        self._record_frames = record_frames
        self._next = 0
        self._pending: dict[int, Future[dict[str, Any]]] = {}
        self._send_lock = threading.Lock()
        try:
            self._ws = self._attach(width, height)
        except BaseException:
            self.close()
            raise

    def open(self, url: str, ready: str = "true", timeout: float = 20.0) -> None:
        """Load ``url`` and wait until the JavaScript expression ``ready`` is true."""
        self.call("Page.navigate", url=url)
        self.wait_for(ready, timeout)

    def evaluate(self, expression: str) -> Any:
        """The value of a JavaScript expression in the page (JSON-able values)."""
        reply = self.call("Runtime.evaluate", expression=expression, returnByValue=True)
        result = reply.get("result", {})
        if "exceptionDetails" in reply:
            raise ArmkitError(
                f"the page failed to evaluate {expression!r}: {reply['exceptionDetails']}"
            )
        return result.get("value")

    def wait_for(self, expression: str, timeout: float = 20.0) -> None:
        """Poll the JavaScript ``expression`` until it is true (ArmkitError after ``timeout`` [s])."""
        wait_until(
            lambda: bool(self.evaluate(expression)), timeout, f"the page to show {expression}"
        )

    def screenshot(self) -> bytes:
        """The page as it looks now, PNG bytes."""
        data = self.call("Page.captureScreenshot", format="png")["data"]
        return base64.b64decode(data)

    def call(self, method: str, timeout: float = 30.0, **params: Any) -> dict[str, Any]:
        """Send one DevTools command and wait for its result."""
        return self._send(method, params).result(timeout=timeout)

    def _send(
        self, method: str, params: dict[str, Any], session: str | None = None
    ) -> Future[dict[str, Any]]:
        with self._send_lock:
            self._next += 1
            future: Future[dict[str, Any]] = Future()
            self._pending[self._next] = future
            msg: dict[str, Any] = {"id": self._next, "method": method, "params": params}
            if session is not None:
                msg["sessionId"] = session
            self._ws.send(json.dumps(msg))
        return future

    def close(self) -> None:
        """Close the page and stop the browser (waits for it to exit)."""
        ws = getattr(self, "_ws", None)
        if ws is not None:
            ws.close()
        if self._proc.poll() is None:
            self._proc.terminate()
            try:
                self._proc.wait(timeout=5.0)
            except subprocess.TimeoutExpired:
                self._proc.kill()
                self._proc.wait()
        self._profile.cleanup()

    def __enter__(self) -> Chromium:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _attach(self, width: int, height: int) -> ClientConnection:
        port_file = Path(self._profile.name) / "DevToolsActivePort"
        wait_until(
            lambda: port_file.exists() and len(port_file.read_text().split()) >= 2,
            START_TIMEOUT,
            "Chromium to start",
            alive=lambda: self._proc.poll() is None,
        )
        port = port_file.read_text().split()[0]
        with urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list", timeout=5) as reply:
            pages = [t for t in json.load(reply) if t.get("type") == "page"]
        ws = connect(pages[0]["webSocketDebuggerUrl"], max_size=None, open_timeout=10)
        self._ws = ws
        threading.Thread(target=self._read, name="armkit-cdp", daemon=True).start()
        self.call("Network.enable")
        self.call("Runtime.enable")
        self.call("Page.enable")
        # the page's websocket lives in a Web Worker: attach to workers to see its frames
        self.call(
            "Target.setAutoAttach", autoAttach=True, waitForDebuggerOnStart=False, flatten=True
        )
        self.call(
            "Emulation.setDeviceMetricsOverride",
            width=width,
            height=height,
            deviceScaleFactor=1,
            mobile=False,
        )
        return ws

    def _read(self) -> None:
        try:
            for raw in self._ws:
                self._dispatch(json.loads(raw))
        except Exception:  # the browser went away: fail whoever waits
            pass
        for future in self._pending.values():
            if not future.done():
                future.set_exception(ArmkitError("Chromium closed the connection"))

    def _dispatch(self, msg: dict[str, Any]) -> None:
        if "id" in msg:
            future = self._pending.pop(msg["id"], None)
            if future is not None:
                if "error" in msg:
                    future.set_exception(ArmkitError(f"Chromium refused: {msg['error']}"))
                else:
                    future.set_result(msg.get("result", {}))
            return
        method, params = msg.get("method"), msg.get("params", {})
        if method == "Target.attachedToTarget":
            self._send("Network.enable", {}, params["sessionId"])
        elif method == "Network.requestWillBeSent":
            self.requests.append(params["request"]["url"])
        elif method == "Network.webSocketCreated":
            self.requests.append(params["url"])
        elif method == "Runtime.consoleAPICalled":
            self.console.append(" ".join(str(a.get("value", "")) for a in params["args"]))
        elif method == "Network.webSocketFrameReceived" and self._record_frames:
            data = params["response"]["payloadData"]
            self.frames.append(Frame(float(params["timestamp"]), len(data), data))


def wait_until(
    done: Callable[[], bool],
    timeout: float,
    what: str,
    alive: Callable[[], bool] = lambda: True,
) -> None:
    """Poll ``done`` every 50 ms; ArmkitError naming ``what`` after ``timeout`` [s]."""
    deadline = time.monotonic() + timeout
    while not done():
        if not alive() or time.monotonic() > deadline:
            raise ArmkitError(f"gave up waiting {timeout:.0f} s for {what}")
        time.sleep(0.05)
