"""Clearance: is every link of the arm (and the object it holds) clear of the
table and of the scene's boards, cubes and containers, at every pose of a path?

numpy only: the links are capsules, the objects boxes; a bounding-box test
keeps the few pairs that can touch, then the exact signed distance from each
capsule's segment to each box (convex along the segment: a golden-section
search) decides. The held object is a box moving with the gripper, checked
with separating axes against the boxes and by its corners against the table.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..model import ArmModel
from ._capsules import Capsules, clearance_capsules, column_links, frame_origins, link_names
from ._cube import Cube
from ._distance import box_box_gap, box_corners, segment_box_distance, segment_segment_distance
from ._obstacles import Obstacles, obstacles
from ._scene import Scene

F64 = NDArray[np.float64]
TOUCH = 0.2e-3  # [m]: surfaces this far into each other still only touch
SWEEP_STEP = 0.0175  # [rad] (1 deg): joint-space sampling of a move for the check
WIDTH_EPS = 0.2e-3  # [m]: grip changes smaller than this are not a motion
COLUMN = "base column"  # the object a link folding into the arm's own base hits
INTO_COLUMN = 2e-3  # [m]: how far a link's capsule may reach into the base column's (both
# are rough envelopes of the real parts)


@dataclass(frozen=True)
class Held:
    """An object in the gripper: the cube and its pose in the tool frame, (4, 4) [m]."""

    cube: Cube
    T_tool_object: F64

    def released_by(self, width: float) -> bool:
        """Whether opening the jaws to ``width`` [m] lets it go: wider than the cube by
        more than ``WIDTH_EPS`` (the simulator's physics and ``Arm`` both ask this)."""
        return width > self.cube.size + WIDTH_EPS


@dataclass(frozen=True)
class Collision:
    """The first pose of a path where something is not clear.

    Attributes:
        step: index of the pose in the path (0 for a single pose).
        link: the link's name (``"elbow-wrist link"``, ``"gripper"``) or ``"held <name>"``.
        object: ``"table"`` or the scene object's name.
        distance: signed clearance [m]; negative = that far into the object.
    """

    step: int
    link: str
    object: str
    distance: float

    def describe(self) -> str:
        """One line: ``the gripper would be 3.2 mm into board``."""
        mm = self.distance * 1000.0
        where = f"{-mm:.1f} mm into" if mm < 0 else f"only {mm:.1f} mm from"
        return f"the {self.link} would be {where} the {self.object}"


def check_clear(
    model: ArmModel,
    q: ArrayLike,
    scene: Scene | None = None,
    held: Held | None = None,
    *,
    ignore: frozenset[str] = frozenset(),
    margin: float = 0.0,
) -> Collision | None:
    """The first collision along joint angles ``q`` [rad], shape (dof,) or (N, dof), or None.

    Checks every link but the base column against the table (``scene.table_z``,
    else ``model.table_z``), the links beyond the one on top of the base column against
    the column (the arm folding into its own base), every link against the scene's boxes (the gripper
    not against the objects in ``ignore``: the one it is closing on), and the held
    object against the table and the boxes. ``margin`` [m]: clearance required.
    """
    qa = np.atleast_2d(np.asarray(q, dtype=np.float64))
    origins, R_tool = frame_origins(model, qa)
    T = scene.T_world_base if scene is not None else np.eye(4)
    table_z = scene.table_z if scene is not None else model.table_z
    caps = _moved(clearance_capsules(model, origins, R_tool), T)
    names = link_names(model)
    column = column_links(model)
    found = [_table(caps, table_z, margin, names, column), _column(caps, column, names)]
    if scene is not None:
        found.append(_boxes(caps, obstacles(scene), ignore, model.dof, margin, names))
    if held is not None:
        T_tool = np.zeros((qa.shape[0], 4, 4))
        T_tool[:, :3, :3] = T[:3, :3] @ R_tool
        T_tool[:, :3, 3] = origins[:, -1, :] @ T[:3, :3].T + T[:3, 3]
        T_tool[:, 3, 3] = 1.0
        found.append(_held(T_tool @ held.T_tool_object, held.cube, scene, table_z, margin))
    hits = [c for c in found if c is not None]
    return min(hits, key=lambda c: (c.step, c.distance)) if hits else None


def _moved(caps: Capsules, T: F64) -> Capsules:
    """Capsules from the base frame to the scene frame by ``T`` (4, 4)."""
    if np.array_equal(T, np.eye(4)):
        return caps
    R, t = T[:3, :3], T[:3, 3]
    return Capsules(caps.p0 @ R.T + t, caps.p1 @ R.T + t, caps.radii, caps.links)


def _table(
    caps: Capsules, table_z: float, margin: float, names: tuple[str, ...], column: int
) -> Collision | None:
    low = np.minimum(caps.p0[..., 2], caps.p1[..., 2]) - caps.radii - table_z  # (N, K)
    low[:, caps.links < column] = np.inf  # the base column stands on the table
    return _first(low, caps.links, names, margin - TOUCH, "table")


def _column(caps: Capsules, column: int, names: tuple[str, ...]) -> Collision | None:
    """The links beyond the first one with a length above the base column (its first
    end stands on the column) against the column's capsules (links < ``column``, their tops
    lowered by their radius: ``_shorter``): into them by more than ``INTO_COLUMN``."""
    length = np.linalg.norm(caps.p1[0] - caps.p0[0], axis=-1)  # rigid: as at every pose
    moving = np.flatnonzero((caps.links >= column) & (length > 1e-9))
    if moving.size == 0:
        return None
    arm = np.flatnonzero(caps.links > caps.links[moving[0]])
    col = np.flatnonzero(caps.links < column)
    top = caps.p0[:, col] + (caps.p1[:, col] - caps.p0[:, col]) * _shorter(
        length[col], caps.radii[col]
    )
    ends = caps.p0[:, arm, None], caps.p1[:, arm, None], caps.p0[:, None, col], top[:, None]
    gap = segment_segment_distance(*ends) - caps.radii[arm, None] - caps.radii[None, col]
    dist = np.full(caps.p0.shape[:2], np.inf)
    dist[:, arm] = gap.min(axis=2)
    return _first(dist, caps.links, names, -INTO_COLUMN, COLUMN)


def _shorter(length: F64, radius: F64) -> F64:
    """The share (K, 1) of each column capsule's segment kept so that its rounded top
    ends at the segment's end, not a radius above it (the shoulder sits there, and a
    folded forearm may pass over it)."""
    keep = np.clip(1.0 - radius / np.where(length > 0.0, length, 1.0), 0.0, 1.0)
    return np.asarray(keep[:, None], dtype=np.float64)


def _boxes(
    caps: Capsules,
    obs: Obstacles,
    ignore: frozenset[str],
    dof: int,
    margin: float,
    names: tuple[str, ...],
) -> Collision | None:
    if not obs.owners:
        return None
    r = caps.radii + margin + TOUCH
    lo = np.minimum(caps.p0, caps.p1) - r[:, None]  # (N, K, 3)
    low = np.flatnonzero(lo[..., 2].ravel() <= obs.hi[:, 2].max())  # most links are high up
    if low.size == 0:
        return None
    hi = np.maximum(caps.p0, caps.p1).reshape(-1, 3)[low] + np.tile(r, len(caps.p0))[low, None]
    near = np.all(
        (lo.reshape(-1, 3)[low, None] <= obs.hi[None]) & (hi[:, None] >= obs.lo[None]), axis=-1
    )
    nk, m = np.nonzero(near)
    n, k = np.divmod(low[nk], caps.p0.shape[1])
    if ignore:
        keep = ~(
            (caps.links[k] == dof)
            & np.isin(m, [i for i, o in enumerate(obs.owners) if o in ignore])
        )
        n, k, m = n[keep], k[keep], m[keep]
    if n.size == 0:
        return None
    Rt = np.transpose(obs.rotations[m], (0, 2, 1))
    a = np.einsum("pij,pj->pi", Rt, caps.p0[n, k] - obs.centers[m])
    b = np.einsum("pij,pj->pi", Rt, caps.p1[n, k] - obs.centers[m])
    d = segment_box_distance(a, b, obs.halves[m]) - caps.radii[k]
    bad = np.flatnonzero(d < margin - TOUCH)
    if bad.size == 0:
        return None
    first = bad[n[bad] == n[bad].min()]
    worst = first[np.argmin(d[first])]
    return Collision(
        int(n[worst]), names[caps.links[k[worst]]], obs.owners[m[worst]], float(d[worst])
    )


def _held(
    T_obj: F64, cube: Cube, scene: Scene | None, table_z: float, margin: float
) -> Collision | None:
    """The held cube, centre poses (N, 4, 4), against the table and the scene's boxes."""
    n = T_obj.shape[0]
    c, R = T_obj[:, :3, 3], T_obj[:, :3, :3]
    h = np.full((n, 3), cube.size / 2)
    low = box_corners(c, R, h)[..., 2].min(axis=1) - table_z
    hits = [(int(i), "table", float(low[i])) for i in np.flatnonzero(low < margin - TOUCH)[:1]]
    if scene is not None and obstacles(scene).owners:
        hits.extend(_held_boxes(c, R, h, obstacles(scene), margin))
    if not hits:
        return None
    step, obj, dist = min(hits)
    return Collision(step, f"held {cube.name}", obj, dist)


def _first(
    dist: F64, links: NDArray[np.intp], names: tuple[str, ...], least: float, what: str
) -> Collision | None:
    """The first pose where a capsule's clearance ``dist`` (N, K) [m] from ``what`` is
    under ``least`` [m]."""
    bad = dist < least
    if not np.any(bad):
        return None
    step = int(np.flatnonzero(bad.any(axis=1))[0])
    k = int(np.argmin(dist[step]))
    return Collision(step, names[links[k]], what, float(dist[step, k]))


def _held_boxes(
    c: F64, R: F64, h: F64, obs: Obstacles, margin: float
) -> list[tuple[int, str, float]]:
    """The first pose where the held box (centres (N, 3), rotations (N, 3, 3), half
    sizes (N, 3)) overlaps a scene box: bounding boxes first, then separating axes."""
    extent = np.einsum("nij,nj->ni", np.abs(R), h) + margin + TOUCH
    near = np.all(
        ((c - extent)[:, None, :] <= obs.hi[None]) & ((c + extent)[:, None, :] >= obs.lo[None]),
        axis=-1,
    )
    ii, mm = np.nonzero(near)
    if ii.size == 0:
        return []
    gap = box_box_gap(c[ii], R[ii], h[ii], obs.centers[mm], obs.rotations[mm], obs.halves[mm])
    bad = np.flatnonzero(gap < margin - TOUCH)
    if bad.size == 0:
        return []
    j = bad[0]
    return [(int(ii[j]), obs.owners[mm[j]], float(gap[j]))]


def joint_sweep(q_from: ArrayLike, targets: ArrayLike, step: float = SWEEP_STEP) -> F64:
    """The poses a straight joint-space move from ``q_from`` (dof,) through each of
    ``targets`` (K, dof) [rad] passes, at most ``step`` [rad] apart, shape (N, dof)
    (``q_from`` left out, every target in)."""
    prev = np.asarray(q_from, dtype=np.float64)
    out = []
    for q in np.atleast_2d(np.asarray(targets, dtype=np.float64)):
        n = max(1, int(np.ceil(float(np.max(np.abs(q - prev))) / step)))
        out.append(prev + (q - prev) * (np.arange(1, n + 1) / n)[:, None])
        prev = q
    return np.vstack(out)


def joint_sweeps(q_from: F64, q_to: F64, step: float = SWEEP_STEP) -> F64:
    """The poses of K separate joint moves, row k from ``q_from[k]`` to ``q_to[k]``
    (K, dof) [rad], each as ``joint_sweep(q_from[k], q_to[k])`` gives them, stacked
    (its target in, its start out), shape (N, dof)."""
    d = q_to - q_from
    n = np.maximum(1, np.ceil(np.max(np.abs(d), axis=1) / step)).astype(np.intp)
    move = np.repeat(np.arange(len(d)), n)
    j = np.arange(len(move)) - np.repeat(np.cumsum(n) - n, n) + 1
    out: F64 = q_from[move] + d[move] * (j / n[move])[:, None]
    return out
