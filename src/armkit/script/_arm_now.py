"""What the check knows of the arm a script will run on: where it is, what it holds,
where its scene's objects are, and how its motors are timed."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from ..scene import Held, Scene

if TYPE_CHECKING:
    from ..arm import Arm
    from ..drivers.timed import TimingModel

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class ArmNow:
    """The arm at the start of a script, as ``check_source`` checks from it (the default:
    the model's home pose, nothing held, the scene's file, the simulator).

    Attributes:
        q: joint angles [rad], shape (dof,), or None: the model's home.
        grip: gripper opening [m], or None: not set yet (the model's own grip length).
        held: the cube in the gripper: its name (a ``pick`` before, in the shell) or with
            its pose in the gripper (``Arm.held``: moves check it too), or None.
        live: where the script's tasks will find the scene's objects, a function of the
            scene (on a simulated arm: where they are now), or None: as the scene has them.
        hardware: it runs on real hardware (a task's waits differ from the simulator's).
        timing: a timed arm's (the OWI's) timing model, its unit's calibration; None: the
            one a new unit starts with.
        motor_s: the motor-seconds a timed arm's battery has given [s].
    """

    q: F64 | None = None
    grip: float | None = None
    held: str | Held | None = None
    live: Callable[[Scene], Scene] | None = None
    hardware: bool = False
    timing: TimingModel | None = None
    motor_s: float = 0.0

    @classmethod
    def of(cls, arm: Arm, carried: Scene | None = None, grip: float | None = None) -> ArmNow:
        """``arm`` as it is: its joints, the cube it holds, its scene's objects (live on a
        simulated arm, else as the script's tasks left them: ``carried``), real or
        simulated, and a timed arm's own timing; ``grip``: the opening a script set [m]."""
        from ..tasks import objects_now

        def live(scene: Scene) -> Scene:
            return objects_now(arm, scene if carried is None else carried)

        start = arm.start()
        return cls(
            q=start.q,
            grip=grip,
            held=arm.held,
            live=live,
            hardware=arm.world is None,
            timing=getattr(start.timer, "timing", None),  # a timed arm's (TimedDriver)
            motor_s=start.motor_s,
        )
