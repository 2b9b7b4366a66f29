"""1000 random moves through the simulated devices grow the process by less than 20 MB
(a 1000-move run used to grow it by 278 MB: the recording and the device logs are bounded)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

CHILD = """
import resource, sys
import numpy as np
from armkit import Arm, UnreachableError
from armkit.model import load_model

def rss_mb():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * resource.getpagesize() / 2**20

model = load_model(sys.argv[1])
rng = np.random.default_rng(0)
with Arm(model, "sim") as arm:
    span = model.upper - model.lower
    def move():  # a random move of up to a tenth of each joint's range, kept inside it
        while True:  # a move into the table is refused before it starts: draw another
            q = np.radians(list(arm.angles().values())) + rng.uniform(-0.1, 0.1, model.dof) * span
            q = np.clip(q, model.lower + 0.1 * span, model.upper - 0.1 * span)
            try:
                return arm.move_joints(list(np.degrees(q)))
            except UnreachableError:
                pass
    for _ in range(20):
        move()
    before = rss_mb()
    for _ in range(1000):
        move()
    print(rss_mb() - before, arm.world.now(), len(arm.world.recording().t))
"""


@pytest.mark.parametrize("arm", ["openmanipulator_x", "lynx6"])
def test_a_thousand_random_moves_stay_bounded(arm: str, tmp_path: Path) -> None:
    env = {**os.environ, "ARMKIT_CONFIG_DIR": str(tmp_path)}
    out = subprocess.run(
        [sys.executable, "-c", CHILD, arm], capture_output=True, text=True, env=env, timeout=600
    )
    assert out.returncode == 0, out.stderr
    grown_mb, simulated_s, samples = (float(v) for v in out.stdout.split())
    assert simulated_s > 200  # a long run: beyond what the recording keeps
    assert samples == 120_000  # 120 s at 1 kHz, the default bound
    assert grown_mb < 20.0
