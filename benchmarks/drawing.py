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
import json
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
    args = parser.parse_args()
    sys.path.insert(0, str(HERE.parent / "src"))
    from armkit.cli._table import table

    files = [str(Path(f).resolve()) for f in args.files]
    if not args.no_vpype:
        vpype_table(files)
    heads = ["arm", "file", "pen", "strokes", "Hausdorff mm", "RMS mm", "pen down mm",
             "pen up mm", "lifts", "simulated s", "wall s"]  # fmt: skip
    print("\nsimulated drawings on the drawing scene's A5 sheet (pen speed 30 mm/s)")
    print(table(heads, sim_rows(files)))
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
    if len(sys.argv) >= 3 and sys.argv[1] == "--worker":
        worker(sys.argv[3:], sys.argv[2])
    else:
        sys.exit(main())
