"""Issue 10, item 2: a model file is checked completely when it loads; the error
names the file, the field and the bound."""

from __future__ import annotations

import re
from importlib import resources
from pathlib import Path

import pytest

from armkit import ModelError
from armkit.model import load_model


def shipped(name: str) -> str:
    return (resources.files("armkit.model") / "arms" / f"{name}.toml").read_text()


def variant(tmp_path: Path, name: str, old: str, new: str, count: int = 1) -> Path:
    text = shipped(name)
    assert old in text, old
    path = tmp_path / f"{name}_variant.toml"
    path.write_text(text.replace(old, new, count))
    return path


@pytest.mark.parametrize(
    ("arm", "old", "new", "field", "words"),
    [
        ("owi535", "a_mm = 90.0", "a_mm = 0.0", "joints[2].dh", "on one axis"),
        ("openmanipulator_x", "a_mm = 124.0", "a_mm = 0.0", "joints[3].dh", "on one axis"),
        ("planar2", "a_mm = 500.0", "a_mm = 1e300", "joints[1].dh.a_mm", "must be 0..10000 mm"),
        ("lynx6", "a_mm = 120.65", "a_mm = -120.65", "joints[1].dh.a_mm", "must be 0..10000 mm"),
        ("lynx6", "a_mm = 120.65", "a_mm = 1e-300", "joints[1].dh.a_mm", "0 or at least 0.01 mm"),
        ("owi535", "length_mm = 110.0", "length_mm = -110.0", "tool.length_mm", "0..10000 mm"),
        ("owi535", "d_mm = 70.0", "d_mm = 1e300", "joints[0].dh.d_mm", "-10000..10000 mm"),
        ("owi535", "[-135.0, 135.0]", "[-1e300, 135.0]", "joints[0].limits_deg[0]", "-360..360"),
        ("owi535", "max_speed_dps = 17.6", "max_speed_dps = 1e300", "joints[0].max_speed_dps",
         "> 0 and <= 3600 deg/s"),
        ("lynx6", "width_mm = [0.0, 50.8]", "width_mm = [0.0, 1e9]", "gripper.width_mm[1]",
         "0..1000 mm"),
        ("owi535", 'traverse_s = { base = 15.3, shoulder = 13.0, elbow = 20.0, wrist = 8.0 }',
         'traverse_s = { base = 15.3, shoulder = 13.0, elbow = 20.0 }',
         "drivers.owi535.traverse_s.wrist", "missing (required)"),
        ("owi535", "gripper_s = 1.7", "", "drivers.owi535.gripper_s", "missing (required)"),
        ("owi535", "gripper_s = 1.7", 'gripper_s = "slow"', "drivers.owi535.gripper_s",
         "must be a number"),
        ("owi535", 'rehome_to = { wrist = "upper"', 'rehome_to = { wrist = "up"',
         "drivers.owi535.rehome_to.wrist", "lower, upper"),
        ("owi535", "wrist = 8.0 }", "wrist = 0.0 }", "drivers.owi535.traverse_s.wrist", "0.5..600"),
        ("openmanipulator_x", "ids = [11, 12, 13, 14]\n", "", "drivers.dynamixel.ids",
         "missing (required)"),
        ("openmanipulator_x", "ids = [11, 12, 13, 14]", "ids = [11, 12, 13]",
         "drivers.dynamixel.ids", "must list 4 servo IDs"),
        ("openmanipulator_x", "gripper_id = 15", "gripper_id = 14", "drivers.dynamixel",
         "must all differ"),
        ("openmanipulator_x", "baudrate = 1000000", "baudrate = 12345",
         "drivers.dynamixel.baudrate", "must be one of"),
        ("openmanipulator_x", "[drivers.dynamixel]", "[drivers.dynamixle]", "drivers.dynamixle",
         "unknown key"),
        ("lynx6", "channels = [0, 1, 2, 3, 4, 5]      # base, shoulder, elbow, wrist, hand, grip\n"
         "baudrate = 9600                   # as",
         "channels = [0, 1, 2, 3, 4, 99]\nbaudrate = 9600 # as",
         "drivers.ssc32.channels[5]", "0..31"),
        ("owi535", 'name = "owi535"', 'name = "x/../../evil/out"', "name", "letters, digits"),
        ("owi535", 'name = "base"', 'name = "base arm"', "joints[0].name", "letters, digits"),
    ],
)  # fmt: skip
def test_bad_fields_are_refused_at_load(
    tmp_path: Path, arm: str, old: str, new: str, field: str, words: str
) -> None:
    path = variant(tmp_path, arm, old, new)
    with pytest.raises(ModelError) as err:
        load_model(path)
    message = str(err.value)
    at = re.match(rf"{re.escape(str(path))}:(\d+):(\d+): field '{re.escape(field)}':", message)
    assert at is not None, message
    line = path.read_text().splitlines()[int(at[1]) - 1]  # its key, or the table holding it
    assert any(part in line for part in re.sub(r"\[\d+\]", "", field).split(".")), message
    assert words in message


