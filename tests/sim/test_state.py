"""The simulated arm's truth between processes: one file per model FILE, written atomically,
held by one process at a time; the OWI's truth apart from the driver's estimate."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from armkit._lock import exclusive
from armkit.cli import main
from armkit.connect import open_driver, sim_state_file, world_of
from armkit.drivers.timed import load_state, state_path
from armkit.model import load_model


def _where(capsys: pytest.CaptureFixture[str], *arm: str) -> list[float]:
    assert main([*arm, "where"]) == 0
    line = capsys.readouterr().out.split("joints ")[1].split("\n")[0].split()
    return [float(w) for w in line[1:-1:2]]


def test_two_model_files_with_one_name_keep_two_poses(
    tmp_path: Path, config_dir: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    shipped = load_model("planar2").source
    assert shipped is not None
    a, b = tmp_path / "a" / "arm.toml", tmp_path / "b" / "arm.toml"
    for path in (a, b):
        path.parent.mkdir()
        path.write_text(shipped.read_text())  # both say name = "planar2"
    assert sim_state_file(load_model(a)) != sim_state_file(load_model(b))
    assert sim_state_file(load_model("planar2")) == config_dir / "sim_planar2.json"
    assert main(["--arm", str(a), "joints", "20", "30"]) == 0
    assert _where(capsys, "--arm", str(a)) == pytest.approx([20, 30], abs=0.1)
    assert _where(capsys, "--arm", str(b)) == pytest.approx([0, 0], abs=0.1)
    assert _where(capsys, "--arm", "planar2") == pytest.approx([0, 0], abs=0.1)
    saved = json.loads(sim_state_file(load_model(a)).read_text())
    assert saved["model_file"] == str(a) and saved["q_deg"] == pytest.approx([20, 30], abs=0.1)


def test_a_second_process_on_the_same_simulated_arm_is_refused(config_dir: Path) -> None:
    state = sim_state_file(load_model("openmanipulator_x"))
    with exclusive(state, "a test holding the arm"):
        env = {**os.environ, "ARMKIT_CONFIG_DIR": str(config_dir)}
        code = "import sys; from armkit.cli import main; sys.exit(main(['where']))"
        out = subprocess.run(
            [sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120
        )
    assert out.returncode == 2
    err = out.stderr.strip()
    assert err.count("\n") == 0 and f"in use by process {os.getpid()}" in err
    assert "openmanipulator_x" in err and not state.exists()


def test_the_state_file_is_held_while_open_and_released_at_close() -> None:
    model = load_model("lynx6")
    first = open_driver(model, "sim", keep=True)
    with pytest.raises(Exception, match="in use by process"):
        open_driver(model, "sim", keep=True)
    first.close()
    open_driver(model, "sim", keep=True).close()  # free again


def test_the_owi_truth_is_kept_apart_from_the_drivers_estimate(config_dir: Path) -> None:
    owi = load_model("owi535")
    assert main(["--arm", "owi535", "joints", "40", "20", "0", "0"]) == 0
    truth = json.loads(sim_state_file(owi).read_text())
    estimate = load_state(state_path("sim"))
    assert truth["q_deg"] != pytest.approx(np.degrees(estimate.angles), abs=1e-6)  # slip, coast
    assert truth["q_deg"][0] == pytest.approx(40, abs=8)
    driver = open_driver(owi, "sim", keep=True)  # a new process: the truth is not reset
    world = world_of(driver)
    assert world is not None
    assert np.degrees(world.arm().q()) == pytest.approx(truth["q_deg"], abs=1e-6)
    np.testing.assert_allclose(driver.read(), estimate.angles)
    driver.close()


def test_a_refused_command_writes_no_state(config_dir: Path) -> None:
    assert main(["joints", "0", "0", "0", "200"]) == 2
    assert main(["--arm", "owi535", "joints", "0", "0", "0", "200"]) == 2
    assert not config_dir.exists() or not any(p.suffix == ".json" for p in config_dir.rglob("*"))


def test_a_state_file_for_another_arm_is_refused(config_dir: Path) -> None:
    omx = load_model("openmanipulator_x")
    config_dir.mkdir()
    sim_state_file(omx).write_text(json.dumps({"arm": "lynx6", "q_deg": [0] * 4, "grip_mm": 1}))
    with pytest.raises(Exception, match="not for this openmanipulator_x arm"):
        open_driver(omx, "sim", keep=True)
    sim_state_file(omx).write_text("{torn")
    with pytest.raises(Exception, match="unreadable simulator state"):
        open_driver(omx, "sim", keep=True)
    open_driver(load_model("lynx6"), "sim", keep=True).close()  # other arms are unaffected


@pytest.mark.parametrize(
    "tool",
    [
        "pen",
        [1, 2],
        {"name": "pen", "tool_length_mm": -5, "width_mm": 24},
        {"name": "pen", "tool_length_mm": 116, "width_mm": 2000},
        {"name": "pen", "width_mm": 24},
    ],
)
def test_a_kept_tool_that_makes_no_sense_is_refused(config_dir: Path, tool: object) -> None:
    omx = load_model("openmanipulator_x")
    config_dir.mkdir()
    kept = {"arm": "openmanipulator_x", "q_deg": [0] * 4, "grip_mm": 24, "tool": tool}
    sim_state_file(omx).write_text(json.dumps(kept))
    with pytest.raises(Exception, match="unreadable simulator state"):
        open_driver(omx, "sim", keep=True)
    kept["tool"] = {"name": "pen", "tool_length_mm": 116, "width_mm": 24}
    sim_state_file(omx).write_text(json.dumps(kept))
    open_driver(omx, "sim", keep=True).close()  # a sound one is taken
