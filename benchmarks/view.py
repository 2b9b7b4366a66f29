"""How well the 3D page follows an arm: moving in the same process, and moved by
ANOTHER process (``armkit view --follow``).

Same process: the simulated OpenManipulator-X swings between two poses in real
time (a ``Mover`` paces the simulation by the wall clock) while ``View`` reads
it ``rate`` times a second and sends what moved. Follow: a second Python process
opens the simulated arm as the CLI does (its state kept in a file, so it
publishes on the live channel while followed) and swings it; this process's
``View`` of a ``LiveSource`` follows it ``rate`` times a second. Headless Chromium opens the
page; the DevTools protocol reports every websocket frame the page receives,
stamped on the same monotonic clock as ``time.monotonic``. Each frame is
decoded (viser's zstd-compressed msgpack) and matched to the read that
produced it by the pose it carries, which gives:

- sent/s, page/s: distinct arm states the view sent, the page received, per
  second while the arm moved (from the first to the last state that changed);
- lag: page receive time minus the time the state was read from the driver
  (follow: minus the time the other process published it); what a person sees
  is older by up to one period more (the age of the read);
- draws/s: frames the page's renderer drew (requestAnimationFrame).

    .venv/bin/python benchmarks/view.py [--seconds 5] [--rates 30 60] [--follow-rates 30 45]
        [--job-rates 45]   (a drawing in another process: armkit draw svg lines.svg)
"""

from __future__ import annotations

import argparse
import base64
import os
import signal
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass

import msgspec
import numpy as np
import zstandard

import armkit
from armkit.connect import sim_state_file
from armkit.viz import ArmSource, Goal, LiveSource, Mover, StateSource
from armkit.viz.web import Chromium, View
from armkit.viz.web._picture import connected_client, wait_for_camera

POSES = (np.radians([-60.0, 10.0, 10.0, -20.0]), np.radians([60.0, -20.0, 30.0, 10.0]))
DRAWING = os.path.join(os.path.dirname(__file__), "..", "examples", "drawings", "lines.svg")
PROBE = "/arm/link_4"  # the node whose position identifies a state
COUNT_DRAWS = "window.__draws = 0; (function tick(){ window.__draws++; requestAnimationFrame(tick); })(); true"


SWING = """
import sys, time
import numpy as np
import armkit
from armkit.connect import open_driver, sim_state_file, world_of
from armkit.viz.live import publish_live
model = armkit.load_model("openmanipulator_x")
driver = open_driver(model, keep=True)
world = world_of(driver)
for truth in world.arms():  # published live as the CLI's kept arm is (cli/_kept.py)
    publish_live(world, truth, sim_state_file(model))
with armkit.Arm(model, driver) as arm:
    end = time.monotonic() + float(sys.argv[1])
    i = 0
    while time.monotonic() < end:
        arm.move_joints([-60.0, 10.0, 10.0, -20.0] if i % 2 == 0 else [60.0, -20.0, 30.0, 10.0], speed=0.6)
        i += 1
"""


@dataclass(frozen=True)
class Row:
    what: str
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
    """Same process: the arm moved by a Mover, the view of its driver."""
    arm = armkit.Arm("openmanipulator_x")
    mover = Mover(arm)

    def swing(start: float) -> None:
        i = 0
        while time.monotonic() - start < seconds:
            mover.request(Goal(q=POSES[i % 2], speed=0.6))
            mover.wait_idle(seconds)
            i += 1
        mover.close()

    return _measure("same process", ArmSource(arm), rate, swing)


def measure_follow(rate: float, seconds: float) -> Row:
    """Another process moves the arm; the view follows it through the live channel."""
    with tempfile.TemporaryDirectory(prefix="armkit-bench-") as config:
        os.environ["ARMKIT_CONFIG_DIR"] = config
        model = armkit.load_model("openmanipulator_x")
        source = LiveSource(model, sim_state_file(model))
        source.state()  # the follow file exists before the other process starts

        def swing(start: float) -> None:
            code = subprocess.run([sys.executable, "-c", SWING, str(seconds)], check=False)
            assert code.returncode == 0

        try:
            return _measure("other process", source, rate, swing)
        finally:
            source.close()
            del os.environ["ARMKIT_CONFIG_DIR"]


