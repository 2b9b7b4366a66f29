"""How well the 3D page follows an arm moving in the same process.

The simulated OpenManipulator-X swings between two poses in real time (a
``Mover`` paces the simulation by the wall clock) while ``View`` reads it
``rate`` times a second and sends what moved. Headless Chromium opens the
page; the DevTools protocol reports every websocket frame the page receives,
stamped on the same monotonic clock as ``time.monotonic``. Each frame is
decoded (viser's zstd-compressed msgpack) and matched to the read that
produced it by the pose it carries, which gives:

- updates/s: distinct arm states the page received per second;
- lag: page receive time minus the time the state was read from the driver
  (what a person sees is older by up to one period more: the age of the read);
- draws/s: frames the page's renderer drew (requestAnimationFrame).

    .venv/bin/python benchmarks/view.py [--seconds 5] [--rates 30 60]
"""

from __future__ import annotations

import argparse
import base64
import time
from dataclasses import dataclass

import msgspec
import numpy as np
import zstandard

import armkit
from armkit.viz import DriverSource, Goal, Mover
from armkit.viz.web import Chromium, View
from armkit.viz.web._picture import connected_client, wait_for_camera

POSES = (np.radians([-60.0, 10.0, 10.0, -20.0]), np.radians([60.0, -20.0, 30.0, 10.0]))
PROBE = "/arm/link_4"  # the node whose position identifies a state
COUNT_DRAWS = "window.__draws = 0; (function tick(){ window.__draws++; requestAnimationFrame(tick); })(); true"


@dataclass(frozen=True)
class Row:
    rate: float
    reads: float
    sent: float
    received: float
    lag_ms: tuple[float, float, float]
    draws: float


def _key(position: object) -> tuple[float, ...]:
    return tuple(round(float(v), 7) for v in np.asarray(position).ravel())


def _decode(payload: str) -> list[dict[str, object]]:
    raw = base64.b64decode(payload)
    size, packed = int.from_bytes(raw[:8], "little"), int.from_bytes(raw[8:16], "little")
    inner = zstandard.ZstdDecompressor().decompress(raw[16 : 16 + packed], max_output_size=size)
    messages: list[dict[str, object]] = msgspec.msgpack.decode(inner)["messages"]
    return messages


def measure(rate: float, seconds: float) -> Row:
    arm = armkit.Arm("openmanipulator_x")
    sent: dict[tuple[float, ...], float] = {}
    with (
        View(DriverSource(arm.model, arm.driver), port=0, rate_hz=rate) as view,
        Chromium(960, 640, record_frames=True) as browser,
    ):

        def remember() -> None:
            state = view.state
            if state is not None:
                sent[_key(armkit.fk_frames(arm.model, state.q)[4, :3, 3])] = state.t

        view.on_update(remember)
        view.start()
        browser.open(view.url, "document.querySelector('canvas') !== null")
        wait_for_camera(view, connected_client(view))
        browser.evaluate(COUNT_DRAWS)
        mover = Mover(arm)
        stats0, first_frame = view.stats(), len(browser.frames)
        start = time.monotonic()
        i = 0
        while time.monotonic() - start < seconds:
            mover.request(Goal(q=POSES[i % 2], speed=0.6))
            mover.wait_idle(seconds)
            i += 1
        elapsed = time.monotonic() - start
        draws = float(browser.evaluate("window.__draws"))
        mover.close()
        time.sleep(0.3)
        stats = view.stats()
        frames = browser.frames[first_frame:]
    lags = []
    for frame in frames:
        for msg in _decode(frame.payload):
            if msg.get("type") == "SetPositionMessage" and msg.get("name") == PROBE:
                t_read = sent.get(_key(msg["position"]))
                if t_read is not None and t_read >= start:
                    lags.append(frame.time - t_read)
    lag = np.array(lags) * 1000.0
    return Row(
        rate,
        (stats.reads - stats0.reads) / elapsed,
        (stats.updates - stats0.updates) / elapsed,
        len(lags) / elapsed,
        (float(np.median(lag)), float(np.percentile(lag, 95)), float(lag.max())),
        draws / elapsed,
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=5.0, help="motion per rate [s]")
    parser.add_argument("--rates", type=float, nargs="+", default=[30.0, 60.0], help="[Hz]")
    args = parser.parse_args()
    print("armkit view following the simulated OpenManipulator-X moving in real time")
    print(f"{args.seconds:.0f} s of motion per row; lag = page receives - state read [ms]\n")
    header = f"{'rate Hz':>8} {'reads/s':>8} {'sent/s':>7} {'page/s':>7} {'lag p50':>8} {'p95':>6} {'max':>6} {'draws/s':>8}"
    print(header)
    print("-" * len(header))
    for rate in args.rates:
        r = measure(rate, args.seconds)
        p50, p95, worst = r.lag_ms
        print(
            f"{r.rate:8.0f} {r.reads:8.1f} {r.sent:7.1f} {r.received:7.1f} "
            f"{p50:8.1f} {p95:6.1f} {worst:6.1f} {r.draws:8.1f}"
        )


if __name__ == "__main__":
    main()
