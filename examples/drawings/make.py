"""Makes the example drawings in this folder (run once; the files are committed).

    .venv/bin/python examples/drawings/make.py

- lines.svg: a line drawing (house, fence, tree, sun, hills, birds) from the
  basic shapes, paths with arcs and Béziers, and transforms; the roof hatching
  and fence are written the way hatch fills are exported, every line left to right.
- text.svg: text outlined as paths, the glyphs of DejaVu Sans (the font
  matplotlib ships; DejaVu's licence lets its glyph outlines be embedded),
  taken with matplotlib's TextPath.
- curve.svg: a dense curve, one hypotrochoid of 2400 cubic Béziers, ringed by
  flow-field streamlines (made with numpy, seed 13).
- seed001.gcode: seed 001's drawing task, three lines and a circle, pen by Z.

All made for armkit and released with it (MIT).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
WIDTH_MM = 120.0  # every drawing's real width: it fits the shipped A5 sheet at real size
HEAD = '<svg xmlns="http://www.w3.org/2000/svg" width="{sw}mm" height="{sh}mm" viewBox="0 0 {w} {h}">\n'


def _head(w: float, h: float) -> str:
    """The root element: a viewBox of w x h units drawn WIDTH_MM wide."""
    return HEAD.format(sw=_f(WIDTH_MM), sh=_f(WIDTH_MM * h / w), w=w, h=h)


def _f(v: float) -> str:
    return f"{v:.3f}".rstrip("0").rstrip(".")


def lines_svg() -> str:
    out = [_head(180, 130), '<g fill="none" stroke="black" stroke-width="0.3">\n']
    out.append('<path d="M 0 105 C 30 95 50 100 80 104 S 140 96 180 102"/>\n')  # ground
    out.append('<path d="M 0 70 Q 40 40 90 72 T 180 60"/>\n')  # hills
    out.append('<g transform="translate(20 52)">\n')  # house
    out.append('<rect x="0" y="0" width="60" height="50"/>\n')
    out.append('<polygon points="-5,0 30,-28 65,0"/>\n')
    out.append('<rect x="24" y="22" width="12" height="28" rx="1.5"/>\n')
    for x in (6, 42):
        out.append(f'<rect x="{x}" y="10" width="12" height="12"/>\n')
        out.append(f'<line x1="{x + 6}" y1="10" x2="{x + 6}" y2="22"/>\n')
        out.append(f'<line x1="{x}" y1="16" x2="{x + 12}" y2="16"/>\n')
    for k in range(1, 14):  # roof hatching, each line left to right
        y = -28 + 2 * k
        half = 35 * (y + 28) / 28
        out.append(
            f'<line x1="{_f(30 - half + 0.5)}" y1="{y}" x2="{_f(30 + half - 0.5)}" y2="{y}"/>\n'
        )
    out.append("</g>\n")
    out.append('<g transform="translate(95 80)">\n')  # fence: pickets drawn bottom to top
    for k in range(16):
        out.append(
            f'<polyline points="{4 * k},22 {4 * k},4 {4 * k + 1},2 {4 * k + 2},4 {4 * k + 2},22"/>\n'
        )
    out.append(
        '<line x1="-2" y1="9" x2="64" y2="9"/><line x1="-2" y1="17" x2="64" y2="17"/>\n</g>\n'
    )
    out.append('<g transform="translate(150 30)">\n<circle r="9"/>\n')  # sun and rays
    for k in range(12):
        out.append(f'<line x1="12" y1="0" x2="18" y2="0" transform="rotate({30 * k})"/>\n')
    out.append("</g>\n")
    out.append('<rect x="128" y="60" width="5" height="30"/>\n')  # tree
    out.append('<ellipse cx="130.5" cy="48" rx="14" ry="16"/>\n')
    out.append('<path d="M 122 44 a 6 6 0 0 1 8 -6 M 131 52 a 5 5 0 0 0 7 -5"/>\n')
    for x, y in ((40, 15), (55, 10), (100, 20)):  # birds
        out.append(f'<path d="M {x} {y} q 3 -3 6 0 q 3 -3 6 0"/>\n')
    out.append("</g>\n</svg>\n")
    return "".join(out)


def text_svg() -> str:
    from matplotlib.font_manager import FontProperties
    from matplotlib.path import Path as MPath
    from matplotlib.textpath import TextPath

    out = [_head(190, 100), '<g fill="none" stroke="black" stroke-width="0.3">\n']
    font = FontProperties(family="DejaVu Sans")
    for k, (words, size) in enumerate((("armkit draws", 20.0), ("pen on paper 0123", 16.0))):
        tp = TextPath((0, 0), words, size=size, prop=font)
        d, i = [], 0
        verts, codes = tp.vertices, tp.codes
        while i < len(codes):
            c = codes[i]
            n = {MPath.MOVETO: 1, MPath.LINETO: 1, MPath.CURVE3: 2, MPath.CURVE4: 3}.get(c, 1)
            letter = {MPath.MOVETO: "M", MPath.LINETO: "L", MPath.CURVE3: "Q", MPath.CURVE4: "C"}
            if c == MPath.CLOSEPOLY:
                d.append("Z")
            else:
                pts = " ".join(f"{_f(x + 10)} {_f(40 + 40 * k - y)}" for x, y in verts[i : i + n])
                d.append(f"{letter[c]} {pts}")
            i += n
        out.append(f'<path d="{" ".join(d)}"/>\n')
    out.append("</g>\n</svg>\n")
    return "".join(out)


def _cubic_path(p: np.ndarray) -> str:
    """Catmull-Rom through the points p (N, 2) as cubic Béziers."""
    d = [f"M {_f(p[0, 0])} {_f(p[0, 1])}"]
    q = np.vstack([p[:1], p, p[-1:]])
    for i in range(1, len(q) - 2):
        c1 = q[i] + (q[i + 1] - q[i - 1]) / 6
        c2 = q[i + 1] - (q[i + 2] - q[i]) / 6
        d.append("C " + " ".join(f"{_f(v)}" for v in (*c1, *c2, *q[i + 1])))
    return " ".join(d)


def curve_svg() -> str:
    out = [_head(180, 180), '<g fill="none" stroke="black" stroke-width="0.2">\n']
    R, r, dist = 50.0, 19.0, 34.0  # hypotrochoid: closes after r / gcd(R, r) = 19 turns
    t = np.linspace(0, 2 * math.pi * 19, 2401)
    x = (R - r) * np.cos(t) + dist * np.cos((R - r) / r * t)
    y = (R - r) * np.sin(t) - dist * np.sin((R - r) / r * t)
    out.append(f'<path d="{_cubic_path(np.column_stack([x + 90, y + 90]))}"/>\n')
    rng = np.random.default_rng(13)
    for _ in range(700):  # streamlines of a swirl field outside the curve
        p = rng.uniform(0, 180, 2)
        if np.hypot(*(p - 90)) < 70:
            continue
        pts = [p]
        for _ in range(40):
            v = pts[-1] - 90
            a = math.atan2(v[1], v[0]) + math.pi / 2 + 0.3 * math.sin(v[0] / 15)
            nxt = pts[-1] + 1.5 * np.array([math.cos(a), math.sin(a)])
            if not (np.all(nxt > 2) and np.all(nxt < 178)) or np.hypot(*(nxt - 90)) < 68:
                break
            pts.append(nxt)
        if len(pts) > 4:
            out.append(f'<path d="{_cubic_path(np.array(pts[::2]))}"/>\n')
    out.append("</g>\n</svg>\n")
    return "".join(out)


GCODE = """\
; seed 001's drawing task: three straight lines and a circle (pen by Z)
; units mm, absolute; the pen is down at Z <= 0
G21 G90 G17
G0 Z5 (pen up)
G0 X10 Y10
G1 Z0 F300 (pen down)
G1 X70 Y10 F1200 ; horizontal
G0 Z5
G0 X10 Y20
G1 Z0
G1 X10 Y80 ; vertical
G0 Z5
G0 X20 Y20
G1 Z0
G1 X70 Y70 ; diagonal
G0 Z5
G0 X120 Y50
G1 Z0
G2 X120 Y50 I-25 J0 ; circle of radius 25 mm around (95, 50), clockwise
G0 Z5
G4 P0.5 (let the ink settle)
G28 (home)
M2
"""


def main() -> None:
    for name, text in (
        ("lines.svg", lines_svg()),
        ("text.svg", text_svg()),
        ("curve.svg", curve_svg()),
        ("seed001.gcode", GCODE),
    ):
        (HERE / name).write_text(text)
        print(f"wrote {HERE / name} ({len(text)} bytes)")


if __name__ == "__main__":
    main()
