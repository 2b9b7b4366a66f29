"""``armkit emulate dynamixel|ssc32|maestro`` under garbage (issue 33, item 5): 10,000
random byte strings written to its pseudo-terminal (random bytes, requests with a
byte flipped or cut short, well-framed requests of unknown instructions and lengths),
and afterwards the emulator is still running and answers a valid request, as a
client that retries finds the real controller again.

The strings are seeded (the same on every run). The emulator's replies are read
while the garbage goes in, as a program on a serial port would, so that no reply is
left blocking the pseudo-terminal."""

from __future__ import annotations

import os
import random
import select
import signal
import subprocess
import sys
import termios
import time
import tty
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest

STRINGS = 10_000
ARMKIT = [sys.executable, "-c", "import sys; from armkit.cli import main; sys.exit(main())"]


def _crc16(data: bytes) -> int:
    """The Dynamixel Protocol 2.0 CRC (e-Manual, 'CRC calculation': polynomial 0x8005)."""
    crc = 0
    for byte in data:
        crc ^= byte << 8
        for _ in range(8):
            crc = ((crc << 1) ^ 0x8005) if crc & 0x8000 else crc << 1
            crc &= 0xFFFF
    return crc


def dxl_packet(ident: int, instruction: int, params: bytes = b"") -> bytes:
    """A Protocol 2.0 instruction packet: header, ID, length, instruction, params, CRC."""
    body = b"\xff\xff\xfd\x00" + bytes([ident]) + (len(params) + 3).to_bytes(2, "little")
    body += bytes([instruction]) + params
    return body + _crc16(body).to_bytes(2, "little")


PING = dxl_packet(0xFE, 0x01)  # broadcast ping: every servo answers, whatever its ID


def _dynamixel(rng: random.Random) -> bytes:
    kind = rng.random()
    if kind < 0.4:  # framed, of a harmless instruction (ping, read) or none the servo knows
        instruction = rng.choice((0x01, 0x02, 0x00, 0x09, 0x7F, 0x55, 0x92, 0x8A, 0xFF))
        params = bytes(rng.randrange(256) for _ in range(rng.choice((0, 1, 4, 9, 40))))
        return dxl_packet(rng.choice((11, 12, 0xFE, 0, 200, 253)), instruction, params)
    if kind < 0.7:  # a valid request, a byte flipped or cut short
        packet = bytearray(dxl_packet(11, 0x02, (132).to_bytes(2, "little") + b"\x04\x00"))
        packet[rng.randrange(len(packet))] ^= 1 << rng.randrange(8)
        return bytes(packet[: rng.randint(1, len(packet))])
    return bytes(rng.randrange(256) for _ in range(rng.randint(1, 40)))


def _ssc32(rng: random.Random) -> bytes:
    if rng.random() < 0.5:
        words = ("#", "P", "S", "T", "Q", "QP", "VA", "VE", "VER", "STOP", "GOBOARD", "0", "31",
                 "1500", "-5", "99999999", "\r", " ", ",", "+", "?")  # fmt: skip
        return "".join(rng.choice(words) for _ in range(rng.randint(1, 12))).encode()
    return bytes(rng.randrange(256) for _ in range(rng.randint(1, 40)))


def _maestro(rng: random.Random) -> bytes:
    if rng.random() < 0.5:  # a command byte (the high bit set) and data bytes
        command = rng.choice((0x84, 0x87, 0x89, 0x90, 0x93, 0xA1, 0xA2, 0xA4, 0xA7, 0xAA, 0x9F))
        return bytes([command, *(rng.randrange(256) for _ in range(rng.randint(0, 6)))])
    return bytes(rng.randrange(256) for _ in range(rng.randint(1, 40)))


def _answers_ssc32(send: Callable[[bytes], bytes]) -> bool:
    return b"SSC32" in send(b"\r\rVER\r")


def _answers_maestro(send: Callable[[bytes], bytes]) -> bool:
    return len(send(bytes([0xA1]))) >= 2  # Get Errors: two bytes, whatever the errors are


def _answers_dynamixel(send: Callable[[bytes], bytes]) -> bool:
    """A status packet's header comes back. Pings go a hundred at a time: a frame the
    garbage left open (its length field read as up to 65,535 bytes; Protocol 2.0 sets
    no timeout) is completed by the next bytes sent, so a retrying client gets through."""
    return b"\xff\xff\xfd\x00" in send(PING * 100)


