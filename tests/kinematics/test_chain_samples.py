"""Compiling a chain finds how many frames stay on the base axis from joint vectors spread
over the limits with no random generator (issue 29 item 7: no numpy.random at start-up);
the answer is the one random vectors give, on every shipped arm."""

from __future__ import annotations

import subprocess
import sys

import numpy as np

from armkit.kinematics._chain import chain_of, spread
from armkit.kinematics._steps import dense_frames
from armkit.model import load_model, shipped_models


def _on_axis_random(name: str, seed: int) -> int:
    model = load_model(name)
    chain = chain_of(model)
    lower, upper = np.array(model.lower), np.array(model.upper)
    q = np.vstack([np.array(model.home), np.zeros(model.dof)])
    q = np.vstack([q, np.random.default_rng(seed).uniform(lower, upper, (16, model.dof))])
    p = dense_frames(chain.steps, chain.tool, q)[:, :, :3, 3]
    on = np.all(np.hypot(p[..., 0], p[..., 1]) < 1e-9, axis=0)
    return int(np.argmin(on)) if not on.all() else len(on)


def test_spread_stays_inside_the_limits_and_moves_every_joint() -> None:
    for dof in range(1, 12):
        lower, upper = np.linspace(-3.0, -0.1, dof), np.linspace(0.2, 2.5, dof)
        q = spread(lower, upper, 8)
        assert q.shape == (8, dof)
        assert np.all(q > lower) and np.all(q < upper)
        assert np.all(np.ptp(q, axis=0) > 0.3 * (upper - lower))


def test_on_axis_is_what_random_vectors_find_on_every_shipped_arm() -> None:
    for name in shipped_models():
        expected = {_on_axis_random(name, seed) for seed in range(3)}
        assert expected == {chain_of(load_model(name)).on_axis}, name


def test_ik_of_a_shipped_arm_loads_no_numpy_random() -> None:
    code = (
        "import sys; from armkit import ik, load_model; "
        "ik(load_model('openmanipulator_x'), [0.2, 0.0, 0.1]); "
        "print('numpy.random' in sys.modules)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"
