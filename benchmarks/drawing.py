"""Pen-up travel: armkit's stroke ordering against vpype's ``linemerge linesort``.

    .venv/bin/python benchmarks/drawing.py [--files examples/drawings/*.svg]

The same SVG files, at their real size, through both pipelines, file to
ordered strokes: armkit ``plan_drawing`` (flatten 0.1 mm, merge ends within
0.05 mm, simplify, greedy + 2-opt, closed strokes re-entered where nearest)
and vpype ``read -m FILE linemerge linesort`` (its defaults: quantization 0.1 mm,
merge tolerance 0.05 mm, greedy with flipping), also with ``linesort --two-opt``.
Pen-up travel is measured by the same function on both outputs: the sum of the
moves between consecutive strokes (not from or back to a home position). The
pen-down lengths of both, from two independent SVG flattenings, should agree.
"file order" is the travel of the strokes as the file lists them.

The planning-time table (``--sizes 1000 3000 10000 30000``): big drawings made
by benchmarks/big_svg.py, each planned whole by armkit (``plan_draw`` on the
drawing scene with the OpenManipulator-X: read, merged, ordered, IK of every
point, every stroke and pen-up move checked for clearance) and by vpype
(``read linemerge linesort``), runs interleaved, ``--repeats`` each; wall time
mean, median and max, and both pen-up travels. ``--only-sizes`` prints only it.

The second table draws the same files fitted onto the A5 sheet of the shipped
``drawing`` scene with the simulated OpenManipulator-X and Lynx6 (the pen
picked up from its cradle and put back), and measures what the simulated pen drew
(``armkit.drawing.measure``: tip within 0.5 mm of the paper is ink). Targets:
Hausdorff <= 1 mm, RMS cross-track <= 0.3 mm. ``--no-vpype`` skips the first table.

vpype lives in its own virtual environment, benchmarks/.peers/vpype (created on
first use: python3 -m venv + pip install vpype); it is never a dependency of
armkit. This file is both the driver (armkit's interpreter) and the worker
(vpype's).
"""

from __future__ import annotations

import argparse
import itertools
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
VENV = HERE / ".peers" / "vpype"
FILES = sorted(str(p) for p in (HERE.parent / "examples" / "drawings").glob("*.svg"))
MM_PER_PX = 25.4 / 96.0


def worker(files: list[str], out_path: str) -> None:
    """Run vpype on each file; write its ordered lines [mm] and times [s]."""
    import vpype
    import vpype_cli

    out = {"version": vpype.__version__}
    for f in files:
        res = {}
        for name, pipe in (("greedy", "linesort"), ("two-opt", "linesort --two-opt")):
            t0 = time.perf_counter()
            doc = vpype_cli.execute(f"read -m '{f}' linemerge {pipe}")
            secs = time.perf_counter() - t0
            lines = [
                [[p.real * MM_PER_PX, p.imag * MM_PER_PX] for p in line]
                for layer in doc.layers.values()
                for line in layer
            ]
            res[name] = {"lines": lines, "seconds": secs}
        out[f] = res
    Path(out_path).write_text(json.dumps(out))


def time_worker(path: str, out_path: str) -> None:
    """vpype ``read linemerge linesort`` on one file: its wall time [s] and pen-up [mm]."""
    import vpype_cli

    t0 = time.perf_counter()
    doc = vpype_cli.execute(f"read -m '{path}' linemerge linesort")
    secs = time.perf_counter() - t0
    lines = [np.array([[p.real, p.imag] for p in line]) * MM_PER_PX
             for layer in doc.layers.values() for line in layer]  # fmt: skip
    Path(out_path).write_text(json.dumps({"seconds": secs, "pen_up": _travel(lines)}))


def _travel(lines: list) -> float:  # type: ignore[type-arg]
    """Pen-up travel between consecutive lines (the same measure for both)."""
    return float(sum(np.hypot(*(b[0] - a[-1])) for a, b in itertools.pairwise(lines)))


def ensure_venv() -> Path:
    """vpype's interpreter; creates the venv and installs vpype on first use."""
    python = VENV / "bin" / "python"
    if not python.exists():
        print(f"creating {VENV} (vpype) ...", file=sys.stderr)
        subprocess.run([sys.executable, "-m", "venv", str(VENV)], check=True)
        subprocess.run([str(python), "-m", "pip", "install", "-q", "vpype"], check=True)
    return python


