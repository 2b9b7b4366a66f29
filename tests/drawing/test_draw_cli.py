"""``armkit draw svg|gcode`` and the shapes in any plane: bad files and names are
one line, exit 2, nothing moved and nothing written (fuzzed, fixed seed)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, seed, settings
from hypothesis import strategies as st

from armkit.cli import main
from armkit.cli._draw import in_plane

CLI_FUZZ = settings(
    max_examples=25,
    deadline=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
)
GCODE = st.lists(
    st.sampled_from(["G1 X10 Y10", "G0 Z5", "G1 Z-1", "M3", "M5", "G2 X0 Y0 I5 J0", "T2",
                     "G1 X1e400", "(open", "G21", "G4 P-1", "Q7", "G1 X5 Y", "N10 G1 X2"]),
    max_size=6,
).map("\n".join)  # fmt: skip
SVG = st.sampled_from(
    [
        "<svg><path d='M 0 0 L 10'/></svg>",
        "<svg><path d='M 0 0 L 10 10'/>",
        "<svg viewBox='0 0 0 0'><rect width='5' height='5'/></svg>",
        "<svg><text>hi</text></svg>",
        "not xml",
        "<svg><polyline points='1,2 3'/></svg>",
        "<svg><g transform='rotate(x)'><line x2='5'/></g></svg>",
    ]
)


def _one_line_or_ok(code: int, err: str) -> None:
    assert code in (0, 2)
    lines = err.strip().splitlines()
    warned = [line for line in lines if line.startswith("armkit: warning: ")]
    if code == 2:
        assert lines[len(warned) :] == [lines[-1]] and lines[-1].startswith("armkit: error: ")


@seed(13)
@CLI_FUZZ
@given(text=GCODE)
def test_fuzzed_gcode_is_planned_or_refused_in_one_line(
    text: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    f = tmp_path / "f.gcode"
    f.write_text(text)
    code = main(["--scene", "drawing", "draw", "gcode", str(f), "--dry-run"])
    _one_line_or_ok(code, capsys.readouterr().err)


@seed(13)
@CLI_FUZZ
@given(text=SVG)
def test_fuzzed_svg_is_planned_or_refused_in_one_line(
    text: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    f = tmp_path / "f.svg"
    f.write_text(text)
    code = main(["--scene", "drawing", "draw", "svg", str(f), "--dry-run"])
    _one_line_or_ok(code, capsys.readouterr().err)


def _state(config_dir: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in config_dir.glob("sim_*.json")}


@pytest.mark.parametrize(
    "args,says",
    [
        (["svg", "BAD", "--sheet", "A5"], "BAD.svg:1:"),
        (["gcode", "BAD.gcode"], "BAD.gcode:2:1: "),
        (["svg", "GOOD", "--sheet", "A4"], "no sheet 'A4'"),
        (["svg", "GOOD", "--result", "no/such/r.png"], "does not exist"),
        (["svg", "GOOD", "--preview", "plan.txt"], "must end in"),
        (["gcode", "GOOD"], "takes .gcode"),
    ],
)
def test_bad_input_moves_nothing(
    args: list[str], says: str, tmp_path: Path, config_dir: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["move", "200", "0", "100"]) == 0  # a state file to compare
    (tmp_path / "BAD.svg").write_text("<svg><path d='M 0 0 L 10 Q'/></svg>")
    (tmp_path / "BAD.gcode").write_text("G21\nT2\n")
    (tmp_path / "GOOD.svg").write_text("<svg><line x1='0' y1='0' x2='10' y2='10'/></svg>")
    names = {"BAD": "BAD.svg", "GOOD": "GOOD.svg"}
    argv = [
        str(tmp_path / names.get(a, a)) if a in ("BAD", "BAD.gcode", "GOOD") else a for a in args
    ]
    argv = [str(tmp_path / a) if a.startswith("no/") else a for a in argv]
    before = _state(config_dir)
    capsys.readouterr()
    assert main(["--scene", "drawing", "draw", *argv]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and says in err[0]
    assert _state(config_dir) == before


def test_a_circle_in_a_wall_plane() -> None:
    pts = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]) * 30 + [200.0, 0.0, 120.0]
    out = in_plane(pts, [200.0, 0.0, 120.0], [1.0, 0.0, 0.0])
    assert np.allclose(out[:, 0], 200.0)  # in the plane x = 200
    assert np.allclose(np.linalg.norm(out - [200.0, 0.0, 120.0], axis=1), 30.0)
    assert main(["draw", "circle", "--center", "200", "0", "120", "--radius", "30",
                 "--normal", "0", "0", "0"]) == 2  # fmt: skip


def test_a_warning_is_one_armkit_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    svg = tmp_path / "t.svg"
    svg.write_text('<svg><text>hi</text><path d="M 0 0 L 10 10"/></svg>')
    code = main(["--scene", "drawing", "draw", "svg", str(svg), "--dry-run"])
    err = capsys.readouterr().err
    assert code == 0
    assert err.startswith("armkit: warning: ") and "text" in err and "Warning" not in err
