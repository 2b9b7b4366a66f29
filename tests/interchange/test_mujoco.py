"""armkit's URDF and MJCF files open unchanged in MuJoCo, pybullet and yourdfpy, with
FK equal to armkit's to 1e-9 m (issue 27 item 4), and their masses are the capsules'."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from armkit import fk, load_model
from armkit.cli import main
from armkit.interchange import CUBE_DENSITY, DENSITY, mjcf_of, urdf_of
from armkit.interchange._bodies import bodies_of
from armkit.interchange._inertia import capsule_inertial
from armkit.interchange._mjcf import STIFF_AT
from armkit.interchange._mjcf_scene import board_boxes
from armkit.model import ArmModel, shipped_models
from armkit.scene import load_scene

ARMS = shipped_models()
N = 200


def _poses(m: ArmModel, seed: int) -> np.ndarray:
    return np.random.default_rng(seed).uniform(m.lower, m.upper, (N, m.dof))


def _set(mm: mujoco.MjModel, data: mujoco.MjData, m: ArmModel, q: np.ndarray) -> None:
    for name, qi in zip(m.joint_names, q, strict=True):
        data.qpos[mm.joint(name).qposadr[0]] = qi
    mujoco.mj_kinematics(mm, data)


def _pose(xpos: np.ndarray, xmat: np.ndarray) -> np.ndarray:
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = np.asarray(xmat).reshape(3, 3), xpos
    return T


def test_every_shipped_arm_is_tested() -> None:
    assert {"owi535", "lynx6", "openmanipulator_x", "puma560", "al5d", "planar2"} <= set(ARMS)


@pytest.mark.parametrize("name", ARMS)
def test_the_urdf_loads_in_mujoco_with_fk_equal(name: str, tmp_path: Path) -> None:
    m = load_model(name)
    path = tmp_path / f"{name}.urdf"
    path.write_text(urdf_of(m))
    mm = mujoco.MjModel.from_xml_path(str(path))
    data = mujoco.MjData(mm)
    assert mm.njnt == m.dof
    tool = mm.body("tool").id
    for q in _poses(m, 1):
        _set(mm, data, m, q)
        got = _pose(data.xpos[tool], data.xmat[tool])
        assert np.abs(got - fk(m, q)).max() < 1e-9


@pytest.mark.parametrize("name", ARMS)
@pytest.mark.parametrize("scene", [None, "board_001", "search_002"])
def test_the_mjcf_loads_in_mujoco_with_fk_equal(name: str, scene: str | None) -> None:
    """The site ``tool`` by mj_kinematics is armkit's fk, in the scene's frame with a scene."""
    m = load_model(name)
    sc = load_scene(scene) if scene else None
    mm = mujoco.MjModel.from_xml_string(mjcf_of(m, sc))
    data = mujoco.MjData(mm)
    T_world_base = np.eye(4) if sc is None else sc.T_world_base
    site = mm.site("tool").id
    for q in _poses(m, 2):
        _set(mm, data, m, q)
        got = _pose(data.site_xpos[site], data.site_xmat[site])
        assert np.abs(got - T_world_base @ fk(m, q)).max() < 1e-9


@pytest.mark.parametrize("name", ARMS)
def test_the_urdf_loads_in_yourdfpy_with_fk_equal(name: str, tmp_path: Path) -> None:
    import yourdfpy

    m = load_model(name)
    path = tmp_path / f"{name}.urdf"
    path.write_text(urdf_of(m))
    robot = yourdfpy.URDF.load(str(path), load_meshes=False, load_collision_meshes=False)
    for q in _poses(m, 3)[:50]:
        robot.update_cfg(q)
        assert np.abs(robot.get_transform("tool", "base_link") - fk(m, q)).max() < 1e-9


@pytest.mark.parametrize("name", ARMS)
def test_the_urdf_loads_in_pybullet_with_the_capsules_masses(name: str, tmp_path: Path) -> None:
    """pybullet gives an inertial-less link 1 kg: every moving link here has its own mass,
    the tool none. pybullet's link frames agree to 1e-6 m (it keeps them in 32-bit)."""
    pybullet = pytest.importorskip("pybullet")
    m = load_model(name)
    path = tmp_path / f"{name}.urdf"
    path.write_text(urdf_of(m))
    client = pybullet.connect(pybullet.DIRECT)
    try:
        robot = pybullet.loadURDF(str(path), useFixedBase=True, physicsClientId=client)
        masses = [
            pybullet.getDynamicsInfo(robot, j, physicsClientId=client)[0] for j in range(m.dof + 1)
        ]
        expected = [link.inertial.mass for link in bodies_of(m).links[1:]] + [0.0]
        assert np.allclose(masses, expected, rtol=1e-9) and min(masses[:-1]) > 0.0
        for q in _poses(m, 4)[:20]:
            for j, qj in enumerate(q):
                pybullet.resetJointState(robot, j, qj, physicsClientId=client)
            state = pybullet.getLinkState(
                robot, m.dof, computeForwardKinematics=True, physicsClientId=client
            )
            assert np.abs(np.array(state[4]) - fk(m, q)[:3, 3]).max() < 1e-6
    finally:
        pybullet.disconnect(client)


