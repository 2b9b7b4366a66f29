"""Where a plan begins when no arm is open: a model and its joint angles."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from .._inputs import joints, shown
from ..model import ArmModel

F64 = NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class Start:
    """An arm that is only planned for (``armkit check`` plans a script's tasks so).

    A task given a ``Start`` instead of an ``Arm`` plans from ``q`` with the scene as
    given and returns the plan; nothing runs, as with ``dry_run=True``.

    Attributes:
        model: the arm's model.
        q: its joint angles at the start [rad], shape (dof,).
    """

    model: ArmModel
    q: F64

    def __post_init__(self) -> None:
        if not isinstance(self.model, ArmModel):
            raise InputError(
                f"Start needs an ArmModel (armkit.load_model), got {shown(self.model)}"
            )
        q = joints(self.q, self.model.dof, "q", batch=False).copy()
        object.__setattr__(self, "q", q)
