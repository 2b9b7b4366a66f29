"""Side-by-side IK benchmark: armkit against Robotics Toolbox for Python and ikpy.

    .venv/bin/python benchmarks/ik_peers.py [--n 1000] [--seed 0] [--arms openmanipulator_x al5d puma560]

The same N reachable targets (FK of random joint vectors inside the limits,
fixed seed) per arm, every solver starting from the arm's home pose. Tasks:
position for the 4/5-joint arms (the peers have no pitch-only mask), full
pose for the PUMA 560. Rows: armkit analytic (where the closed-form family
fits; position targets, pitch free), armkit lm per call (``armkit.kinematics.ik``),
armkit lm batch per target (the least CPU time of the repeats), RTB C++ ``ETS.ik_LM`` (the ETS path, which
applies the tool once, tol 1e-10 on 1/2|e|^2), RTB Python ``ETS.ikine_LM``
(same settings) and ikpy ``Chain.inverse_kinematics``. The peers' robots are
built from armkit's own DH rows (offsets, flips, tool) and every answer is
verified with armkit's FK: success = within 1 mm (and 0.1 deg for pose
targets) with every joint inside its limits.

The peers live in their own virtual environment, benchmarks/.peers-venv
(created on first use: python3 -m venv + pip install roboticstoolbox-python
ikpy pin); they are never dependencies of armkit. This file is both the driver
(run with armkit's interpreter) and the worker (run by the peers' one).
"""

from __future__ import annotations

import argparse
import contextlib
import json
import math
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
PEERS_VENV = HERE / ".peers-venv"
ARM_TASKS = {
    "openmanipulator_x": "position",
    "al5d": "position",
    "puma560": "pose",
    "puma560_offset": "pose",
    "panda": "pose",
}
WARMUP = 10
# Arms with no closed form, for the numeric solvers (issue 29.2): the PUMA 560 with a
# 40 mm offset in its wrist (a 6R whose wrist axes do not meet), and a 7-joint URDF (the
# Franka Panda's modified DH parameters and limits, flange 107 mm, approach along its z).
_PANDA = [  # a, d [mm], alpha, lower, upper [deg]
    (0.0, 333.0, 0.0, -166.0, 166.0),
    (0.0, 0.0, -90.0, -101.0, 101.0),
    (0.0, 316.0, 90.0, -166.0, 166.0),
    (82.5, 0.0, 90.0, -176.0, -4.0),
    (-82.5, 384.0, -90.0, -166.0, 166.0),
    (0.0, 0.0, 90.0, -1.0, 215.0),
    (88.0, 0.0, 90.0, -166.0, 166.0),
]


def extra_model(name: str, folder: Path):  # type: ignore[no-untyped-def]
    """The benchmark's own arms (see above), written as model files and loaded."""
    from armkit.model import load_model

    if name == "puma560_offset":
        text = (HERE.parent / "src/armkit/model/arms/puma560.toml").read_text()
        text = text.replace('name = "puma560"', 'name = "puma560_offset"')
        text = text.replace("alpha_deg = -90.0, d_mm = 0.0 }", "alpha_deg = -90.0, d_mm = 40.0 }")
    else:  # a URDF: each modified DH row as a joint origin Rx(alpha) Tx(a) Tz(d)
        joints, parent = [], "base"
        for i, (a, d, al, lo, hi) in enumerate(_PANDA):
            c, s_ = math.cos(math.radians(al)), math.sin(math.radians(al))
            joints.append(
                f'<joint name="j{i + 1}" type="revolute"><parent link="{parent}"/>'
                f'<child link="l{i + 1}"/><origin xyz="{a / 1000} {-s_ * d / 1000} {c * d / 1000}" '
                f'rpy="{math.radians(al)} 0 0"/><axis xyz="0 0 1"/><limit lower="{math.radians(lo)}" '
                f'upper="{math.radians(hi)}" effort="1" velocity="1"/></joint><link name="l{i + 1}"/>'
            )
            parent = f"l{i + 1}"
        path = folder / "panda.urdf"
        path.write_text(
            '<?xml version="1.0"?><robot name="panda"><link name="base"/>' + "".join(joints)
            + '<joint name="flange" type="fixed"><parent link="l7"/><child link="tool"/>'
            '<origin xyz="0 0 0.107" rpy="0 -1.5707963267948966 0"/></joint><link name="tool"/></robot>'
        )  # fmt: skip
        return load_model(path)
    path = folder / f"{name}.toml"
    path.write_text(text)
    return load_model(path)


