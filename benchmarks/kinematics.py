"""Kinematics speed and success per shipped arm, each figure beside its target (issue 29).

Run:  .venv/bin/python benchmarks/kinematics.py [--n 1000] [--batch 100000] [--seed 0]

Targets are FK of random joint vectors inside the limits (fixed seed), with the
pitch of that pose (none for planar2), the full orientation for the PUMA 560; the
"position only" rows give no pitch (the solver picks the one nearest the home
pose's that fits). Position-only targets where a joint limit refuses that pitch
(the solver then searches the limits' boundary) are their own "boundary" row.
"ok %" = solved, within 1 mm (the pitch within 0.01 deg, the orientation within
0.01 deg) and inside the limits (checked by FK). Per-call figures: each target
timed as the fastest of ``--repeats`` calls (a loaded machine only adds time),
then median, mean, p99 and max over the targets; batch figures: the least CPU time of
3 runs over N targets, per target (wall time on a quiet machine). Only the public API is used (and, for the cost
of FK's input checks, the chain's unchecked pose code), so the same script times
any version of armkit (PYTHONPATH=old/src). benchmarks/ik_peers.py measures the
peers (Robotics Toolbox, Pinocchio, ikpy) side by side in one run.
"""

from __future__ import annotations

import argparse
import math
import os
import time
from collections.abc import Callable, Sequence

import numpy as np

from armkit import fk, ik, ik_batch, load_model, pitch_of
from armkit.model import ArmModel

ARMS = ["owi535", "openmanipulator_x", "lynx6", "planar2"]
POSITION_ONLY = ["openmanipulator_x", "lynx6"]
Target = tuple[tuple[float, float, float], "float | None", "np.ndarray | None"]


def timed(fn: Callable[[], object], repeats: int) -> float:
    """The fastest of ``repeats`` calls of fn [s]."""
    best = math.inf
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def cpu_best_of(fn: Callable[[], object], runs: int = 3) -> float:
    """The least CPU time of ``runs`` calls of fn [s]: a batch of milliseconds is
    preempted on a loaded machine, and its wall time then counts other processes' work."""
    best = math.inf
    for _ in range(runs):
        t0 = time.process_time()
        fn()
        best = min(best, time.process_time() - t0)
    return best


def stats(label: str, secs: Sequence[float], ok: float, target: str) -> list[str]:
    us = np.asarray(secs) * 1e6
    figures = (np.median(us), us.mean(), np.percentile(us, 99), us.max())
    return [label, *(f"{v:.2f}" for v in figures), f"{ok:.2f}", target]


def make_targets(m: ArmModel, n: int, seed: int, task: str) -> tuple[np.ndarray, list[Target]]:
    q = np.random.default_rng(seed).uniform(m.lower, m.upper, (n, m.dof))
    T = fk(m, q)
    pitch = np.asarray(pitch_of(T)) if task == "pitch" else None
    return (
        T,
        [
            (
                tuple(T[i, :3, 3].tolist()),  # type: ignore[misc]
                None if pitch is None else float(pitch[i]),
                T[i, :3, :3].copy() if task == "pose" else None,
            )
            for i in range(n)
        ],
    )


def solve(m: ArmModel, t: Target) -> np.ndarray:
    return ik(m, t[0], t[1], orientation=t[2]).q


def verify(m: ArmModel, targets: list[Target], idx: Sequence[int] | None = None) -> float:
    """Percent of targets solved within 1 mm (and 0.01 deg) inside the limits."""
    idx = range(len(targets)) if idx is None else idx
    good = 0
    for i in idx:
        p, pt, R = targets[i]
        q = solve(m, targets[i])
        T = fk(m, q)
        close = np.linalg.norm(T[:3, 3] - p) < 1e-3
        if pt is not None:
            close &= abs(math.remainder(float(pitch_of(T)) - pt, 2 * math.pi)) < math.radians(0.01)
        if R is not None:
            cos = (np.trace(R @ T[:3, :3].T) - 1.0) / 2.0
            close &= math.acos(max(-1.0, min(1.0, cos))) < math.radians(0.01)
        good += bool(close and m.within_limits(q))
    return 100.0 * good / max(len(idx), 1)


def per_call_rows(name: str, n: int, seed: int, repeats: int) -> list[list[str]]:
    m = load_model(name)
    task = "pose" if m.dof == 6 else ("free" if m.dof == 2 else "pitch")
    rows = []
    q = np.random.default_rng(seed).uniform(m.lower, m.upper, (min(n, 300), m.dof))
    fk_s = [timed(lambda v=v: fk(m, v), repeats) for v in q]
    rows.append(stats(f"{name} fk", fk_s, 100.0, "<= 6 us" if name == "openmanipulator_x" else ""))
    from armkit.kinematics._chain import chain_of

    pose = getattr(chain_of(m), "pose", None)  # (an older armkit has none)
    if name == "openmanipulator_x" and pose is not None:  # fk's checks' cost: the pose code alone
        lists = [v.tolist() for v in q]
        core = [timed(lambda v=v: np.array(pose(v)).reshape(4, 4), repeats) for v in lists]
        rows.append(stats(f"{name} fk unchecked (checks' cost = difference)", core, 100.0, ""))
    _, targets = make_targets(m, n, seed, task)
    secs = [timed(lambda t=t: solve(m, t), repeats) for t in targets]
    label = (
        f"{name} ik " + {"pose": "full pose", "free": "position", "pitch": "position+pitch"}[task]
    )
    rows.append(stats(label, secs, verify(m, targets), "<= 20 us" if task == "pose" else ""))
    return rows


