"""Plan drawings for a pen: SVG and G-code onto an A5 sheet, strokes ordered to
cut pen-up travel, and a picture of the plan at the sheet's real size.

Each file is read (svgelements for SVG, armkit's own G-code reader), flattened
within 0.1 mm, fitted inside a 10 mm margin, merged where strokes meet,
simplified, and ordered (greedy nearest neighbour, then 2-opt and Or-opt).
The pen starts at the middle of the sheet's near edge, where the arm is.

Needs: the svg and plot extras (pip install 'armkit[svg,plot]'; ``make test`` has them).
Run: .venv/bin/python examples/11_plan_drawing.py   (writes plan_<name>.png here)
"""

from __future__ import annotations

from pathlib import Path

from armkit.drawing import Fit, PaperSize, pen_up_length, plan_drawing, preview, read_drawing

DRAWINGS = Path(__file__).resolve().parent / "drawings"
A5 = PaperSize(0.210, 0.148)  # landscape [m]
START = (0.105, 0.0)  # (u, v) [m]: the pen starts at the middle of the near edge


def main() -> None:
    print(f"{'file':<14} {'strokes':>7} {'pen down':>9} {'pen up, file order':>19} {'planned':>8}")
    for name in ("lines.svg", "text.svg", "curve.svg", "seed001.gcode"):
        figure = read_drawing(DRAWINGS / name)
        fit = Fit.as_is() if name.endswith(".gcode") else Fit.to_sheet(margin=0.010)
        plan = plan_drawing(figure, A5, fit, tolerance=1e-4, start=START)
        # the same strokes in the file's own order, for comparison
        as_listed = [
            s @ plan.transform[:2, :2].T + plan.transform[:2, 2] for s in figure.flatten(1e-4)
        ]
        before = pen_up_length(as_listed, plan.start)
        print(
            f"{name:<14} {plan.pen_lifts:>7} {plan.pen_down_length * 1e3:>6.0f} mm"
            f" {before * 1e3:>16.0f} mm {plan.pen_up_length * 1e3:>5.0f} mm"
        )
        picture = preview(plan, Path(f"plan_{Path(name).stem}.png"), dpi=100)
        print(f"  wrote {picture} ({plan.size[0] * 1e3:.0f} x {plan.size[1] * 1e3:.0f} mm)")


if __name__ == "__main__":
    main()