def test_a_file_not_in_utf8_names_the_file(tmp_path: Path) -> None:
    path = tmp_path / "latin1.toml"
    path.write_bytes(shipped("owi535").replace("OWI-535", "OWI-535 \xe9").encode("latin-1"))
    with pytest.raises(
        ModelError, match=rf"^{re.escape(str(path))}:\d+:\d+: not UTF-8 text \(byte e9\)"
    ):
        load_model(path)


def test_a_name_cannot_write_outside_the_config_dir(
    tmp_path: Path,
    config_dir: Path,
    cli,  # type: ignore[no-untyped-def]
) -> None:
    path = variant(tmp_path, "openmanipulator_x", 'name = "openmanipulator_x"', 'name = "x/../../evil/out"')  # fmt: skip
    got = cli("--arm", str(path), "move", "200", "0", "100")
    assert got.one_line_refusal and "field 'name'" in got.err
    written = [p for p in tmp_path.rglob("*") if p.is_file() and p != path]
    assert written == []


def test_typed_driver_sections() -> None:
    from armkit.model import dynamixel_section, owi_section

    owi = owi_section(load_model("owi535"))
    assert owi.traverse_s["wrist"] == 8.0 and owi.rehome_to["elbow"] == "lower"
    assert owi.calibration_pose["shoulder"][0]["wrist"] == "upper"
    dxl = dynamixel_section(load_model("openmanipulator_x"))
    assert (
        dxl.ids == (11, 12, 13, 14) and dxl.gripper_id == 15 and dxl.gripper_ticks == (2483, 1613)
    )
    with pytest.raises(ModelError, match="not an OWI-535"):
        owi_section(load_model("lynx6"))


def test_a_hobby_servo_section_is_typed_and_its_settle_time_is_read(tmp_path: Path) -> None:
    # the servo driver builds its tables from the section the model checked at load
    # (it once re-read the raw table, and settle_ms, which it read, the model refused)
    from armkit.drivers.servo import load_setup
    from armkit.model import ServoSection, servo_section

    servos = servo_section(load_model("lynx6"), "ssc32")
    assert isinstance(servos, ServoSection) and servos.channels == (0, 1, 2, 3, 4, 5)
    assert servos.settle_ms == 100.0 and servos.center_deg == (90.0,) * 5
    old = "channels = [0, 1, 2, 3, 4, 5]"
    path = variant(tmp_path, "lynx6", old, f"settle_ms = 40\n{old}")
    assert load_setup(load_model(path), "ssc32").settle_s == pytest.approx(0.040)
    path = variant(tmp_path, "lynx6", old, f"settle_ms = 4000\n{old}")
    with pytest.raises(ModelError, match=r"settle_ms': must be 0\.\.2000 ms, got 4000"):
        load_model(path)


def test_every_shipped_model_still_loads() -> None:
    from armkit.model import shipped_models

    assert len([load_model(name) for name in shipped_models()]) >= 6
