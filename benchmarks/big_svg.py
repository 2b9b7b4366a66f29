"""Big SVG drawings for the planning-time benchmark: N strokes of hatching and curls.

    .venv/bin/python benchmarks/big_svg.py N OUT.svg [--seed 0]

N strokes on a 120 x 170 mm page (the shipped A5 sheet at real size): a quarter
are short straight hatch lines, a quarter short polylines (random walks of 3-6
points), a quarter small arcs (cubic Béziers), a quarter small closed squares;
one stroke in ten starts where the previous one ended (``linemerge`` joins them).
Made with numpy (fixed seed), so every run plans the same file.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

W_MM, H_MM = 120.0, 170.0


def big_svg(n: int, seed: int = 0) -> str:
    """The SVG text of ``n`` strokes (units: mm)."""
    rng = np.random.default_rng(seed)
    paths: list[str] = []
    tail = None
    for k in range(n):
        size = rng.uniform(0.8, 4.0)
        if tail is not None and rng.random() < 0.1:
            x, y = tail
        else:
            x, y = rng.uniform(5, W_MM - 5), rng.uniform(5, H_MM - 5)
        kind = k % 4
        if kind == 0:
            a = rng.uniform(0, np.pi)
            pts = np.array([[x, y], [x + size * np.cos(a), y + size * np.sin(a)]])
            d = _poly(pts)
        elif kind == 1:
            steps = rng.normal(0.0, size / 2, size=(int(rng.integers(2, 6)), 2))
            pts = np.vstack([[x, y], np.array([x, y]) + np.cumsum(steps, axis=0)])
            d = _poly(pts)
        elif kind == 2:
            c = rng.uniform(-size, size, size=(3, 2)) + np.array([x, y])
            pts = np.vstack([[x, y], c])
            d = f"M {x:.3f} {y:.3f} C " + " ".join(f"{p[0]:.3f} {p[1]:.3f}" for p in c)
        else:
            pts = np.array([[x, y], [x + size, y], [x + size, y + size], [x, y + size]])
            d = _poly(pts) + " Z"
        tail = tuple(np.clip(pts[-1] if kind != 3 else pts[0], 1, [W_MM - 1, H_MM - 1]))
        paths.append(f'<path d="{d}"/>')
    head = (
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{W_MM:g}mm" height="{H_MM:g}mm" '
        f'viewBox="0 0 {W_MM:g} {H_MM:g}">\n<g fill="none" stroke="black" stroke-width="0.2">\n'
    )
    return head + "\n".join(paths) + "\n</g>\n</svg>\n"


def _poly(pts: np.ndarray) -> str:  # type: ignore[type-arg]
    pts = np.clip(pts, 1, [W_MM - 1, H_MM - 1])
    return "M " + " L ".join(f"{p[0]:.3f} {p[1]:.3f}" for p in pts)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("n", type=int)
    ap.add_argument("out")
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    Path(args.out).write_text(big_svg(args.n, args.seed))


if __name__ == "__main__":
    main()
