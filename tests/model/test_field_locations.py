"""A field error of a model or scene file says FILE:LINE:COL where the field is written
(issue 33 item 4): its key, else the table that holds it, else the array's first table;
a field that is nowhere written leaves the error about the whole file (FILE:)."""

from __future__ import annotations

from pathlib import Path

import pytest

import armkit.model
from armkit import ModelError
from armkit._toml_where import locate
from armkit.model import load_model

ARMS = Path(armkit.model.__file__).parent / "arms"

TEXT = """\
name = "x"
[[joints]]
name = "a"
limits_deg = [-90, 90]

[[joints]]
  name = "b"
  frame = { xyz_mm = [0, 0, 1] }
[gripper.jaws]
width_mm = 3
"""


@pytest.mark.parametrize(
    ("field", "at"),
    [
        ("name", (1, 1)),
        ("joints", (2, 1)),
        ("joints[0].limits_deg", (4, 1)),
        ("joints[0].limits_deg[1]", (4, 1)),
        ("joints[1]", (6, 1)),
        ("joints[1].name", (7, 3)),
        ("joints[1].frame.xyz_mm", (8, 3)),
        ("joints[1].home_deg", (6, 1)),  # not written: its table
        ("gripper.jaws.width_mm", (10, 1)),
        ("gripper.jaws.depth_mm", (9, 1)),
        ("tool", (0, 0)),  # nowhere: the whole file
    ],
)
def test_a_field_is_found_where_it_is_written(field: str, at: tuple[int, int]) -> None:
    assert locate(TEXT, field) == at


def test_a_model_file_error_names_the_line_of_the_field(tmp_path: Path) -> None:
    lines = (ARMS / "lynx6.toml").read_text().splitlines()
    k = lines.index('name = "shoulder"') + 1  # the second joint's limits, upside down
    assert lines[k].startswith("limits_deg = ")
    lines[k] = "limits_deg = [90.0, -90.0]"
    path = tmp_path / "bad.toml"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(ModelError) as refused:
        load_model(path)
    assert str(refused.value).startswith(f"{path}:{k + 1}:1: field 'joints[1].limits_deg'")