# ---------------------------------------------------------------- the worker (peers' venv)


def _fixed(T: np.ndarray) -> tuple[list[float], list[float]]:
    """A 4x4 transform as (xyz, rpy) with R = Rz(yaw) Ry(pitch) Rx(roll)."""
    R = T[:3, :3]
    rpy = [
        math.atan2(R[2, 1], R[2, 2]),
        math.asin(max(-1.0, min(1.0, -R[2, 0]))),
        math.atan2(R[1, 0], R[0, 0]),
    ]
    return T[:3, 3].tolist(), rpy


def _rot(axis: str, angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    T = np.eye(4)
    i, j = {"x": (1, 2), "z": (0, 1)}[axis]
    T[i, i], T[i, j], T[j, i], T[j, j] = c, -s, s, c
    return T


def _trans(x: float = 0.0, z: float = 0.0) -> np.ndarray:
    T = np.eye(4)
    T[0, 3], T[2, 3] = x, z
    return T


def _rtb_robot(spec: dict):  # type: ignore[no-untyped-def]
    import roboticstoolbox as rtb
    from spatialmath import SE3

    if spec["frames"] is not None:  # a URDF arm: per joint its origin, then a turn about z
        ets = rtb.ETS()
        for i, ((origin, sign), lim) in enumerate(zip(spec["frames"], spec["limits"], strict=True)):
            ets *= rtb.ET.SE3(np.array(origin)) * rtb.ET.Rz(jindex=i, flip=sign < 0, qlim=lim)
        return ets * rtb.ET.SE3(np.array(spec["tool"]))
    kind = rtb.RevoluteMDH if spec["modified"] else rtb.RevoluteDH
    links = [
        kind(a=r["a"], alpha=r["alpha"], d=r["d"], offset=r["offset"], flip=r["sign"] < 0, qlim=lim)
        for r, lim in zip(spec["rows"], spec["limits"], strict=True)
    ]
    robot = rtb.DHRobot(links, tool=SE3(np.array(spec["tool"]), check=False))
    return robot.ets()  # the ETS includes the tool once


def _ikpy_chain(spec: dict):  # type: ignore[no-untyped-def]
    from ikpy.chain import Chain
    from ikpy.link import OriginLink, URDFLink

    links, F = [OriginLink()], np.eye(4)
    if spec["frames"] is not None:  # a URDF arm: its joints as they are
        for i, ((origin, sign), lim) in enumerate(zip(spec["frames"], spec["limits"], strict=True)):
            xyz, rpy = _fixed(np.array(origin))
            axis = np.array([0, 0, sign])
            links.append(
                URDFLink(f"j{i}", np.array(xyz), np.array(rpy), rotation=axis, bounds=tuple(lim))
            )
        xyz, rpy = _fixed(np.array(spec["tool"]))
        links.append(URDFLink("tool", np.array(xyz), np.array(rpy), joint_type="fixed"))
        return Chain(links, active_links_mask=[False] + [True] * len(spec["frames"]) + [False])
    for i, (r, lim) in enumerate(zip(spec["rows"], spec["limits"], strict=True)):
        before = _rot("x", r["alpha"]) @ _trans(x=r["a"]) if spec["modified"] else np.eye(4)
        xyz, rpy = _fixed(F @ before @ _rot("z", r["offset"]))
        links.append(
            URDFLink(
                f"j{i}",
                np.array(xyz),
                np.array(rpy),
                rotation=np.array([0, 0, r["sign"]]),
                bounds=tuple(lim),
            )
        )
        F = (
            _trans(z=r["d"])
            if spec["modified"]
            else _trans(z=r["d"]) @ _trans(x=r["a"]) @ _rot("x", r["alpha"])
        )
    xyz, rpy = _fixed(F @ np.array(spec["tool"]))
    links.append(URDFLink("tool", np.array(xyz), np.array(rpy), joint_type="fixed"))
    mask = [False] + [True] * len(spec["limits"]) + [False]
    return Chain(links, active_links_mask=mask)


def _time_solver(solve, targets: list[np.ndarray], dof: int, repeats: int) -> dict:  # type: ignore[no-untyped-def]
    for T in targets[:WARMUP]:
        solve(T)
    q, secs, its = [], [], []
    for T in targets:
        best = math.inf
        for _ in range(repeats):
            t0 = time.perf_counter()
            ans, it = solve(T)
            best = min(best, time.perf_counter() - t0)
        secs.append(best)
        q.append([float("nan")] * dof if ans is None else [float(v) for v in ans])
        its.append(float("nan") if it is None else float(it))
    return {"q": q, "seconds": secs, "iterations": its}


def _peer_fk(spec: dict, ets, chain, checks: list) -> dict:  # type: ignore[no-untyped-def]
    """Single-pose FK per call [s] (fastest of 5 per pose) and the largest difference from
    armkit's [m]: RTB's C++ ETS.eval, Pinocchio built from armkit's URDF, ikpy."""
    import pinocchio as pin

    pm = pin.buildModelFromXML(spec["urdf"])
    pd, frame = pm.createData(), pm.getFrameId("tool")

    def pin_fk(q):  # type: ignore[no-untyped-def]
        pin.forwardKinematics(pm, pd, q)
        pin.updateFramePlacement(pm, pd, frame)
        return pd.oMf[frame].homogeneous

    qs = [np.array(q) for q in spec["fk_q"]]
    out = {}
    for name, fn in (
        ("rtb C++ ETS.eval", ets.eval),
        ("pinocchio", pin_fk),
        ("ikpy", lambda q: chain.forward_kinematics([0.0, *q, 0.0])),
    ):
        err = max(
            float(np.abs(fn(np.array(q)) - T).max())
            for q, T in zip(spec["check_q"], checks, strict=True)
        )
        secs = []
        for q in qs:
            best = math.inf
            for _ in range(5):
                t0 = time.perf_counter()
                fn(q)
                best = min(best, time.perf_counter() - t0)
            secs.append(best)
        out[name] = {"seconds": secs, "error": err}
    return out


def worker(spec_path: str, out_path: str) -> None:
    """Run the peers on the targets in spec_path; write answers and times to out_path."""
    spec = json.loads(Path(spec_path).read_text())
    targets = [np.array(T) for T in spec["targets"]]
    q0, dof, pose = np.array(spec["q0"]), len(spec["limits"]), spec["task"] == "pose"
    mask = np.ones(6) if pose else np.array([1.0, 1, 1, 0, 0, 0])
    ets, chain = _rtb_robot(spec), _ikpy_chain(spec)
    checks = [np.array(c) for c in spec["checks"]]
    fk_error = {
        "rtb": max(
            float(np.abs(ets.eval(np.array(q)) - T).max())
            for q, T in zip(spec["check_q"], checks, strict=True)
        ),
        "ikpy": max(
            float(np.abs(chain.forward_kinematics([0.0, *q, 0.0]) - T).max())
            for q, T in zip(spec["check_q"], checks, strict=True)
        ),
    }

    def rtb_cpp(T):  # type: ignore[no-untyped-def]
        sol = ets.ik_LM(T, q0=q0, tol=1e-10, mask=mask, joint_limits=True)
        return (sol.q if sol.success else None), sol.iterations

    def rtb_py(T):  # type: ignore[no-untyped-def]
        sol = ets.ikine_LM(T, q0=q0, tol=1e-10, mask=mask, joint_limits=True)
        return (sol.q if sol.success else None), sol.iterations

    def ikpy_ik(T):  # type: ignore[no-untyped-def]
        kw = {"target_orientation": T[:3, :3], "orientation_mode": "all"} if pose else {}
        full = chain.inverse_kinematics(T[:3, 3], initial_position=[0.0, *q0, 0.0], **kw)
        return full[1 : 1 + dof], None

    out = {"fk_error": fk_error, "fk": _peer_fk(spec, ets, chain, checks)}
    for name, fn in (
        ("rtb C++ ETS.ik_LM", rtb_cpp),
        ("rtb Python ETS.ikine_LM", rtb_py),
        ("ikpy", ikpy_ik),
    ):
        out[name] = _time_solver(fn, targets, dof, spec["repeats"])
    Path(out_path).write_text(json.dumps(out))


# ---------------------------------------------------------------- the driver (armkit's venv)


def ensure_peers_venv() -> Path:
    """The peers' interpreter; creates the venv and installs the peers on first use."""
    python = PEERS_VENV / "bin" / "python"
    if not python.exists():
        print(f"creating {PEERS_VENV} (roboticstoolbox-python, ikpy) ...", file=sys.stderr)
        subprocess.run([sys.executable, "-m", "venv", str(PEERS_VENV)], check=True)
        pip = [str(python), "-m", "pip", "install", "-q", "roboticstoolbox-python", "ikpy", "pin"]
        subprocess.run(pip, check=True)
    return python


def import_seconds(python: Path | str, module: str, repeats: int = 3) -> float:
    """Best-of-``repeats`` wall time of ``import module`` in a fresh interpreter [s]."""
    code = f"import time; t = time.perf_counter(); import {module}; print(time.perf_counter() - t)"
    runs = [
        float(
            subprocess.run(
                [str(python), "-c", code], capture_output=True, text=True, check=True
            ).stdout
        )
        for _ in range(repeats)
    ]
    return min(runs)


def _spec(model, targets, task: str, repeats: int) -> dict:  # type: ignore[no-untyped-def]
    from armkit.interchange import urdf_of
    from armkit.kinematics import fk, joint_frames

    check_q = targets.q[:5]
    frames = None
    if model.convention == "frames":
        joints, tool = joint_frames(model)
        frames = [(j.origin.tolist(), float(j.axis[2])) for j in joints]
    return {
        "modified": model.convention == "modified",
        "rows": [
            {"a": r.a, "alpha": r.alpha, "d": r.d, "offset": r.theta_offset, "sign": r.sign}
            for r in model.dh
        ]
        if frames is None
        else [],
        "limits": [[j.lower, j.upper] for j in model.joints],
        "tool": (model.T_flange_tool if frames is None else tool).tolist(),
        "frames": frames,
        "q0": model.home.tolist(),
        "task": task,
        "repeats": repeats,
        "targets": targets.T.tolist(),
        "check_q": check_q.tolist(),
        "checks": fk(model, check_q).tolist(),
        "fk_q": targets.q[:300].tolist(),
        "urdf": urdf_of(model),
    }


def _armkit_runs(model, targets, repeats: int) -> dict:  # type: ignore[no-untyped-def]
    """armkit's rows: {name: (q (N, dof), seconds (N,), iterations (N,))}."""
    from armkit.cli._compare_methods import _one_call, applicable_methods
    from armkit.kinematics import ik_batch

    runs = {}
    for method in ("analytic", "lm"):
        if method not in applicable_methods(model, targets.task):
            continue
        call = _one_call(model, targets, method)
        runs[f"armkit {method}"] = _time_calls(call, len(targets.q), model.dof, repeats)
    R = targets.T[:, :3, :3] if targets.task == "pose" else None
    P = targets.T[:, :3, 3]
    ik_batch(
        model,
        P[:WARMUP],
        None,
        model.home,
        orientations=None if R is None else R[:WARMUP],
        method="lm",
    )
    per = math.inf
    for _ in range(repeats):  # CPU time: a batch runs for milliseconds and is preempted on
        t0 = time.process_time()  # a loaded machine (one thread: CPU = wall when quiet)
        out = ik_batch(model, P, None, model.home, orientations=R, method="lm")
        per = min(per, (time.process_time() - t0) / len(P))
    runs["armkit lm batch (per target, CPU)"] = (
        out.q,
        np.full(len(P), per),
        np.full(len(P), np.nan),
    )
    return runs


def _time_calls(call, n: int, dof: int, repeats: int) -> tuple:  # type: ignore[no-untyped-def]
    from armkit import UnreachableError

    for i in range(WARMUP):
        with contextlib.suppress(UnreachableError):
            call(i)
    q, secs, its = np.full((n, dof), np.nan), np.empty(n), np.full(n, np.nan)
    for i in range(n):
        secs[i] = math.inf
        for _ in range(repeats):
            t0 = time.perf_counter()
            try:
                res = call(i)
                q[i], its[i] = res.q, res.iterations
            except UnreachableError:
                pass
            secs[i] = min(secs[i], time.perf_counter() - t0)
    return q, secs, its


def _row(model, targets, name: str, q, secs, its, import_s: float, rows=None) -> list[str]:  # type: ignore[no-untyped-def]
    """One solver's figures, over the targets ``rows`` (default all)."""
    from armkit.cli._compare_methods import Targets, verified
    from armkit.kinematics import fk

    rows = slice(None) if rows is None else rows
    q, secs = np.asarray(q, dtype=float)[rows], np.asarray(secs, dtype=float)[rows]
    its, targets = (
        np.asarray(its, dtype=float)[rows],
        Targets(targets.q[rows], targets.T[rows], targets.task),
    )
    ok = verified(model, targets, q)
    answered = np.all(np.isfinite(q), axis=1)
    err = np.linalg.norm(
        fk(model, np.where(answered[:, None], q, model.home))[:, :3, 3] - targets.T[:, :3, 3],
        axis=1,
    )
    one = "batch" not in name
    us = secs * 1e6
    return [
        name,
        f"{100 * ok.mean():.1f}",
        f"{np.median(us):.1f}",
        f"{us.mean():.1f}" if one else "-",
        f"{np.percentile(us, 95):.1f}" if one else "-",
        f"{np.percentile(us, 99):.1f}" if one else "-",
        f"{us.max():.1f}" if one else "-",
        f"{np.nanmedian(its):.0f}" if np.isfinite(its).any() else "-",
        f"{np.median(err[answered]) * 1000:.2g}" if answered.any() else "-",
        f"{import_s:.2f}",
    ]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=1000, help="targets per arm (default 1000)")
    parser.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    parser.add_argument(
        "--repeats",
        type=int,
        default=3,
        help="time each call R times, keep the fastest (default 3)",
    )
    parser.add_argument("--arms", nargs="+", default=list(ARM_TASKS), choices=list(ARM_TASKS))
    args = parser.parse_args()
    sys.path.insert(0, str(HERE.parent / "src"))
    from armkit.model import load_model, shipped_models

    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")
    python = ensure_peers_venv()
    imports = {
        "armkit": import_seconds(sys.executable, "armkit.kinematics"),
        "rtb": import_seconds(python, "roboticstoolbox"),
        "ikpy": import_seconds(python, "ikpy.chain"),
    }
    print(
        f"python {sys.version.split()[0]}, n = {args.n}, seed = {args.seed}, fastest of {args.repeats}, from the home pose"
    )
    with tempfile.TemporaryDirectory() as tmp:
        for arm in args.arms:
            model = load_model(arm) if arm in shipped_models() else extra_model(arm, Path(tmp))
            print(_arm_table(python, model, args.n, args.seed, args.repeats, imports))
    return 0


