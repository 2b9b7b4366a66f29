"""What is on the table: boards with sockets, cubes, containers, places, pens,
sheets and instruments (pure data and geometry, SI units inside), loaded from
TOML scene files written in millimetres and degrees; and the clearance check of
the arm's links against them. Every kind of object is one module and one entry of
``OBJECT_KINDS``, and answers one protocol (``SceneObject``: its name, its solids
for the clearance check, its primitives for the views)."""

from ._board import Board as Board
from ._capsules import Capsules as Capsules
from ._capsules import arm_capsules as arm_capsules
from ._capsules import link_names as link_names
from ._clearance import Collision as Collision
from ._clearance import Held as Held
from ._clearance import check_clear as check_clear
from ._clearance import joint_sweep as joint_sweep
from ._clearance import joint_sweeps as joint_sweeps
from ._container import Container as Container
from ._cube import Cube as Cube
from ._cube import Settled as Settled
from ._cube import cube_colour as cube_colour
from ._cube import cube_primitive as cube_primitive
from ._cube import settle as settle
from ._errors import SceneError as SceneError
from ._grasp import MIN_COVER as MIN_COVER
from ._grasp import grasp as grasp
from ._hand import Hand as Hand
from ._instruments import Drum as Drum
from ._instruments import Xylophone as Xylophone
from ._instruments import midi_note as midi_note
from ._instruments import note_name as note_name
from ._instruments import note_number as note_number
from ._kinds import OBJECT_KINDS as OBJECT_KINDS
from ._load import load_scene as load_scene
from ._load import shipped_scenes as shipped_scenes
from ._object import ObjectKind as ObjectKind
from ._object import Placed as Placed
from ._object import SceneObject as SceneObject
from ._object import Solid as Solid
from ._object import Support as Support
from ._object import support_under as support_under
from ._pen import Pen as Pen
from ._pen import PenStand as PenStand
from ._physics import SceneEvent as SceneEvent
from ._physics import ScenePhysics as ScenePhysics
from ._picture import PICTURE_SUFFIXES as PICTURE_SUFFIXES
from ._picture import top_view as top_view
from ._place import Place as Place
from ._rect import Rect as Rect
from ._refusal import is_inside as is_inside
from ._refusal import move_refusal as move_refusal
from ._scene import Scene as Scene
from ._show import describe as describe
from ._state import load_physics as load_physics
from ._state import physics_text as physics_text
from ._state import rest_scene as rest_scene
from ._state import save_physics as save_physics
from ._state import scene_state_file as scene_state_file
from ._surfaces import PAPER_SIZES as PAPER_SIZES
from ._surfaces import Sheet as Sheet
