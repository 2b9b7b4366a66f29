"""The one pseudo-terminal server: any simulated byte device, served where any program can open it.

``PtyServer(device, world)`` opens a pseudo-terminal and serves its master side
from a background thread; ``.port`` is the slave side's path. Any client that
opens a serial port by path (pyserial, the official dynamixel-sdk, a terminal
program) talks to the device as to real hardware on a USB-serial adapter.
Bytes reach the device at the world's device time and replies are written when due.
The client lives in real time, so the world should too (``World(realtime=True)``).
Like the hardware, the device ignores a client set to another baud rate.

The server thread takes only the device's own lock and reads the world's device time
(``World.device_time``), which never steps the arms: a device answers within
microseconds of reading a request, whatever the world's own thread is doing.
"""

from __future__ import annotations

import contextlib
import os
import select
import termios
import threading
import time
import tty
from collections import deque
from typing import Self

from ._outbox import ByteDevice, deliver, log
from ._world import World

# termios speed constant -> bit/s, for the standard rates this platform names
_RATES = {
    getattr(termios, f"B{rate}"): rate
    for rate in (
        9600,
        19200,
        38400,
        57600,
        115200,
        230400,
        460800,
        500000,
        576000,
        921600,
        1000000,
        1152000,
        1500000,
        2000000,
        2500000,
        3000000,
        3500000,
        4000000,
    )
    if hasattr(termios, f"B{rate}")
}


class PtyServer:
    """``device`` on a pseudo-terminal (see module doc). Attributes: ``port`` (the path to
    open), ``misheard`` (bytes sent at the wrong baud rate), ``reply_s`` (for each reply
    written at once, the wall time from reading the request to writing the reply [s];
    the last ``LOG_ROWS``)."""

    def __init__(self, device: ByteDevice, world: World) -> None:
        self.device, self.world = device, world
        self.misheard = 0
        self.reply_s: deque[float] = log()
        self._master, self._slave = os.openpty()
        tty.setraw(self._slave)
        os.set_blocking(self._master, False)
        self.port = os.ttyname(self._slave)
        self._wake_r, self._wake_w = os.pipe()
        self._running = True
        self._thread = threading.Thread(target=self._serve, name=f"{device.name}-pty", daemon=True)
        self._thread.start()

    def _serve(self) -> None:
        read_at: float | None = None  # when the request being answered was read
        while self._running:
            ready, _, _ = select.select([self._master, self._wake_r], [], [], self._wait_s())
            if self._master in ready:
                self._receive()
                read_at = time.monotonic() if read_at is None else read_at
                if select.select([self._master], [], [], 0.0)[0]:
                    continue  # the host sent more already: read it before answering
            if self._send_due() and read_at is not None:
                self.reply_s.append(time.monotonic() - read_at)
            read_at = None

    def _wait_s(self) -> float:
        with self.device.lock:
            due = self.device.outbox.next_due()
        now = self.world.device_time()
        return 0.5 if due is None else max(0.0, (due - now) / self.world.pace)

    def _receive(self) -> None:
        try:
            data = os.read(self._master, 4096)
        except OSError:
            return
        rate = self._host_rate()
        with self.device.lock:
            heard = deliver(self.device, data, self.world.device_time(), rate)
        if not heard:
            self.misheard += len(data)

    def _host_rate(self) -> int | None:
        """The rate the client set on the terminal [bit/s] (None: not a standard one)."""
        speed = termios.tcgetattr(self._slave)[5]
        return _RATES.get(speed)

    def _send_due(self) -> bool:
        """Write the replies that are due; True if there were any."""
        with self.device.lock:
            data = self.device.outbox.take(self.world.device_time())
        if data:
            with contextlib.suppress(OSError):  # nobody reading: lost, as on a real line
                os.write(self._master, data)
        return bool(data)

    def close(self) -> None:
        """Stop serving and close the pseudo-terminal. Safe to call twice."""
        if not self._running:
            return
        self._running = False
        os.write(self._wake_w, b"x")
        self._thread.join(timeout=2.0)
        for fd in (self._master, self._slave, self._wake_r, self._wake_w):
            os.close(fd)

    def __enter__(self) -> Self:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