def boundary_rows(name: str, n: int, seed: int, repeats: int) -> list[list[str]]:
    """Position only, normal targets and boundary targets apart (see the module docstring)."""
    from armkit.kinematics._chain import chain_of

    m = load_model(name)
    chain = chain_of(m)
    assert chain.free is not None
    _, targets = make_targets(m, n, seed, "free")
    hard = [chain.free(*t[0], chain.home) == [] for t in targets]
    secs = np.array([timed(lambda t=t: solve(m, t), repeats) for t in targets])
    normal = [i for i in range(n) if not hard[i]]
    edge = [i for i in range(n) if hard[i]]
    ratio = np.median(secs[edge]) / np.median(secs[normal]) if edge else math.nan
    return [
        stats(f"{name} ik position, all", secs, verify(m, targets), ""),
        stats(f"{name} ik position, normal", secs[normal], verify(m, targets, normal), ""),
        stats(
            f"{name} ik position, boundary ({100 * len(edge) / n:.1f} %; {ratio:.1f}x normal)",
            secs[edge],
            verify(m, targets, edge),
            "<= 2x normal",
        ),
    ]


def batch_rows(name: str, n: int, seed: int, position_only: bool = False) -> list[str]:
    m = load_model(name)
    task = "free" if position_only or m.dof == 2 else ("pose" if m.dof == 6 else "pitch")
    T, _ = make_targets(m, n, seed, task)
    q = np.random.default_rng(seed).uniform(m.lower, m.upper, (n, m.dof))
    P = T[:, :3, 3]
    pitch = np.asarray(pitch_of(T)) if task == "pitch" else None
    R = T[:, :3, :3] if task == "pose" else None
    fk_ns = cpu_best_of(lambda: fk(m, q)) / n * 1e9
    ik_ns = cpu_best_of(lambda: ik_batch(m, P, pitch, orientations=R)) / n * 1e9
    out = ik_batch(m, P, pitch, orientations=R)
    got = fk(m, np.where(out.ok[:, None], out.q, m.home))
    good = out.ok & (np.linalg.norm(got[:, :3, 3] - P, axis=1) < 1e-3)
    kind = {"free": "position", "pitch": "position+pitch", "pose": "full pose"}[task]
    label = f"{name}, {'position only' if position_only else kind}"
    target = ">= 0.5 M/s" if task == "pose" else ">= 1 M/s"
    return [
        label,
        "-" if position_only else f"{fk_ns:.0f}",
        f"{ik_ns:.0f}",
        f"{1e3 / ik_ns:.2f}",
        f"{100 * good.mean():.2f}",
        target,
    ]


def table(headers: list[str], rows: list[list[str]]) -> str:
    widths = [max(len(h), *(len(r[i]) for r in rows)) for i, h in enumerate(headers)]
    lines = [
        "  ".join(
            h.rjust(w) if i else h.ljust(w)
            for i, (h, w) in enumerate(zip(headers, widths, strict=True))
        )
    ]
    for r in rows:
        lines.append(
            "  ".join(
                c.rjust(w) if i else c.ljust(w)
                for i, (c, w) in enumerate(zip(r, widths, strict=True))
            )
        )
    return "\n".join(lines)


def main() -> None:
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument(
        "--n", type=int, default=1000, help="single-call targets per arm (default 1000)"
    )
    ap.add_argument("--batch", type=int, default=100_000, help="batch size (default 100000)")
    ap.add_argument(
        "--repeats", type=int, default=3, help="calls per target, fastest kept (default 3)"
    )
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")
    rows = []
    for name in [*ARMS, "puma560"]:
        rows += per_call_rows(name, args.n, args.seed, args.repeats)
    for name in POSITION_ONLY:
        rows += boundary_rows(name, args.n, args.seed, args.repeats)
    headers = ["per call", "median us", "mean us", "p99 us", "max us", "ok %", "target"]
    print(table(headers, rows))
    print()
    brows = [batch_rows(name, args.batch, args.seed) for name in [*ARMS, "puma560"]]
    brows += [batch_rows(name, args.batch, args.seed, True) for name in POSITION_ONLY]
    headers = ["batch (CPU time)", "fk ns/pose", "ik ns/target", "ik M targets/s", "ok %", "target"]
    print(table(headers, brows))
    print("fk batch target: <= 300 ns/pose")


if __name__ == "__main__":
    main()
