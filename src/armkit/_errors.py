"""The one error hierarchy of armkit.

Every error a user can cause is an ``ArmkitError``; the CLI prints its message
on one line and exits non-zero. Messages say what was asked, what is allowed
and what to do.
"""

from __future__ import annotations

from typing import Any, Literal

Reason = Literal[
    "too_far",
    "too_close",
    "joint_limit",
    "off_plane",
    "pitch",
    "no_convergence",
    "table",
    "collision",
    "discontinuous",
    "unreachable",
]
"""Why a target or path cannot be reached (``UnreachableError.reason``):

- ``"too_far"``: beyond the links' reach; ``"too_close"``: inside the links' inner reach.
- ``"joint_limit"``: reachable only with a joint outside its limits (the message names it).
- ``"off_plane"``: outside the plane of a planar arm; ``"pitch"``: not at that pitch.
- ``"no_convergence"``: a numeric solver stopped without meeting its tolerance.
- ``"table"``: the pose or path puts the arm into the table.
- ``"collision"``: the pose or path puts a link (or the held object) into an object of the scene.
- ``"discontinuous"``: a path's joint angles jump between two neighbouring points.
- ``"unreachable"``: none of the above is known (a path planner's fallback).
"""


class ArmkitError(Exception):
    """Base class of every error armkit raises on purpose.

    Attributes:
        details: more than the one line says (each way tried and why it failed),
            one item per line; the CLI prints them with ``--explain``. "" if none.
    """

    details: str = ""


class ArmkitWarning(UserWarning):
    """Base class of armkit's warnings (something left out or uncertain, nothing refused);
    the CLI prints each as one ``armkit: warning: ...`` line on stderr."""


class ModelError(ArmkitError):
    """An arm model file (or a scene file) is missing, malformed or inconsistent.

    Attributes:
        file: the file it is about, if one (None: a model made in code).
        field: the dotted field it is about (``joints[1].limits_deg``), if one.
    """

    def __init__(self, message: str, *, file: str | None = None, field: str | None = None):
        super().__init__(message)
        self.file, self.field = file, field


class UnreachableError(ArmkitError):
    """No joint angles put the tool at the target within the joint limits.

    Attributes:
        reason: why, a ``Reason`` (see there).
        closest: the closest joint vector found [rad], shape (dof,), or None.
    """

    def __init__(
        self, message: str, *, reason: Reason = "unreachable", closest: Any = None
    ) -> None:
        super().__init__(message)
        self.reason: Reason = reason
        self.closest = closest


class NoSolutionError(UnreachableError):
    """A numeric solver stopped without meeting its tolerance."""


class JointLimitError(ArmkitError):
    """A joint angle is outside its limits."""


class DeviceError(ArmkitError):
    """A device is missing, refused access, or answered wrongly."""


class ScriptError(ArmkitError):
    """A command-language script is wrong."""


class NoSuchName(ArmkitError, AttributeError):
    """``armkit.NAME`` (or ``armkit.model.NAME``, ...) for a name the package does not
    have (an AttributeError too, so ``hasattr`` and ``from ... import NAME`` behave as
    Python's)."""


class InputError(ArmkitError, ValueError):
    """A value someone gave (an argument, an option, a parameter) is not allowed:
    not a number, out of its range, or the wrong count. The message names the
    argument, what is allowed and what was given, in the units it was given in.
    Also a ``ValueError``, so code that catches that keeps working."""


class ReplyError(DeviceError, ValueError):
    """A device answered something that cannot be: a reply of the wrong length or an
    impossible value (a bus fault, a wrong baud rate, another device on the port)."""
