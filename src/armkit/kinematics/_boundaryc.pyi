"""The compiled boundary search (``_boundaryc.c``); see ``_boundary_fast`` for its use."""

def boundary(
    packed: bytes, r: float, z: float, rho: float, want: float, /
) -> tuple[float, float]: ...