def run_vpype(python: Path, files: list[str]) -> dict:  # type: ignore[type-arg]
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "out.json"
        subprocess.run([str(python), __file__, "--worker", out, *files], check=True)
        return json.loads(out.read_text())  # type: ignore[no-any-return]


def _vpype_time(python: Path, path: Path) -> tuple[float, float]:
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "out.json"
        subprocess.run([str(python), __file__, "--time-worker", out, str(path)], check=True)
        got = json.loads(out.read_text())
        return float(got["seconds"]), float(got["pen_up"])


def _armkit_time(path: Path) -> tuple[float, float, int]:
    """armkit planning ``path`` whole (as ``armkit draw svg --dry-run``): [s], pen-up [mm], strokes."""
    from armkit import Arm
    from armkit.drawing import plan_draw
    from armkit.scene import load_scene
    from armkit.sim import World

    scene = load_scene("drawing")
    with Arm("openmanipulator_x", "sim", world=World()) as arm:
        t0 = time.perf_counter()
        job = plan_draw(arm, scene, path)
        secs = time.perf_counter() - t0
    strokes = [s * 1e3 for s in job.plan.strokes]
    return secs, _travel(strokes), len(strokes)


def scale_table(sizes: list[int], repeats: int) -> None:
    """Planning time and pen-up travel against the number of strokes, vpype beside."""
    from big_svg import big_svg

    from armkit.cli._table import table

    python = ensure_venv()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        warm = Path(tmp) / "warm.svg"
        warm.write_text(big_svg(50))
        _armkit_time(warm)  # imports (svgelements, ...) outside the timing, as vpype's
        for n in sizes:
            f = Path(tmp) / f"big{n}.svg"
            f.write_text(big_svg(n))
            ours, theirs = [], []
            for _ in range(repeats):  # interleaved
                ours.append(_armkit_time(f))
                theirs.append(_vpype_time(python, f))
            a, v = np.array([o[0] for o in ours]), np.array([t[0] for t in theirs])
            up, vup = ours[0][1], theirs[0][1]
            rows.append([n, ours[0][2], f"{a.mean():.2f}", f"{np.median(a):.2f}", f"{a.max():.2f}",
                         f"{v.mean():.2f}", f"{np.median(v):.2f}", f"{v.max():.2f}",
                         f"{np.median(a) / np.median(v):.2f}", f"{up:.0f}", f"{vup:.0f}",
                         f"{up / vup:.2f}"])  # fmt: skip
    print(f"\nplanning a drawing of N strokes (benchmarks/big_svg.py), {repeats} runs each, "
          "interleaved; wall s; pen-up mm; targets: time <= vpype's, pen-up <= 0.85 x vpype's")  # fmt: skip
    heads = ["N", "strokes planned", "armkit mean", "median", "max", "vpype mean", "median",
             "max", "time ratio", "armkit pen-up", "vpype pen-up", "pen-up ratio"]  # fmt: skip
    print(table(heads, rows))
    if len(sizes) > 1:
        med = [float(r[3]) for r in rows]
        k = np.polyfit(np.log(sizes), np.log(med), 1)[0]
        print(f"armkit planning time grows as N^{k:.2f} over N = {sizes[0]}..{sizes[-1]}")


def armkit_row(path: str) -> dict:  # type: ignore[type-arg]
    """armkit's plan at real size: strokes [mm], file-order travel, time [s]."""
    from armkit.drawing import Fit, pen_up_length, plan_drawing, read_svg

    t0 = time.perf_counter()
    fig = read_svg(path)
    plain = fig.flatten(1e-4)
    size = np.ptp(np.vstack(plain), axis=0) + 0.02
    plan = plan_drawing(fig, (float(size[0]), float(size[1])), Fit(scale=1.0, margin=0.0))
    secs = time.perf_counter() - t0
    return {
        "strokes_in": len(plain),
        "file_order": pen_up_length(plain) * 1e3,
        "strokes": [s * 1e3 for s in plan.strokes],
        "seconds": secs,
    }


