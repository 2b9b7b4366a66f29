"""The command language: ``.arm`` scripts, checked whole before the arm moves.

A script is a list of lines; ``#`` starts a comment. Numbers take a unit written
right after them or as the next word (``1.5s``, ``20 mm``); a bare number has the
default unit of where it stands: mm for lengths, deg for angles, s for times,
% for speeds. Also accepted: ``cm``, ``m``, ``in``; ``rad``; ``ms``, ``min``;
``mm/s``, ``cm/s``, ``m/s``.

Grammar (one statement per line; ``[]`` optional, ``|`` or, ``...`` repeated)::

    script    := { line }
    line      := [ statement ] [ "#" comment ]
    header    := "arm" NAME | "driver" NAME [ "port" PORT ] | "scene" FILE
                 (before any other statement, each at most once)
    target    := "xyz" X Y Z [ "pitch" P ] | X Y Z [ "pitch" P ]
               | "joints" A1 ... An | POSE | "here"
    statement := header
               | "pose" NAME "=" target
               | "move" target            # joint move to the target
               | "line" target            # straight line, at the tool speed
               | "joints" A1 ... An       # = move joints A1 ... An
               | "turn" JOINT [ "by" ] ANGLE
               | "grip" ( WIDTH | "open" | "close" )
               | "home" | "wait" TIME | "light" ( "on" | "off" )   # TIME: 0..3600 s
               | "speed" PERCENT          # joint moves, % of each joint's max speed
               | "speed" SPEED            # straight lines, e.g. 40 mm/s
               | "run" JOINT DIRECTION TIME   # OWI timed rotation (000's program mode)
               | JOB { ARGUMENT }         # pick, place, move-item, rotate-cube, stack,
                                          # search, draw, play (see armkit.script.JOBS)
               | "repeat" COUNT NEWLINE { statement } "end"     # COUNT: 0..10000
               | "define" NAME [ "(" PARAM { "," PARAM } ")" ] NEWLINE { statement } "end"
               | NAME { NUMBER | NAME }   # call a procedure
    DIRECTION := "forward" | "backward" (shoulder, elbow, wrist) | "left" | "right" (base)

A ``wait`` is at most ``MAX_WAIT_S`` (3600 s, an hour) and a ``repeat`` (or
``--repeat``) at most ``MAX_REPEAT`` (10 000) iterations: more is a slipped unit
or digit (``wait 1e9``), refused by the check; a longer pause is a loop of waits.

A procedure's parameters stand where a number or a pose name is expected
(``define dip(spot, depth)``, ``line xyz 180 0 depth``, ``move spot``).
Procedures are defined at the top level before they are called.

Before the first motion the whole script is checked (``check_source``):
unknown commands and arguments (with "did you mean"), units, undefined names,
repeat/define balance, and every target on the arm's model: reach (``ik``),
joint limits, the table plane (``model.table_z``), straight lines point by point.
Every problem is reported as ``file:line:col: error: message`` with the line and
a caret; nothing moves if there is one. ``run_source`` then runs it through the
public ``Arm`` API; a failure at run time names the line and repeat iteration.
"""

from ._ast import Header as Header
from ._ast import Loc as Loc
from ._ast import Program as Program
from ._ast import Source as Source
from ._ast import Statement as Statement
from ._backend import Frame as Frame
from ._backend import ScriptRunError as ScriptRunError
from ._check import CheckResult as CheckResult
from ._check import Setup as Setup
from ._check import check_file as check_file
from ._check import check_source as check_source
from ._check import load_scene_info as load_scene_info
from ._check import setup_of as setup_of
from ._diagnostics import Diagnostic as Diagnostic
from ._diagnostics import ScriptCheckError as ScriptCheckError
from ._jobs import JOBS as JOBS
from ._jobs import JobParam as JobParam
from ._jobs import JobSpec as JobSpec
from ._parse import parse as parse
from ._resolve import SceneInfo as SceneInfo
from ._run import run_checked as run_checked
from ._run import run_source as run_source
from ._session import Reply as Reply
from ._session import Session as Session
from ._shell import Shell as Shell
from ._teach import Teaching as Teaching
from ._teach import joints_line as joints_line
from ._timetable import Timetable as Timetable
from ._timetable import TimetableRow as TimetableRow
from ._walk import MAX_REPEAT as MAX_REPEAT
from ._walk import MAX_WAIT_S as MAX_WAIT_S