KINDS = {  # the garbage, the valid request, the baud rate a client sets (the device's own)
    "ssc32": (_ssc32, _answers_ssc32, termios.B9600),
    "maestro": (_maestro, _answers_maestro, termios.B9600),
    "dynamixel": (_dynamixel, _answers_dynamixel, termios.B1000000),
}


@contextmanager
def emulator(tmp_path: Path, kind: str) -> Iterator[tuple[int, subprocess.Popen[str]]]:
    """``armkit emulate KIND`` in a child process; yields (its pty opened raw at the
    device's baud rate, as a serial port is, and the process)."""
    env = {**os.environ, "ARMKIT_CONFIG_DIR": str(tmp_path / "config")}
    proc = subprocess.Popen(
        [*ARMKIT, "emulate", kind], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        env=env,
    )  # fmt: skip
    fd = -1
    try:
        assert proc.stdout is not None
        port = proc.stdout.readline().strip()
        assert port.startswith("/dev/"), proc.stderr.read() if proc.stderr else ""
        fd = os.open(port, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
        tty.setraw(fd, termios.TCSANOW)
        attributes = termios.tcgetattr(fd)
        attributes[4] = attributes[5] = KINDS[kind][2]
        termios.tcsetattr(fd, termios.TCSANOW, attributes)
        yield fd, proc
    finally:
        if fd >= 0:
            os.close(fd)
        if proc.poll() is None:
            proc.send_signal(signal.SIGINT)
            proc.wait(timeout=20)
        for stream in (proc.stdout, proc.stderr):
            if stream is not None:
                stream.close()


def _drain(fd: int, wait: float) -> bytes:
    """What the emulator wrote until it was quiet for ``wait`` seconds."""
    out = b""
    while select.select([fd], [], [], wait)[0]:
        try:
            chunk = os.read(fd, 65536)
        except BlockingIOError:
            continue
        if not chunk:
            break
        out += chunk
    return out


def _write(fd: int, data: bytes) -> None:
    while data:
        select.select([], [fd], [], 5.0)
        try:
            data = data[os.write(fd, data) :]
        except BlockingIOError:
            _drain(fd, 0.0)


@pytest.mark.parametrize("kind", list(KINDS))
def test_the_emulator_survives_garbage_and_answers_afterwards(tmp_path: Path, kind: str) -> None:
    garbage, answers, _ = KINDS[kind]
    rng = random.Random(f"emulate {kind}")
    with emulator(tmp_path, kind) as (fd, proc):

        def send(request: bytes) -> bytes:
            _write(fd, request)
            return _drain(fd, 0.3)

        assert answers(send), "the emulator does not answer before the garbage"
        for k in range(STRINGS):
            _write(fd, garbage(rng))
            if k % 50 == 0:
                _drain(fd, 0.0)
        _drain(fd, 0.5)
        assert proc.poll() is None, proc.stderr.read() if proc.stderr else ""
        deadline = time.monotonic() + 60.0  # a client retries; a Dynamixel may be mid-packet
        while not answers(send):
            assert time.monotonic() < deadline, f"the {kind} emulator answers no valid request"
        assert proc.poll() is None


@pytest.mark.parametrize(
    "line",
    [
        b"STOP-5", b"QP-599", b"QP\xb2", b"R-", b"R-5=3", b"R5=99999999999999",
        b"#" + b"9" * 5000 + b"P1500", b"#1P" + b"9" * 5000, b"#1P1500S" + b"9" * 5000,
        b"#0:" + b"9" * 5000, b"#1\xb2P1500",
    ],
)  # fmt: skip
def test_the_ssc32_ignores_a_command_with_a_channel_or_register_it_has_not(line: bytes) -> None:
    """Found by the garbage above: each of these stopped the emulator's thread (an
    IndexError or ValueError); the board ignores a command it cannot read."""
    from armkit.sim.ssc32 import SimSSC32

    board = SimSSC32()
    board.receive(line + b"\r", 0.0)
    assert board.errors
    board.receive(b"VER\r", 0.0)
    assert board.outbox.take(1.0) == b"SSC32-V2.50USB\r"
