"""Motion: joint profiles, Cartesian paths, planning and streaming (SI units).

Everything here works in metres, radians and seconds; ``Arm`` and the CLI convert
from millimetres and degrees.
"""

from .._clock import Clock as Clock
from .._clock import WallClock as WallClock
from .._clock import clock_of as clock_of
from .._polyline import distance_to_polyline as distance_to_polyline
from ._approach import approach as approach
from ._approach import retreat as retreat
from ._chained import batchable as batchable
from ._chained import chained_ik as chained_ik
from ._chained import reachable_at as reachable_at
from ._paths import arc as arc
from ._paths import circle as circle
from ._paths import corners as corners
from ._paths import cube_edges as cube_edges
from ._paths import line as line
from ._paths import polyline as polyline
from ._paths import rectangle as rectangle
from ._plan import JointPath as JointPath
from ._plan import PathError as PathError
from ._plan import deviation as deviation
from ._plan import plan_path as plan_path
from ._profiles import Quintic as Quintic
from ._profiles import Trapezoid as Trapezoid
from ._profiles import quintic as quintic
from ._profiles import trapezoid as trapezoid
from ._profiles import trapezoid_in_line as trapezoid_in_line
from ._stream import EarlyStreaming as EarlyStreaming
from ._stream import NaiveStepping as NaiveStepping
from ._stream import Streamer as Streamer
from ._stream import TimedStreaming as TimedStreaming
from ._stream import follow as follow
from ._stream import forecast_follow as forecast_follow
from ._timing import TimedPath as TimedPath
from ._timing import time_path as time_path
