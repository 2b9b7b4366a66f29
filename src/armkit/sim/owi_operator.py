"""An automatic operator for calibrating the simulated OWI: it 'presses Enter'
when every running motor has reached its limit, a little late like a person."""

from __future__ import annotations

import numpy as np

from .owi_sim import OwiSim


class SimOperator:
    """``ask``/``say`` for :func:`armkit.drivers.timed.calibrate_owi535` on a simulated arm.

    Args:
        sim: the simulated arm (its clock must be simulated, or waiting is real).
        seed: for the reaction times.
        reaction_s: mean delay between the limit and the answer [s].
        step_s: how often it looks [s].
    """

    def __init__(
        self, sim: OwiSim, seed: int = 0, reaction_s: float = 0.08, step_s: float = 0.02
    ) -> None:
        self.sim = sim
        self.reaction_s, self.step_s = reaction_s, step_s
        self._rng = np.random.default_rng(seed)
        self.lines: list[str] = []

    def ask(self, prompt: str) -> str:
        """Wait (on the sim clock) until the running joints sit at their limits; answer ''."""
        self.lines.append(prompt)
        physics, clock = self.sim.physics, self.sim.clock
        running = [j for j in range(4) if physics.dirs[j] != 0]
        deadline = clock.now() + 120.0
        while running and not all(physics.at_limit(j) for j in running) and clock.now() < deadline:
            clock.sleep(self.step_s)
        if running:
            clock.sleep(max(0.0, self.reaction_s + 0.03 * float(self._rng.standard_normal())))
        return ""

    def say(self, text: str) -> None:
        """Keep what the routine said."""
        self.lines.append(text)


def auto_operator(driver: object) -> SimOperator | None:
    """An automatic operator if ``driver`` runs on a simulated OWI (``--driver sim``), else
    None (a person answers). For wiring ``calibrate`` on the simulator."""
    sim = getattr(driver, "simulation", None)
    return SimOperator(sim) if isinstance(sim, OwiSim) else None
