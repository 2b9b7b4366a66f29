"""Teach from the page: joint sliders, a draggable target, and named poses.

The sliders and the target move an ``Arm`` in this process through a
``Mover`` (latest goal wins, real-time pace). Dragging the target checks it
first (``check_target``): the arm follows only when it is reachable and clear;
otherwise the marker turns red with the reason and the arm stays. "Record"
keeps the current pose under a name (``Teach.poses``) and prints it, and
``Teach.script()`` gives the recorded poses and the moves made between them as
a script ``armkit run`` replays (``armkit view --write FILE.arm``). Where the
driver can switch the torque off (Dynamixel), "torque off" lets the arm be moved
by hand; on the simulator the joint sliders are then that hand (``SimArm.push``).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._errors import ArmkitError, InputError
from ...arm import Arm, Position
from ...kinematics import fk
from ...script import Teaching, joints_line
from .._mover import Goal, Mover
from ._view import View

NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_-]{0,63}$")


@dataclass(frozen=True)
class TaughtPose:
    """A pose recorded from the page: joint ``angles`` [deg] by joint name, the
    gripper ``position`` [mm, deg] and its opening ``grip`` [mm]."""

    name: str
    angles: dict[str, float]
    position: Position
    grip: float

    def line(self) -> str:
        """One line for people: name, angles [deg], where the gripper is [mm]."""
        angles = " ".join(f"{k} {v:.1f}" for k, v in self.angles.items())
        x, y, z, pitch = self.position
        return (
            f"{self.name}: {angles} deg; gripper ({x:.1f}, {y:.1f}, {z:.1f}) mm, "
            f"pitch {pitch:.1f} deg, open {self.grip:.1f} mm"
        )


class Teach:
    """The teach panel of ``view``, moving ``arm`` (see the module doc).

    Attributes:
        poses: recorded poses by name, in the order recorded.
        status: the last message shown on the page (a refusal or a recording).
        teaching: the script lines so far (``joints``/``grip`` moves, ``pose`` lines).
    """

    def __init__(self, view: View, arm: Arm, *, echo: bool = True) -> None:
        self.view = view
        self.arm = arm
        self.echo = echo
        self.poses: dict[str, TaughtPose] = {}
        self.status = ""
        self.limp = False  # torque off: the sliders push the simulated arm by hand
        start = view.source.state()
        self.teaching = Teaching(arm.model.name, start.q.copy(), origin="the armkit 3D view")
        self._written = (joints_line(start.q), round(start.grip * 1000.0, 1))
        self._following_target = False
        self.mover = Mover(arm, on_error=self._refused)
        gui = view.server.gui
        self._status = gui.add_markdown("Drag the target or a slider to move the arm.")
        self._sliders = self._add_sliders()
        self._grip = self._add_grip()
        self._pitch, self._any_pitch = self._add_target_options()
        self._gizmo = self._add_gizmo()
        self._add_limp_box()
        self._name = gui.add_text("pose name", "pose_1")
        gui.add_button("Record pose").on_click(lambda _: self._record_clicked())
        gui.add_button("Home").on_click(lambda _: self.move_joints(arm.model.home))
        view.on_update(self._sync)

    def record(self, name: str) -> TaughtPose:
        """Keep the arm's pose now under ``name`` (letters, digits, _ and -)."""
        if not NAME.match(name):
            raise InputError(
                f"pose name {name!r}: use letters, digits, _ and -, starting with a letter"
            )
        state = self.view.source.state()
        angles = {
            n: float(math.degrees(a))
            for n, a in zip(self.arm.model.joint_names, state.q, strict=True)
        }
        pose = TaughtPose(name, angles, self.arm.position(), state.grip * 1000.0)
        self.poses[name] = pose
        self._moves()
        self.teaching.save(name, np.clip(state.q, self.arm.model.lower, self.arm.model.upper))
        self._say(f"recorded {pose.line()}")
        self._name.value = f"pose_{len(self.poses) + 1}"  # type: ignore[misc]
        return pose

    def set_limp(self, on: bool) -> bool:
        """Torque off (``on``) or on again where the arm is; False if the driver refused."""
        if on == self.limp:
            return True
        self.mover.wait_idle()
        try:
            self.arm.relax() if on else self.arm.stiffen()
        except ArmkitError as exc:
            self._say(f"torque: {exc}")
            return False
        self.limp = on
        self._say("torque off: move the arm by hand" if on else "torque on: the arm holds")
        return True

    def push_joints(self, q: Any) -> bool:
        """While limp, a hand puts the simulated arm at ``q`` [rad], shape (dof,) (on a
        real arm the person moves it and the sliders follow); False with the reason."""
        world = self.arm.world
        if not self.limp or world is None:
            self._say("the torque is on: it moves by the sliders" if not self.limp
                      else "torque off: move the arm itself")  # fmt: skip
            return False
        try:
            world.arm().push(np.asarray(q, dtype=np.float64))
        except ValueError as exc:
            self._say(f"refused: {exc}")
            return False
        return True

    def script(self) -> str:
        """The recorded poses and the moves made, as a script ``armkit run`` replays (the
        arm's start pose first, its pose now last)."""
        self._moves()
        return self.teaching.script()

    def _moves(self) -> None:
        """Add the move to where the arm is now (a ``joints`` line, a ``grip`` line) if it
        moved since the last line written."""
        state, model = self.view.source.state(), self.arm.model
        joints = joints_line(np.clip(state.q, model.lower, model.upper))
        width = round(state.grip * 1000.0, 1)
        if joints != self._written[0]:
            self.teaching.lines.append(joints)
        if width != self._written[1] and model.gripper.width_max > model.gripper.width_min:
            self.teaching.lines.append(f"grip {width:.1f}")
        self._written = (joints, width)

    def _record_clicked(self) -> None:
        try:
            self.record(self._name.value)
        except ValueError as exc:
            self._say(str(exc))

    def drag_target(self, position: Any, pitch_deg: float | None = None) -> bool:
        """Put the target at ``position`` [m], shape (3,), pitch [deg] (None: any); the
        arm follows when it can (True), else the marker says why not (False)."""
        pitch = None if pitch_deg is None else math.radians(pitch_deg)
        if self.limp:
            self._say("torque off: move the arm by hand, or switch the torque on")
            return False
        check = self.view.set_target(position, pitch)
        self._following_target = True
        self._gizmo.position = check.position
        if check.q is None:
            self._say(f"target: {check.reason}")
            return False
        self.mover.request(Goal(q=check.q))
        return True

    def move_joints(self, q: Any) -> None:
        """Move the arm to joint angles ``q`` [rad], shape (dof,), as the sliders do."""
        if self.limp:
            self._say("torque off: switch the torque on to move the arm from the page")
            return
        self._following_target = False
        self.mover.request(Goal(q=np.asarray(q, dtype=np.float64), speed=1.0))

    def close(self) -> None:
        """Stop moving the arm."""
        self.mover.close()

    def _add_limp_box(self) -> None:
        """ "torque off (move by hand)", where the driver can (``relax``/``stiffen``)."""
        if not self.arm.can_go_limp:
            return
        box = self.view.server.gui.add_checkbox("torque off (move by hand)", False)

        def clicked(_: Any) -> None:
            if not self.set_limp(bool(box.value)):
                box.value = self.limp  # type: ignore[misc]

        box.on_update(clicked)

    def _add_sliders(self) -> list[Any]:
        gui, model = self.view.server.gui, self.arm.model
        q = np.degrees(self.arm.read())
        sliders = []
        with gui.add_folder("Joints [deg]"):
            for i, joint in enumerate(model.joints):
                lo, hi = math.degrees(joint.lower), math.degrees(joint.upper)
                s = gui.add_slider(joint.name, lo, hi, 0.5, float(np.clip(q[i], lo, hi)))
                s.on_update(self._joint_moved)
                sliders.append(s)
        return sliders

    def _add_grip(self) -> Any:
        g = self.arm.model.gripper
        if not g.present:
            return None
        lo, hi = g.width_min * 1000.0, g.width_max * 1000.0
        slider = self.view.server.gui.add_slider("gripper [mm]", lo, hi, 0.5, hi)
        slider.on_update(self._grip_moved)
        return slider

    def _add_target_options(self) -> tuple[Any, Any]:
        gui = self.view.server.gui
        default = self.arm.model.default_pitch
        pitch = gui.add_slider(
            "target pitch [deg]", -90.0, 90.0, 1.0, math.degrees(default or -math.pi / 2)
        )
        any_pitch = gui.add_checkbox("any pitch", default is None)
        return pitch, any_pitch

    def _add_gizmo(self) -> Any:
        tip = self.arm.position()
        gizmo = self.view.server.scene.add_transform_controls(
            "/target/gizmo",
            scale=0.08,
            disable_rotations=True,
            position=(tip.x / 1000.0, tip.y / 1000.0, tip.z / 1000.0),
        )
        gizmo.on_update(lambda event: self._gizmo_moved(event.target.position))
        return gizmo

    def _gizmo_moved(self, position: Any) -> None:
        pitch = None if self._any_pitch.value else float(self._pitch.value)
        self.drag_target(np.asarray(position, dtype=np.float64), pitch)

    def _joint_moved(self, event: Any) -> None:
        if event.client is None:  # set by _sync, not by a person
            return
        self._following_target = False
        q = np.radians([float(s.value) for s in self._sliders])
        if self.limp:
            self.push_joints(q)
        else:
            self.mover.request(Goal(q=q))

    def _grip_moved(self, event: Any) -> None:
        if event.client is not None and not self.limp:
            self.mover.request(Goal(grip=float(self._grip.value) / 1000.0))

    def _sync(self) -> None:
        """While nothing is being moved from the page, the sliders follow the arm, and
        so does the target handle unless a target was placed."""
        state = self.view.state
        if state is None or not self.mover.idle:
            return
        for slider, angle in zip(self._sliders, np.degrees(state.q), strict=True):
            slider.value = round(float(angle), 1)
        if not self._following_target:
            self._gizmo.position = fk(self.arm.model, state.q)[:3, 3]

    def _refused(self, reason: str) -> None:
        self._say(f"refused: {reason}")

    def _say(self, text: str) -> None:
        self.status = text
        self._status.content = text
        if self.echo:
            print(f"armkit view: {text}", flush=True)
