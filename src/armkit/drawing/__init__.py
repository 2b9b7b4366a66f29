"""Drawing: SVG, G-code and shapes onto a sheet as ordered pen strokes (pure, SI).

Read a source (``read_svg``, ``read_gcode``, ``shapes.figure``), plan it on a
sheet (``plan_drawing``: flatten, fit, cut, merge, simplify, order), and compare
what a pen drew with the plan (``measure``). Sheet coordinates are u, v [m];
``DrawingPlan.world_strokes(sheet)`` puts them on the sheet's plane.

The job on an arm (seed 001's third task): ``draw(arm, scene, file, sheet, pen)``
plans it whole (the pen picked up from its stand, strokes cut to reach, every
move checked), runs it and, on a simulated arm, measures what the pen drew
(``PenTracer``, a World observer).
"""

from . import shapes as shapes
from ._distance import distance_to_strokes as distance_to_strokes
from ._distance import hausdorff as hausdorff
from ._draw import draw as draw
from ._draw import run_job as run_job
from ._errors import DrawingError as DrawingError
from ._errors import DrawingWarning as DrawingWarning
from ._figure import Figure as Figure
from ._fit import Fit as Fit
from ._fit import clip_to_box as clip_to_box
from ._fit import fit_transform as fit_transform
from ._gcode import read_gcode as read_gcode
from ._job import DrawJob as DrawJob
from ._job import DrawOptions as DrawOptions
from ._job import find_pen as find_pen
from ._job import find_sheet as find_sheet
from ._job import plan_draw as plan_draw
from ._job import plan_on_sheet as plan_on_sheet
from ._merge import merge_strokes as merge_strokes
from ._metrics import DrawingMetrics as DrawingMetrics
from ._metrics import PenTrace as PenTrace
from ._metrics import ink as ink
from ._metrics import measure as measure
from ._metrics import sheet_uv as sheet_uv
from ._order import order_strokes as order_strokes
from ._order import pen_up_length as pen_up_length
from ._picture import check_picture_path as check_picture_path
from ._picture import preview as preview
from ._picture import result as result
from ._plan import DrawingPlan as DrawingPlan
from ._plan import PaperSize as PaperSize
from ._plan import SheetLike as SheetLike
from ._plan import SheetPlane as SheetPlane
from ._plan import plan_drawing as plan_drawing
from ._plan import read_drawing as read_drawing
from ._segments import FigurePath as FigurePath
from ._simplify import simplify as simplify
from ._svg import read_svg as read_svg
from ._tracer import PenTracer as PenTracer

__all__ = ["shapes"]
