"""The one error hierarchy of armkit.

Every error a user can cause is an ``ArmkitError``; the CLI prints its message
on one line and exits non-zero. Messages say what was asked, what is allowed
and what to do.
"""

from __future__ import annotations

from typing import Any


class ArmkitError(Exception):
    """Base class of every error armkit raises on purpose."""


class ModelError(ArmkitError):
    """An arm model file is missing, malformed or inconsistent."""


class UnreachableError(ArmkitError):
    """No joint angles put the tool at the target within the joint limits.

    Attributes:
        reason: one of ``"too_far"``, ``"too_close"``, ``"joint_limit"``,
            ``"off_plane"``, ``"pitch"``, ``"no_convergence"``.
        closest: the closest joint vector found [rad], shape (dof,), or None.
    """

    def __init__(self, message: str, *, reason: str = "", closest: Any = None) -> None:
        super().__init__(message)
        self.reason = reason
        self.closest = closest


class NoSolutionError(UnreachableError):
    """A numeric solver stopped without meeting its tolerance."""


class JointLimitError(ArmkitError):
    """A joint angle is outside its limits."""


class DeviceError(ArmkitError):
    """A device is missing, refused access, or answered wrongly."""


class ScriptError(ArmkitError):
    """A command-language script is wrong."""


class InputError(ArmkitError, ValueError):
    """A value someone gave (an argument, an option, a parameter) is not allowed:
    not a number, out of its range, or the wrong count. The message names the
    argument, what is allowed and what was given, in the units it was given in."""


class ReplyError(DeviceError, ValueError):
    """A device answered something that cannot be: a reply of the wrong length or an
    impossible value (a bus fault, a wrong baud rate, another device on the port)."""
