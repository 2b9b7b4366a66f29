"""Where a plan begins: the arm as it will be when the plan runs."""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from .._inputs import joints, shown
from ..connect import forecaster
from ..drivers import Forecaster
from ..model import ArmModel
from ..scene import Held, HeldTool, Scene

F64 = NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class Start:
    """The arm as a plan starts from it (``Arm.start()`` gives the arm as it is now; a
    plan's ``end`` is the Start of the next). Planning from a Start moves nothing.

    Attributes:
        model: the arm's model.
        q: its joint angles [rad], shape (dof,).
        grip: the gripper's opening as last commanded [m], or None: not set yet (the
            model's own grip length).
        held: the cube in the gripper and its pose in the tool frame, or None; every
            move checks it with the links.
        scene: the objects as they will be, at rest (a held cube left out), or None: the
            table alone.
        jaws: the jaws' true opening [m] where known without a command (a simulated
            gripper's), for open jaws passing over cubes; None: ``grip``.
        motor_s: motor-seconds the batteries have given [s] (timed motors slow with it).
        forecaster: how the arm's driver times its moves (``armkit.drivers.Forecaster``);
            None: the model's own driver kind's (``armkit.connect.forecaster``).
        tool: the tool in the gripper (a pen, a mallet), or None: while it is held its
            tip is the tool point every move is planned and checked with.
    """

    model: ArmModel
    q: F64
    grip: float | None = None
    held: Held | None = None
    scene: Scene | None = None
    jaws: float | None = None
    motor_s: float = 0.0
    forecaster: Forecaster | None = None
    tool: HeldTool | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.model, ArmModel):
            raise InputError(
                f"Start needs an ArmModel (armkit.load_model), got {shown(self.model)}"
            )
        q = joints(self.q, self.model.dof, "q", batch=False).copy()
        object.__setattr__(self, "q", q)
        if self.scene is not None and not isinstance(self.scene, Scene):
            raise InputError(f"Start's scene must be a Scene or None, got {shown(self.scene)}")

    @cached_property
    def kin(self) -> ArmModel:
        """The model with the grip point at the commanded opening (scissor grippers), or
        at the held tool's tip."""
        kin = self.model if self.grip is None else self.model.with_grip_width(self.grip)
        return kin if self.tool is None else kin.with_tool_length(self.tool.tool_length)

    @property
    def opening(self) -> float | None:
        """The jaws' opening [m] as best known (``jaws``, else ``grip``), or None."""
        return self.grip if self.jaws is None else self.jaws

    @cached_property
    def timer(self) -> Forecaster:
        """``forecaster``, or the model's own driver kind's."""
        return self.forecaster if self.forecaster is not None else forecaster(self.model)

    def then(self, **changes: Any) -> Start:
        """The same Start with ``changes`` (``q=``, ``grip=``, ...), the forecaster kept."""
        new = replace(self, **changes)
        if self.forecaster is None and "timer" in self.__dict__:
            new.__dict__["timer"] = self.timer  # made once per plan, not per move
        return new