def _arm_table(python: Path, model, n: int, seed: int, repeats: int, imports: dict) -> str:  # type: ignore[no-untyped-def]
    """The table of one arm: armkit's rows, then the peers', all verified by armkit's FK."""
    from armkit.cli._compare_methods import reachable_targets
    from armkit.cli._table import table

    targets = reachable_targets(model, n, seed, ARM_TASKS[model.name])
    runs = _armkit_runs(model, targets, repeats)
    peers, fk_error = _run_peers(python, model, targets, repeats)
    fk_times = peers.pop("fk")
    for name, res in peers.items():
        runs[name] = (res["q"], res["seconds"], res["iterations"])
    rows = []
    for part, subset in _parts(model, targets):
        for name, run in runs.items():
            lib = (
                "armkit"
                if name.startswith("armkit")
                else ("ikpy" if name.startswith("ikpy") else "rtb")
            )
            label = name if part == "" else f"{name}, {part}"
            rows.append(_row(model, targets, label, *run, imports[lib], subset))
    headers = ["solver", "success %", "median us", "mean us", "p95 us", "p99 us", "max us"]
    headers += ["median iter", "median err mm", "import s"]
    title = (
        f"\n{model.name} ({model.dof} joints), task {targets.task}; peers' FK vs armkit's: "
        f"rtb {fk_error['rtb']:.1e} m, ikpy {fk_error['ikpy']:.1e} m"
    )
    return title + "\n" + table(headers, rows) + "\n" + _fk_table(model, targets, fk_times, repeats)


