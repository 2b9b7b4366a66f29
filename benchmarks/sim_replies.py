"""How fast ``armkit emulate`` answers the official dynamixel-sdk while the cores are busy.

``armkit emulate dynamixel --arm openmanipulator_x`` runs in its own process and
session (as in a second terminal) beside ``LOAD_PER_CORE`` busy processes per core
(in a session of their own, a build in a third terminal); this process reads Present
Position ``REQUESTS`` times through ``dynamixel_sdk.PacketHandler``, round robin over
the five servos. Reported: the SDK's round trip (write to whole reply) and the
emulator's own time from reading a request to writing its reply (its summary at exit),
median and 99.9th percentile [ms], against the SDK's timeout for that read (its
``setPacketTimeout``: 34 ms and the bytes' time) and the target, a fifth of it.

Run: .venv/bin/python benchmarks/sim_replies.py (benchmarks/sim.py runs it last).
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

import numpy as np

LOAD_PER_CORE = 2
REQUESTS = 5_000


def _start(args: list[str]) -> subprocess.Popen[str]:
    return subprocess.Popen(
        args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True
    )


def measure(requests: int = REQUESTS) -> tuple[np.ndarray, int, str, float]:
    """(round trips [s], timeouts, the emulator's own summary, the SDK's timeout [ms])."""
    import dynamixel_sdk as sdk

    emulator = _start(
        [sys.executable, "-m", "armkit.cli", "emulate", "dynamixel", "--arm", "openmanipulator_x"]
    )
    assert emulator.stdout is not None
    path = emulator.stdout.readline().strip()
    hogs = [
        _start([sys.executable, "-c", "while True: pass"])
        for _ in range(LOAD_PER_CORE * (os.cpu_count() or 1))
    ]
    try:
        port = sdk.PortHandler(path)
        port.openPort(), port.setBaudRate(1_000_000)
        ph = sdk.PacketHandler(2.0)
        trips, timeouts = [], 0
        for k in range(requests):
            start = time.perf_counter()
            _, result, _ = ph.read4ByteTxRx(port, 11 + k % 5, 132)
            trips.append(time.perf_counter() - start)
            timeouts += result != sdk.COMM_SUCCESS
        port.setPacketTimeout(4 + 11)
        timeout_ms = port.packet_timeout
        port.closePort()
    finally:
        for hog in hogs:
            hog.kill()
        emulator.send_signal(signal.SIGTERM)
        _, err = emulator.communicate(timeout=30)
    summary = next((line for line in err.splitlines() if "answered" in line), err.strip())
    return np.array(trips), timeouts, summary, timeout_ms


def main() -> None:
    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")
    os.environ.setdefault("ARMKIT_CONFIG_DIR", os.path.join(os.getcwd(), ".bench-config"))
    trips, timeouts, summary, timeout_ms = measure()
    p50, p999 = np.percentile(trips * 1000.0, [50, 99.9])
    load = LOAD_PER_CORE * (os.cpu_count() or 1)
    print(
        f"\narmkit emulate dynamixel, {len(trips)} SDK reads, {load} busy processes beside it [ms]"
    )
    head = f"{'':<28} {'median':>8} {'p99.9':>8}"
    print(head + "\n" + "-" * len(head))
    print(f"{'SDK round trip':<28} {p50:8.2f} {p999:8.2f}")
    print(f"emulator itself: {summary.removeprefix('armkit: emulator stopped; ')}")
    print(
        f"SDK timeout {timeout_ms:.1f} ms, target p99.9 < {timeout_ms / 5:.1f} ms; {timeouts} timeouts"
    )


if __name__ == "__main__":
    main()