def measure_job(rate: float, seconds: float) -> Row:
    """A job in another process (``armkit --scene drawing draw svg lines.svg``, as a
    teacher runs it beside ``armkit view --follow``), interrupted ``seconds`` after it
    starts moving."""
    with tempfile.TemporaryDirectory(prefix="armkit-bench-") as config:
        os.environ["ARMKIT_CONFIG_DIR"] = config
        model = armkit.load_model("openmanipulator_x")
        source = LiveSource(model, sim_state_file(model))
        source.state()

        def draw(start: float) -> None:
            argv = [sys.executable, "-m", "armkit.cli", "--scene", "drawing", "draw", "svg"]
            with subprocess.Popen(
                [*argv, DRAWING], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True
            ) as job:
                assert job.stdout is not None
                job.stdout.readline()  # "draw lines.svg on A5 ...": planned, it starts moving
                time.sleep(seconds)
                job.send_signal(signal.SIGINT)
                job.communicate()

        try:
            return _measure("job (draw)", source, rate, draw)
        finally:
            source.close()
            del os.environ["ARMKIT_CONFIG_DIR"]


def _measure(what: str, source: StateSource, rate: float, swing: Callable[[float], None]) -> Row:
    model = source.model
    sent: dict[tuple[float, ...], float] = {}
    shown: list[float] = []  # when each update was sent [s]
    with (
        View(source, port=0, rate_hz=rate) as view,
        Chromium(960, 640, record_frames=True) as browser,
    ):

        def remember() -> None:
            state = view.state
            if state is not None:
                sent[_key(armkit.fk_frames(model, state.q)[4, :3, 3])] = state.t
                shown.append(time.monotonic())

        view.on_update(remember)
        view.start()
        browser.open(view.url, "document.querySelector('canvas') !== null")
        wait_for_camera(view, connected_client(view))
        browser.evaluate(COUNT_DRAWS)
        stats0, first_frame = view.stats(), len(browser.frames)
        start = time.monotonic()
        swing(start)
        elapsed = time.monotonic() - start
        draws = float(browser.evaluate("window.__draws"))
        time.sleep(0.3)
        stats = view.stats()
        frames = browser.frames[first_frame:]
    lag = np.array(_lags(frames, sent, start)) * 1000.0
    moving = [t for t in shown if t >= start]
    if len(moving) < 2 or moving[-1] <= moving[0]:
        raise SystemExit(
            f"{what} at {rate:g} Hz: the view saw {len(moving)} updates while the arm moved"
        )
    span = moving[-1] - moving[0]  # while the arm moved (the other process starts first)
    return Row(
        what,
        rate,
        (stats.reads - stats0.reads) / elapsed,
        (len(moving) - 1) / span,
        len(lag) / span,
        (float(np.median(lag)), float(np.percentile(lag, 95)), float(lag.max())),
        draws / elapsed,
    )


def _lags(frames: list[object], sent: dict[tuple[float, ...], float], start: float) -> list[float]:
    lags = []
    for frame in frames:
        for msg in _decode(frame.payload):  # type: ignore[attr-defined]
            if msg.get("type") == "SetPositionMessage" and msg.get("name") == PROBE:
                t_read = sent.get(_key(msg["position"]))
                if t_read is not None and t_read >= start:
                    lags.append(frame.time - t_read)  # type: ignore[attr-defined]
    return lags


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=5.0, help="motion per rate [s]")
    parser.add_argument("--rates", type=float, nargs="*", default=[30.0, 60.0], help="[Hz]")
    parser.add_argument(
        "--follow-rates", type=float, nargs="*", default=[30.0, 45.0], help="[Hz], --follow"
    )
    parser.add_argument(
        "--job-rates", type=float, nargs="*", default=[45.0], help="[Hz], --follow of a job"
    )
    args = parser.parse_args()
    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")
    print("armkit view following the simulated OpenManipulator-X moving in real time")
    print(f"{args.seconds:.0f} s of motion per row; lag = page receives - state read [ms]")
    print("(other process: - state published by the process that moves the arm)\n")
    header = f"{'moved by':<14} {'rate Hz':>8} {'reads/s':>8} {'sent/s':>7} {'page/s':>7} {'lag p50':>8} {'p95':>6} {'max':>6} {'draws/s':>8}"
    print(header)
    print("-" * len(header))
    rows = [(measure, r) for r in args.rates] + [(measure_follow, r) for r in args.follow_rates]
    rows += [(measure_job, r) for r in args.job_rates]
    for how, rate in rows:
        r = how(rate, args.seconds)
        p50, p95, worst = r.lag_ms
        print(
            f"{r.what:<14} {r.rate:8.0f} {r.reads:8.1f} {r.sent:7.1f} {r.received:7.1f} "
            f"{p50:8.1f} {p95:6.1f} {worst:6.1f} {r.draws:8.1f}"
        )


if __name__ == "__main__":
    main()