def sim_rows(files: list[str]) -> list[list[object]]:
    """Each file drawn by each simulated arm on the drawing scene's A5 sheet."""
    from armkit import Arm
    from armkit.drawing import DrawOptions, draw
    from armkit.scene import load_scene
    from armkit.sim import World

    scene = load_scene("drawing")
    rows: list[list[object]] = []
    for arm_name, held in (("openmanipulator_x", False), ("lynx6", False)):
        for f in files:
            t0 = time.perf_counter()
            arm = Arm(arm_name, "sim", world=World())
            job = draw(arm, scene, f, "A5", options=DrawOptions(held=held), fit=True)
            wall = time.perf_counter() - t0
            m = job.metrics
            assert m is not None
            rows.append([arm_name, Path(f).name, "held" if held else "picked up",
                         len(job.plan.strokes), f"{m.hausdorff * 1e3:.2f}",
                         f"{m.rms_cross_track * 1e3:.3f}", f"{m.pen_down_length * 1e3:.0f}",
                         f"{m.pen_up_length * 1e3:.0f}", m.pen_lifts, f"{m.duration:.1f}",
                         f"{wall:.1f}"])  # fmt: skip
    return rows


def _length(strokes: list) -> float:  # type: ignore[type-arg]
    return float(sum(np.linalg.norm(np.diff(s, axis=0), axis=1).sum() for s in strokes))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--files", nargs="+", default=FILES, help="SVG files")
    parser.add_argument("--no-vpype", action="store_true", help="only the simulated drawings")
    parser.add_argument("--sizes", type=int, nargs="*", default=[1000, 3000, 10000, 30000],
                        help="strokes of the planning-time table (none: no table)")  # fmt: skip
    parser.add_argument("--repeats", type=int, default=3, help="runs per size and tool")
    parser.add_argument("--only-sizes", action="store_true", help="only the planning-time table")
    args = parser.parse_args()
    sys.path.insert(0, str(HERE.parent / "src"))
    sys.path.insert(0, str(HERE))
    from armkit.cli._table import table

    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")
    if args.sizes:
        scale_table(args.sizes, args.repeats)
    if args.only_sizes:
        return 0
    files = [str(Path(f).resolve()) for f in args.files]
    if not args.no_vpype:
        vpype_table(files)
    heads = ["arm", "file", "pen", "strokes", "Hausdorff mm", "RMS mm", "pen down mm",
             "pen up mm", "lifts", "simulated s", "wall s"]  # fmt: skip
    print("\nsimulated drawings on the drawing scene's A5 sheet (pen speed 30 mm/s)")
    print(table(heads, sim_rows(files)))
    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")
    return 0


def vpype_table(files: list[str]) -> None:
    """Pen-up travel, armkit against vpype, printed."""
    from armkit.cli._table import table
    from armkit.drawing import pen_up_length

    peers = run_vpype(ensure_venv(), files)
    rows = []
    for f in files:
        ours = armkit_row(f)
        theirs = peers[f]
        up = {k: pen_up_length([np.array(line) for line in v["lines"]]) for k, v in theirs.items()}
        down = _length(ours["strokes"])
        their_down = _length([np.array(line) for line in theirs["greedy"]["lines"]])
        rows.append(
            [
                Path(f).name,
                ours["strokes_in"],
                f"{down:.1f} / {their_down:.1f}",
                f"{ours['file_order']:.1f}",
                f"{len(ours['strokes'])} / {len(theirs['greedy']['lines'])}",
                f"{pen_up_length(ours['strokes']):.1f}",
                f"{up['greedy']:.1f}",
                f"{up['two-opt']:.1f}",
                f"{ours['seconds']:.2f}",
                f"{theirs['greedy']['seconds']:.2f}",
            ]
        )
    print(f"python {sys.version.split()[0]}, vpype {peers['version']}; lengths in mm, times in s")
    headers = [
        "file",
        "strokes in",
        "pen-down armkit / vpype",
        "file order",
        "strokes armkit / vpype",
        "armkit pen-up",
        "vpype linesort",
        "vpype --two-opt",
        "armkit s",
        "vpype s",
    ]
    print(table(headers, rows))


if __name__ == "__main__":
    if len(sys.argv) >= 3 and sys.argv[1] == "--time-worker":
        time_worker(sys.argv[3], sys.argv[2])
    elif len(sys.argv) >= 3 and sys.argv[1] == "--worker":
        worker(sys.argv[3:], sys.argv[2])
    else:
        sys.exit(main())
