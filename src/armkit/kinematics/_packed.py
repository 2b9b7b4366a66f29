"""A chain packed as one float64 buffer, the form the compiled LM kernel reads
(``_numeric/_lmc.c``): dof; per joint its fixed transform's rotation (9, row-major) and
translation (3) [m], sign, offset [rad]; the tool's rotation and translation; the lower
and upper limits [rad]; the reach [m]; the angle rows' weight [m/rad]."""

from __future__ import annotations

from array import array

from ._steps import Fixed, Step


def pack_chain(
    steps: tuple[Step, ...], tool: Fixed, lower: tuple[float, ...], upper: tuple[float, ...],
    reach: float, weight: float,
) -> bytes:  # fmt: skip
    """The chain's numbers as the kernel reads them (see the module docstring)."""
    out = array("d", [float(len(steps))])
    for s in steps:
        T = s.before.T
        out.extend(T[:3, :3].ravel().tolist() + T[:3, 3].tolist() + [s.sign, s.offset])
    out.extend(tool.T[:3, :3].ravel().tolist() + tool.T[:3, 3].tolist())
    out.extend([*lower, *upper, reach, weight])
    return out.tobytes()