def _parts(model, targets) -> list[tuple[str, object]]:  # type: ignore[no-untyped-def]
    """All targets; on a position-only closed-form arm also its normal and boundary targets
    (where a joint limit refuses the pitch the solver chooses first, issue 29.3)."""
    from armkit.kinematics._chain import chain_of

    chain = chain_of(model)
    if targets.task != "position" or chain.free is None:
        return [("", None)]
    edge = np.array([chain.free(*p, chain.home) == [] for p in targets.T[:, :3, 3].tolist()])
    share = f"{100 * edge.mean():.1f} %"
    return [("", None), ("normal targets", ~edge), (f"boundary targets ({share})", edge)]


def _fk_table(model, targets, peers: dict, repeats: int) -> str:  # type: ignore[no-untyped-def]
    """Single-pose FK per call, armkit beside the peers (issue 29.4: <= 6 us)."""
    from armkit.cli._table import table
    from armkit.kinematics import fk

    qs = targets.q[:300]
    secs = []
    for q in qs:
        best = math.inf
        for _ in range(5):
            t0 = time.perf_counter()
            fk(model, q)
            best = min(best, time.perf_counter() - t0)
        secs.append(best)
    rows = []
    for name, s, err in [("armkit fk", secs, 0.0)] + [
        (k, v["seconds"], v["error"]) for k, v in peers.items()
    ]:
        us = np.asarray(s) * 1e6
        figures = (np.median(us), us.mean(), np.percentile(us, 99), us.max())
        rows.append([name, *(f"{v:.2f}" for v in figures), f"{err:.1e}"])
    return table(["single FK", "median us", "mean us", "p99 us", "max us", "vs armkit m"], rows)


def _run_peers(python: Path, model, targets, repeats: int) -> tuple[dict, dict]:  # type: ignore[no-untyped-def]
    with tempfile.TemporaryDirectory() as tmp:
        spec, out = Path(tmp) / "spec.json", Path(tmp) / "out.json"
        spec.write_text(json.dumps(_spec(model, targets, targets.task, repeats)))
        subprocess.run([str(python), __file__, "--worker", str(spec), str(out)], check=True)
        result = json.loads(out.read_text())
    fk_error = result.pop("fk_error")
    return result, fk_error


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "--worker":
        worker(sys.argv[2], sys.argv[3])
    else:
        sys.exit(main())
