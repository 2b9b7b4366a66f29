"""The arm's links as capsules (segments with a radius), one pose or a batch.

Capsule i joins the origins of frames i and i + 1 of ``armkit.fk_frames``; capsule
0 is the base column, the last joins the flange to the tool point. For the
clearance check the last capsule (the gripper) tapers to the tool point: it is
split into ``TAPER`` pieces whose radii fall from the link's radius to a third of
it, the tip piece ending at the tool point itself, so the tool point may touch a
surface (a pen on paper, the jaws around a cube) while the wrist keeps its radius.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..kinematics import fk_frames, frames_on_base_axis
from ..model import ArmModel

F64 = NDArray[np.float64]
TAPER = 3  # pieces of the gripper's capsule in the clearance check


@dataclass(frozen=True)
class Capsules:
    """Segments with radii.

    Attributes:
        p0, p1: segment ends [m], shape (K, 3) for one pose or (N, K, 3) for N poses.
        radii: [m], shape (K,).
        links: which link (capsule of ``arm_capsules``) each one belongs to, shape (K,).
    """

    p0: F64
    p1: F64
    radii: F64
    links: NDArray[np.intp]


def link_names(model: ArmModel) -> tuple[str, ...]:
    """A name for each capsule of ``arm_capsules``: base column (``column_links`` of
    them), the links between joints (``"shoulder-elbow link"``), the gripper."""
    names = [j.name for j in model.joints]
    between = [f"{a}-{b} link" for a, b in itertools.pairwise(names)]
    k = column_links(model)
    return ("base column",) * k + (*between, "gripper")[k - 1 :]


def column_links(model: ArmModel) -> int:
    """How many capsules, from the first, form the base column (at least one): both ends
    on the vertical axis through the base origin at every pose, so standing on the base.
    A DH chain has one (the base to the frame after row 0); a chain of joint frames
    (URDF) whose first joint sits at the base origin has two (the base to that joint,
    that joint up to the next)."""
    return max(1, frames_on_base_axis(model) - 1)


def arm_capsules(model: ArmModel, q: ArrayLike) -> Capsules:
    """The arm's links as capsules for joint angles ``q`` [rad], shape (dof,) or (N, dof).

    Returns:
        Capsules with K = dof + 1 (ends (K, 3) or (N, K, 3)), radii ``model.link_radii``
        (15 mm each if the model gives none), in the arm's base frame [m].
    """
    origins = fk_frames(model, q)[..., :3, 3]
    return Capsules(
        origins[..., :-1, :], origins[..., 1:, :], _radii(model), np.arange(model.dof + 1)
    )


def clearance_capsules(model: ArmModel, origins: F64, R_tool: F64) -> Capsules:
    """``arm_capsules`` for N poses from ``frame_origins`` (origins (N, dof + 2, 3),
    tool rotations (N, 3, 3)), the gripper split into tapering pieces."""
    n, links = origins.shape[0], model.dof
    radii = _radii(model)
    p0 = np.empty((n, links + TAPER, 3))
    p1 = np.empty((n, links + TAPER, 3))
    p0[:, :links], p1[:, :links] = origins[:, :-2], origins[:, 1:-1]
    flange, tool = origins[:, -2, :], origins[:, -1, :]
    s = np.arange(TAPER + 1) / TAPER
    along = flange[:, None, :] + s[None, :, None] * (tool - flange)[:, None, :]  # (N, TAPER+1, 3)
    p0[:, links:], p1[:, links:] = along[:, :-1], along[:, 1:]
    piece = radii[-1] * (TAPER - np.arange(TAPER)) / TAPER
    p1[:, -1] = tool - R_tool[:, :, 0] * piece[-1]  # the tip piece's cap ends at the tool point
    return Capsules(
        p0,
        p1,
        np.concatenate([radii[:-1], piece]),
        np.concatenate([np.arange(links), np.full(TAPER, links)]),
    )


def _radii(model: ArmModel) -> F64:
    if len(model.link_radii) == model.dof + 1:
        return np.array(model.link_radii)
    return np.full(model.dof + 1, 0.015)


def frame_origins(model: ArmModel, q: F64) -> tuple[F64, F64]:
    """Origins of every frame of ``fk_frames`` for N poses, shape (N, dof + 2, 3) [m],
    and the tool frame's rotation, shape (N, 3, 3) (column 0: the approach axis)."""
    frames = fk_frames(model, q)
    return frames[:, :, :3, 3], frames[:, -1, :3, :3]
