"""Model files: every shipped arm loads; every kind of mistake names the file and the field."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from armkit import ModelError, load_model
from armkit.model import shipped_models

GOOD = """
name = "mini"
dh_convention = "modified"
[[joints]]
name = "a"
limits_deg = [-90, 90]
home_deg = 0
dh = { a_mm = 0, alpha_deg = 0, d_mm = 50 }
[[joints]]
name = "b"
limits_deg = [-90, 90]
home_deg = 10
dh = { a_mm = 0, alpha_deg = -90, d_mm = 0 }
[tool]
length_mm = 100
"""


def test_shipped_models_load() -> None:
    names = shipped_models()
    for name in ("owi535", "openmanipulator_x", "lynx6", "planar2"):
        assert name in names
        m = load_model(name)
        assert m.name == name and m.dof == len(m.dh) >= 2
        assert all(j.lower < j.upper for j in m.joints)


def test_units_are_converted(tmp_path: Path) -> None:
    p = tmp_path / "mini.toml"
    p.write_text(GOOD)
    m = load_model(p)
    assert m.joint_names == ("a", "b")
    assert math.isclose(m.dh[0].d, 0.05) and math.isclose(m.joints[1].home, math.radians(10))
    assert math.isclose(m.T_flange_tool[0, 3], 0.1)


@pytest.mark.parametrize(
    ("edit", "field", "allowed"),
    [
        (
            lambda s: s.replace('name = "a"', 'name = "a"\ncolour = "red"'),
            "joints[0].colour",
            "allowed",
        ),
        (lambda s: s.replace('dh_convention = "modified"\n', ""), "dh_convention", "missing"),
        (
            lambda s: s.replace("[-90, 90]", "[90, -90]", 1),
            "joints[0].limits_deg",
            "min must be < max",
        ),
        (
            lambda s: s.replace("home_deg = 0", 'home_deg = "zero"', 1),
            "joints[0].home_deg",
            "must be a number",
        ),
        (
            lambda s: s.replace('"modified"', '"craig"'),
            "dh_convention",
            "'standard', 'modified' or 'frames'",
        ),
        (lambda s: s.replace(", d_mm = 50 }", " }"), "joints[0].dh.d_mm", "missing"),
        (
            lambda s: s.replace("home_deg = 10", "home_deg = 100"),
            "joints[1].home_deg",
            "outside limits",
        ),
        (
            lambda s: s.replace("length_mm = 100", "length_mm = [1]"),
            "tool.length_mm",
            "must be a number",
        ),
    ],
)
def test_errors_name_file_field_and_rule(tmp_path: Path, edit, field: str, allowed: str) -> None:  # type: ignore[no-untyped-def]
    p = tmp_path / "bad.toml"
    p.write_text(edit(GOOD))
    with pytest.raises(ModelError) as exc:
        load_model(p)
    msg = str(exc.value)
    assert str(p) in msg and f"'{field}'" in msg and allowed in msg


def test_not_toml_and_unknown_name(tmp_path: Path) -> None:
    p = tmp_path / "broken.toml"
    p.write_text("name = [")
    with pytest.raises(ModelError, match="not valid TOML"):
        load_model(p)
    with pytest.raises(ModelError, match=r"shipped arms are .*owi535"):
        load_model("owi536")
    with pytest.raises(ModelError, match="no such model file"):
        load_model(tmp_path / "missing.toml")


def test_link_radii_and_table(tmp_path: Path) -> None:
    from armkit import load_model

    omx = load_model("openmanipulator_x")
    assert len(omx.link_radii) == omx.dof + 1 and omx.table_z == 0.0
    text = (
        Path(str(omx.source))
        .read_text()
        .replace("[links]\nradius_mm = [25.0, 15.0, 15.0, 15.0, 15.0]", "[links]\nradius_mm = 12\n")
    )
    f = tmp_path / "m.toml"
    f.write_text("table_z_mm = -5\n" + text)
    m = load_model(f)
    assert m.link_radii == (0.012,) * 5 and m.table_z == pytest.approx(-0.005)
    f.write_text(text.replace("radius_mm = 12", "radius_mm = [1, 2]"))
    with pytest.raises(ModelError, match=r"links.radius_mm.*5 numbers"):
        load_model(f)
    f.write_text(text.replace("radius_mm = 12", "radius_mm = -1"))
    with pytest.raises(ModelError, match=r"links.radius_mm\[0\]"):
        load_model(f)
