"""Jobs for an arm on a scene: pick, place, move an item, rotate and stack cubes
(seeds 000 and 001). Each task is planned whole -- every IK and every clearance
check -- before anything moves; ``dry_run=True`` returns the plan only, and a ``Start`` (a
model and its joints) in place of the arm plans without one."""

from ..arm import GRIP_S as GRIP_S
from ..arm import Start as Start
from ._calibration import Calibration as Calibration
from ._calibration import CalibrationError as CalibrationError
from ._calibration import default_calibration_file as default_calibration_file
from ._calibration import load_calibration as load_calibration
from ._jobs import move_item as move_item
from ._jobs import pick as pick
from ._jobs import place as place
from ._jobs import rotate_cube as rotate_cube
from ._jobs import stack as stack
from ._jobs import stack_names as stack_names
from ._live import TaskFailed as TaskFailed
from ._live import attach_scene as attach_scene
from ._live import attached as attached
from ._live import held_now as held_now
from ._live import objects_now as objects_now
from ._live import obstacles_now as obstacles_now
from ._live import run_plan as run_plan
from ._live import run_verified as run_verified
from ._plan import Plan as Plan
from ._plan import Step as Step
from ._plan import TaskError as TaskError
from ._reach import ReachResult as ReachResult
from ._reach import plan_reach as plan_reach
from ._reach import reach as reach
from ._search import SearchResult as SearchResult
from ._search import check_angles as check_angles
from ._search import only_container as only_container
from ._search import plan_search as plan_search
from ._search import search as search
from ._targets import Destination as Destination
from ._targets import resolve as resolve
