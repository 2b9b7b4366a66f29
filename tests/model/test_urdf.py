"""URDF out and in: every shipped arm round-trips with identical FK; errors name file and element."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from armkit import ModelError, fk, ik, load_model
from armkit.cli import main
from armkit.interchange import urdf_of
from armkit.interchange._bodies import bodies_of
from armkit.kinematics import why_no_closed_form
from armkit.model import shipped_models


@pytest.mark.parametrize("name", shipped_models())
def test_shipped_arms_round_trip_with_identical_fk(name: str, tmp_path: Path) -> None:
    m = load_model(name)
    path = tmp_path / f"{name}.urdf"
    path.write_text(urdf_of(m))
    back = load_model(path)
    assert back.dof == m.dof and back.joint_names == m.joint_names
    assert np.allclose(back.lower, m.lower) and np.allclose(back.upper, m.upper)
    q = np.random.default_rng(3).uniform(m.lower, m.upper, (200, m.dof))
    assert np.abs(fk(back, q) - fk(m, q)).max() < 1e-12
    assert (why_no_closed_form(back) == "") == (why_no_closed_form(m) == "")


@pytest.mark.parametrize("name", shipped_models())
def test_a_urdf_arm_s_home_is_inside_its_limits(name: str, tmp_path: Path) -> None:
    """URDF has no home: 0 where it lies strictly inside a joint's limits, else the middle
    (the Lynx6's 0 deg stops would start it folded against them)."""
    path = tmp_path / f"{name}.urdf"
    path.write_text(urdf_of(load_model(name)))
    back = load_model(path)
    assert np.all((back.lower < back.home) & (back.home < back.upper))
    middle = (back.lower + back.upper) / 2
    assert np.all((back.home == 0.0) | (back.home == middle))


def test_the_cli_writes_a_urdf_that_the_cli_reads(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "omx.urdf"
    assert main(["--arm", "openmanipulator_x", "urdf", "-o", str(out)]) == 0
    assert "wrote" in capsys.readouterr().out
    text = out.read_text()
    assert text.count('type="revolute"') == 4 and text.count("<cylinder") >= 8
    assert main(["--arm", str(out), "fk", "0", "0", "0", "0"]) == 0
    assert "x 274.00  y 0.00  z 204.50 mm" in capsys.readouterr().out
    m = load_model(out)
    res = ik(m, (0.2, 0.0, 0.05), -np.pi / 2)  # the closed form, recognised from the axes
    assert res.method == "analytic" and np.abs(fk(m, res.q)[:3, 3] - [0.2, 0.0, 0.05]).max() < 1e-12


def test_the_output_folder_is_checked_first(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["urdf", "-o", str(tmp_path / "no" / "x.urdf")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "does not exist" in err


ROBOT = """<robot name="r">
  <link name="base"/><link name="a"/><link name="b"/><link name="c"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="a"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="j2" type="JTYPE"><parent link="a"/><child link="b"/>
    <origin xyz="0.1 0 0"/><axis xyz="0 1 0"/>LIMIT</joint>
  <joint name="j3" type="revolute"><parent link="b"/><child link="c"/>
    <origin xyz="0.1 0 0"/><axis xyz="0 1 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""
LIMIT = '<limit lower="-1" upper="1" effort="1" velocity="1"/>'


@pytest.mark.parametrize(
    ("jtype", "limit", "match"),
    [
        ("prismatic", LIMIT, r"<joint name='j2'>: type 'prismatic' is not supported"),
        ("revolute", "", r"<joint name='j2'>: <limit lower upper> is required"),
        (
            "revolute",
            '<limit lower="1" upper="-1"/>',
            r"<joint name='j2'>: <limit> lower must be < upper",
        ),
    ],
)
def test_errors_name_the_file_and_element(
    tmp_path: Path, jtype: str, limit: str, match: str
) -> None:
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.replace("JTYPE", jtype).replace("LIMIT", limit))
    with pytest.raises(ModelError, match=match) as e:
        load_model(path)
    assert str(path) in str(e.value)


def test_bad_xml_missing_file_and_tip(tmp_path: Path) -> None:
    path = tmp_path / "bad.urdf"
    path.write_text("<robot name='x'><link name='a'")
    with pytest.raises(ModelError, match=r"bad.urdf: not valid XML"):
        load_model(path)
    with pytest.raises(ModelError, match="no such URDF file"):
        load_model(tmp_path / "none.urdf")
    good = tmp_path / "r.urdf"
    good.write_text(ROBOT.replace("JTYPE", "continuous").replace("LIMIT", ""))
    with pytest.raises(ModelError, match=r"<link name='zz'>: no such link"):
        load_model(f"{good}#zz")
    assert load_model(f"{good}#b").dof == 2 and load_model(good).dof == 3


@pytest.mark.parametrize("name", ["openmanipulator_x", "lynx6", "puma560"])
def test_link_capsules_join_the_frames_the_clearance_check_uses(name: str, tmp_path: Path) -> None:
    """In a URDF viewer (here yourdfpy's scene graph) every capsule end sits on the origin
    of a frame of fk_frames, at any pose."""
    import yourdfpy

    from armkit.kinematics import fk_frames

    m = load_model(name)
    path = tmp_path / "arm.urdf"
    path.write_text(urdf_of(m))
    robot = yourdfpy.URDF.load(str(path), load_meshes=False, load_collision_meshes=False)
    q = np.random.default_rng(5).uniform(m.lower, m.upper, m.dof)
    robot.update_cfg(q)
    centres = []
    for link in robot.robot.links:
        for c in link.collisions:
            if c.geometry.sphere is not None:
                centres.append((robot.get_transform(link.name, "base_link") @ c.origin)[:3, 3])
    ends = fk_frames(m, q)[:, :3, 3]
    gaps = np.linalg.norm(np.array(centres)[:, None, :] - ends[None, :, :], axis=2)
    assert gaps.min(axis=1).max() < 1e-9  # every sphere on a frame origin
    assert gaps.min(axis=0).max() < 1e-9  # every frame origin has a sphere
    # two per capsule, and one capsule of length 0 where a moving link has none (the OMX's
    # waist link: the shoulder sits on the waist axis)
    assert len(centres) == 2 * sum(len(link.capsules) for link in bodies_of(m).links)
    assert len(centres) >= 2 * len(m.link_radii)


def test_an_arm_read_from_urdf_moves_in_the_simulator_and_is_checked_for_clearance(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """A URDF has no driver table and no gripper: the generic simulated bus drives it,
    grip is refused in one line, and the clearance check sees its base column (two
    capsules of joint frames: the base to the waist joint, the waist up to the shoulder)
    as the DH model's one, so it refuses what the DH model refuses."""
    from armkit.scene import check_clear, link_names

    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path / "config"))  # the sim's kept state
    m = load_model("openmanipulator_x")
    path = tmp_path / "omx.urdf"
    path.write_text(urdf_of(m))
    back = load_model(path)
    assert link_names(back)[:2] == ("base column", "base column")
    up = ik(m, (0.2, 0.0, 0.1), 0.0).q
    down = ik(m, (0.2, 0.0, -0.01), -1.2).q
    for model in (m, back):
        assert check_clear(model, model.home) is None and check_clear(model, up) is None
        hit = check_clear(model, down)
        assert hit is not None and hit.object == "table"
    assert main(["--arm", str(path), "move", "200", "0", "100"]) == 0
    assert "gripper at x 200.0 y 0.0 z 100.0 mm" in capsys.readouterr().out
    assert main(["--arm", str(path), "move", "200", "0", "-10"]) == 2
    assert "into the table" in capsys.readouterr().err
    assert main(["--arm", str(path), "grip", "20"]) == 2
    err = capsys.readouterr().err
    assert "has no gripper" in err and err.count("\n") == 1


@pytest.mark.parametrize(
    ("origin", "match"),
    [
        (
            'xyz="0 0 nan"',
            r"<joint name='j1'>: <origin> xyz=\"0 0 nan\" must be 3 finite numbers \[m\]",
        ),
        (
            'xyz="0 0 1e9"',
            r"<joint name='j1'>: <origin> xyz=\"0 0 1e9\" is 1e\+09 m .*URDF lengths are metres",
        ),
        ('xyz="0 0 765"', r"is 765 m from the parent joint; .*76.5 mm is 0.0765"),
        (
            'xyz="0 0 0.1" rpy="0 inf 0"',
            r"<joint name='j1'>: <origin> rpy=\"0 inf 0\" must be 3 finite numbers \[rad\]",
        ),
    ],
)
def test_a_joint_origin_not_finite_or_absurd_is_refused_naming_file_and_joint(
    tmp_path: Path, origin: str, match: str
) -> None:
    """The loader refuses it, not the kinematics later ('the links add up to nan m ... mm')."""
    path = tmp_path / "r.urdf"
    text = ROBOT.replace("JTYPE", "revolute").replace("LIMIT", LIMIT)
    path.write_text(text.replace('<origin xyz="0 0 0.1"/>', f"<origin {origin}/>"))
    with pytest.raises(ModelError, match=match) as e:
        load_model(path)
    assert str(e.value).startswith(f"{path}: ") and "in mm" not in str(e.value)


def test_a_first_joint_of_an_unsupported_type_is_named(tmp_path: Path) -> None:
    """Every moving joint prismatic: the first is named, not 'no revolute joint'."""
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.replace('"revolute"', '"prismatic"').replace("JTYPE", "prismatic").replace("LIMIT", LIMIT))  # fmt: skip
    with pytest.raises(
        ModelError,
        match=r"<joint name='j1'>: type 'prismatic' is not supported; armkit arms have revolute",
    ):
        load_model(path)


def test_a_directory_is_no_model_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "arm.urdf").mkdir()
    with pytest.raises(ModelError, match=r"arm.urdf: is a directory; give a .urdf file"):
        load_model(tmp_path / "arm.urdf")
    with pytest.raises(ModelError, match=r": is a directory; give a .toml or .urdf file$"):
        load_model(tmp_path)
    assert main(["--arm", str(tmp_path), "show"]) == 2
    assert capsys.readouterr().err == (
        f"armkit: error: {tmp_path}: is a directory; give a .toml or .urdf file\n"
    )
