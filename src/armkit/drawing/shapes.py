"""Shapes in a sheet's coordinates u, v [m] (line, arc, circle, rectangle,
polyline) and ``figure(*paths)`` to plan them; see ``_shapes``."""

from ._shapes import arc as arc
from ._shapes import circle as circle
from ._shapes import figure as figure
from ._shapes import line as line
from ._shapes import polyline as polyline
from ._shapes import rectangle as rectangle