@pytest.mark.parametrize("length", [0.0, 0.05, 0.3])
def test_capsule_mass_and_inertia_are_mujoco_s_own(length: float) -> None:
    """MuJoCo computes a capsule geom's mass and inertia itself (inertiafromgeom): the
    same numbers as armkit's formula."""
    a, b, r = np.array([0.01, -0.02, 0.03]), np.array([0.01 + length, -0.02, 0.03]), 0.015
    shape = (
        f'type="capsule" fromto="{" ".join(map(str, [*a, *b]))}"'
        if length
        else (f'type="sphere" pos="{" ".join(map(str, a))}"')
    )
    xml = (
        "<mujoco><worldbody><body><freejoint/>"
        f'<geom {shape} size="{r}" density="{DENSITY}"/>'
        "</body></worldbody></mujoco>"
    )
    mm = mujoco.MjModel.from_xml_string(xml)
    mine = capsule_inertial(a, b, r)
    assert mm.body_mass[1] == pytest.approx(mine.mass, rel=1e-9)
    assert np.allclose(
        np.sort(mm.body_inertia[1]), np.sort(np.linalg.eigvalsh(mine.inertia)), rtol=1e-9
    )


@pytest.mark.parametrize("name", ARMS)
def test_the_actuators_hold_home_and_the_jaws_open(name: str) -> None:
    """One simulated second at home: every joint within 2 x STIFF_AT of home against
    gravity; then the gripper actuator opens the jaws to their full width."""
    m = load_model(name)
    mm = mujoco.MjModel.from_xml_string(mjcf_of(m))
    data = mujoco.MjData(mm)
    mujoco.mj_resetDataKeyframe(mm, data, mm.key("home").id)
    data.ctrl[: m.dof] = m.home
    for _ in range(500):
        mujoco.mj_step(mm, data)
    q = np.array([data.qpos[mm.joint(n).qposadr[0]] for n in m.joint_names])
    assert np.abs(q - m.home).max() < 2 * STIFF_AT
    if not m.gripper.present:
        return
    travel = (m.gripper.width_max - m.gripper.width_min) / 2
    data.ctrl[mm.actuator("gripper").id] = travel
    for _ in range(1000):
        mujoco.mj_step(mm, data)
    for jaw in ("jaw_left", "jaw_right"):
        assert data.qpos[mm.joint(jaw).qposadr[0]] == pytest.approx(travel, abs=2e-3)


def test_the_scene_s_cubes_are_free_bodies_with_their_mass() -> None:
    sc = load_scene("board_001")
    mm = mujoco.MjModel.from_xml_string(mjcf_of(load_model("openmanipulator_x"), sc))
    assert sc.cubes
    for c in sc.cubes:
        body = mm.body(c.name)
        assert mm.body_mass[body.id] == pytest.approx(CUBE_DENSITY * c.size**3)
        assert mm.jnt_type[mm.body_jntadr[body.id]] == mujoco.mjtJoint.mjJNT_FREE
    data = mujoco.MjData(mm)
    mujoco.mj_resetDataKeyframe(mm, data, mm.key("home").id)
    mujoco.mj_kinematics(mm, data)
    for c in sc.cubes:
        assert np.abs(data.xpos[mm.body(c.name).id] - c.T[:3, 3]).max() < 1e-12


def test_a_board_s_sockets_are_holes() -> None:
    """A point inside a socket is in no box of the board; one between sockets and one in
    the plate under them are in one."""
    b = load_scene("board_001").boards[0]
    boxes = board_boxes(b)

    def inside(p: np.ndarray) -> int:
        n = 0
        for T, half in boxes:
            local = T[:3, :3].T @ (p - T[:3, 3])
            n += bool(np.all(np.abs(local) < half + 1e-12))
        return n

    for r in range(b.rows):
        for c in range(b.cols):
            floor = b.socket(r, c)
            assert inside(floor + np.array([0, 0, b.socket_depth / 2])) == 0
            assert inside(floor - np.array([0, 0, 1e-4])) == (
                1 if b.thickness > b.socket_depth else 0
            )
    between = (b.socket(0, 0) + b.socket(0, 1)) / 2 + np.array([0, 0, b.socket_depth / 2])
    assert inside(between) == 1


def test_the_cli_writes_mjcf_with_a_scene_or_prints_it(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "omx.xml"
    argv = ["--arm", "openmanipulator_x", "--scene", "board_001", "mjcf", "-o", str(out)]
    assert main(argv) == 0
    assert capsys.readouterr().out == f"wrote {out} (4 joints, gripper: yes on scene board_001)\n"
    mujoco.MjModel.from_xml_path(str(out))
    assert main(["--arm", "planar2", "mjcf"]) == 0
    printed = capsys.readouterr().out
    assert printed == mjcf_of(load_model("planar2"))
    assert main(["mjcf", "-o", str(tmp_path / "no" / "x.xml")]) == 2
    assert "-o/--output" in capsys.readouterr().err and not (tmp_path / "no").exists()
