"""What the simulated OWI received, for the tests (a module name no other test folder uses)."""

from __future__ import annotations

from armkit.sim.owi_sim import OwiSim


def sent(sim: OwiSim) -> list[str]:
    """Every command sent so far, as hex strings ('400000')."""
    return [t.data.hex() for t in sim.backend.transfers]
