"""Kinematics speed and success per shipped arm: FK, batch FK, closed-form IK, batch IK.

Run:  .venv/bin/python benchmarks/kinematics.py [--n 1000] [--batch 100000] [--seed 0]

Targets are FK of random joint vectors inside the limits (fixed seed), with the
pitch of that pose (none for planar2); the "position only" rows give no pitch
(the solver picks the one nearest the home pose's that fits). "ok %" = solved,
within 1 mm (and the pitch within 0.01 deg where one was given) and inside
the limits (checked by FK). Only the public API is used, so the same script
times any version of armkit (PYTHONPATH=old/src). Times are medians over targets, each timed over
repeated calls; batch times are the best of 3 runs divided by N. Quoted peer
numbers (peers.md, same kind of machine) are printed for scale below the table;
benchmarks/ik_peers.py measures the peers side by side in one run.
"""

from __future__ import annotations

import argparse
import math
import statistics
import time
from collections.abc import Callable

import numpy as np

from armkit import fk, ik, ik_batch, load_model, pitch_of

ARMS = ["owi535", "openmanipulator_x", "lynx6", "planar2"]
POSITION_ONLY = ["openmanipulator_x", "lynx6"]
PEERS = """for scale (../shared/reference/peers.md, a 2-core machine like this one, OpenManipulator-X):
  RTB DHRobot.fkine (Python) 37 us/call; RTB C++ ets().eval 4.7 us/call, 0.5-0.75 us/pose batched
  ikpy forward_kinematics 15-17 us; RTB C++ ik_LM 18 us median; a plain-Python closed form 4.8 us"""


def per_call(fn: Callable[[], object], repeat: int = 20) -> float:
    """Seconds per call of fn, timed over ``repeat`` calls."""
    t0 = time.perf_counter()
    for _ in range(repeat):
        fn()
    return (time.perf_counter() - t0) / repeat


def best_of(fn: Callable[[], object], runs: int = 3) -> float:
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def measure(name: str, n: int, batch: int, seed: int, position_only: bool = False) -> list[str]:
    m = load_model(name)
    rng = np.random.default_rng(seed)
    q = rng.uniform(m.lower, m.upper, (max(n, batch), m.dof))
    T = fk(m, q)
    P = T[:, :3, 3]
    free = m.dof == 2 or position_only  # planar2: the pitch follows from the position
    pitch = None if free else np.asarray(pitch_of(T))
    targets = [(tuple(P[i].tolist()), None if pitch is None else float(pitch[i])) for i in range(n)]
    fk_us = statistics.median(per_call(lambda i=i: fk(m, q[i])) for i in range(min(n, 300))) * 1e6
    fk_ns = best_of(lambda: fk(m, q[:batch])) / batch * 1e9
    ik_us = statistics.median(per_call(lambda t=t: ik(m, t[0], t[1])) for t in targets) * 1e6
    ikb_ns = (
        best_of(lambda: ik_batch(m, P[:batch], None if pitch is None else pitch[:batch]))
        / batch
        * 1e9
    )
    ok = verify(m, targets)
    return [
        f"{name}, position only" if position_only else name,
        "-" if position_only else f"{fk_us:.2f}",
        "-" if position_only else f"{fk_ns:.0f}",
        f"{ik_us:.2f}",
        f"{ikb_ns:.0f}",
        f"{1e9 / ikb_ns / 1e6:.2f}",
        f"{ok:.2f}",
    ]


def verify(m, targets) -> float:  # type: ignore[no-untyped-def]
    """Percent of targets solved, within 1 mm (and the pitch within 0.01 deg), inside the limits."""
    good = 0
    for p, pt in targets:
        res = ik(m, p, pt)
        T = fk(m, res.q)
        close = np.linalg.norm(T[:3, 3] - p) < 1e-3
        level = pt is None or abs(
            math.remainder(float(pitch_of(T)) - pt, 2 * math.pi)
        ) < math.radians(0.01)
        good += bool(close and level and m.within_limits(res.q))
    return 100.0 * good / len(targets)


def main() -> None:
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument(
        "--n", type=int, default=1000, help="single-call targets per arm (default 1000)"
    )
    ap.add_argument("--batch", type=int, default=100_000, help="batch size (default 100000)")
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    headers = [
        "arm",
        "fk us/call",
        "fk batch ns/pose",
        "ik us/call",
        "ik_batch ns/target",
        "ik_batch M/s",
        "ok %",
    ]
    rows = [measure(name, args.n, args.batch, args.seed) for name in ARMS]
    rows += [measure(name, args.n, args.batch, args.seed, True) for name in POSITION_ONLY]
    widths = [max(len(h), *(len(r[i]) for r in rows)) for i, h in enumerate(headers)]
    print("  ".join(h.rjust(w) for h, w in zip(headers, widths, strict=True)))
    for r in rows:
        print("  ".join(c.rjust(w) for c, w in zip(r, widths, strict=True)))
    print("targets: ik <= 5 us/call, ik_batch >= 1 M targets/s, fk batch <= 300 ns/pose")
    print(PEERS)


if __name__ == "__main__":
    main()
