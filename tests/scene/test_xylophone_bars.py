"""Xylophones bar by bar: the TOML form, its errors (file and field named), a fuzz of
bad tables (fixed seeds), and the shipped glockenspiel's layout."""

from __future__ import annotations

import math
import random
import re
from pathlib import Path

import numpy as np
import pytest

from armkit._errors import ArmkitError
from armkit.music import load_score
from armkit.music._listen import surfaces
from armkit.scene import SceneError, Xylophone, load_scene

TUNES = Path(__file__).parents[2] / "examples" / "music"
SHARPS = (1, 3, 6, 8, 10)
GOOD = """name = "t"
[[xylophones]]
name = "glock"
bar_size_mm = [60.0, 22.0]
bars = [
  { note = "C5", top_mm = [180.0, 25.0, 20.0] },
  { note = 74, top_mm = [180.0, 0.0, 20.0], size_mm = [58.0, 22.0] },
  { note = "C#5", top_mm = [250.0, 12.5, 32.0], row_deg = -80.0 },
]
"""


def _load(tmp_path: Path, text: str) -> Xylophone:
    path = tmp_path / "s.toml"
    path.write_text(text)
    xylo = load_scene(path).instruments[0]
    assert isinstance(xylo, Xylophone)
    return xylo


def test_bars_are_read_one_by_one_any_order(tmp_path: Path) -> None:
    xylo = _load(tmp_path, GOOD)
    assert xylo.notes == (72, 73, 74)
    assert xylo.bar_top(73) == pytest.approx([0.25, 0.0125, 0.032])
    assert xylo.bar_size(74) == pytest.approx((0.058, 0.022))
    assert xylo.bar_size(73) == pytest.approx((0.060, 0.022))
    assert xylo.bar_row(72) == pytest.approx(-math.pi / 2)  # lowest to highest bar
    assert xylo.bar_row(73) == pytest.approx(math.radians(-80.0))
    with pytest.raises(ValueError, match=r"no note 75 \(D#5\); it plays C5..D5"):
        xylo.bar_top(75)


def test_the_listener_sees_each_bar_where_it_is(tmp_path: Path) -> None:
    xylo = _load(tmp_path, GOOD)
    found = {s.note: s for s in surfaces([xylo])}
    sharp = found[73]
    assert sharp.centre == pytest.approx([0.25, 0.0125, 0.032])
    assert sharp.half == pytest.approx((0.011, 0.030))
    # 29 mm along the bar's length (its row at -80 deg): on it; 29 mm along x: off it
    length_dir = np.array([math.cos(math.radians(10.0)), math.sin(math.radians(10.0))])
    assert sharp.under(sharp.centre[:2] + 0.029 * length_dir)
    assert not found[72].under(found[72].centre[:2] + np.array([0.0, 0.012]))


BAD = [
    ("bars = 3", "xylophones[0].bars", "list of 1..88"),
    ("bars = []", "xylophones[0].bars", "list of 1..88"),
    ('bars = [{ note = "H5", top_mm = [0, 0, 0] }]', "bars[0].note", "note name like C4"),
    ("bars = [{ note = 128, top_mm = [0, 0, 0] }]", "bars[0].note", "0..127"),
    ("bars = [{ note = 60 }]", "bars[0].top_mm", "missing"),
    ("bars = [{ note = 60, top_mm = [0, 0] }]", "bars[0].top_mm", "list of 3"),
    ("bars = [{ note = 60, top_mm = [0, 0, 0], pitch = 1 }]", "bars[0].pitch", "unknown key"),
    (
        'bars = [{ note = 60, top_mm = [0, 0, 0] }, { note = "C4", top_mm = [0, 50, 0] }]',
        "bars[1].note",
        "C4 is already bars[0]",
    ),
    (
        "bars = [{ note = 60, top_mm = [0, 0, 0] }, { note = 61, top_mm = [0, 10, 0] }]",
        "xylophones[0].bars",
        "C4 and C#4 overlap",
    ),
    ("bars = [{ note = 60, top_mm = [0, 0, 0] }]", "xylophones[0].row_deg", "missing"),
    (
        "bars = [{ note = 60, top_mm = [0, 0, 0] }]\nbar_count = 3",
        "xylophones[0].bar_count",
        "either bars or",
    ),
]


@pytest.mark.parametrize(("body", "field", "message"), BAD)
def test_bad_bars_name_file_field_and_what_is_allowed(
    tmp_path: Path, body: str, field: str, message: str
) -> None:
    text = f'name = "t"\n[[xylophones]]\nname = "x"\nbar_size_mm = [40.0, 20.0]\n{body}\n'
    with pytest.raises(SceneError) as err:
        _load(tmp_path, text)
    assert str(tmp_path / "s.toml") in str(err.value)
    assert field in str(err.value) and message in str(err.value)


def test_a_bar_without_a_size_is_refused(tmp_path: Path) -> None:
    text = GOOD.replace("bar_size_mm = [60.0, 22.0]\n", "")
    with pytest.raises(SceneError, match=r"bars\[0\]\.size_mm': missing"):
        _load(tmp_path, text)


@pytest.mark.parametrize("seed", range(6))
def test_fuzzed_bars_load_or_fail_as_scene_errors(tmp_path: Path, seed: int) -> None:
    rng = random.Random(seed)
    junk = [0, -1, 200, 1.5, "C#4", "X9", True, [], [1, 2, 3], [1e9, 0, 0], {}, "nan"]
    for _ in range(40):
        bars = []
        for k in range(rng.randint(1, 4)):
            bar = {"note": 60 + k, "top_mm": [100.0, 30.0 * k, 20.0]}
            key = rng.choice(["note", "top_mm", "size_mm", "row_deg", "extra"])
            bar[key] = rng.choice(junk)
            bars.append(bar)
        items = ", ".join(
            "{ " + ", ".join(f"{k} = {_toml(v)}" for k, v in b.items()) + " }" for b in bars
        )
        text = f'name = "t"\n[[xylophones]]\nname = "x"\nbar_size_mm = [40.0, 20.0]\nrow_deg = 90\nbars = [{items}]\n'
        try:
            xylo = _load(tmp_path, text)
        except SceneError as err:
            assert re.search(r"s\.toml:\d+:\d+: field 'xylophones\[0\]", str(err)), str(err)
            assert "\n" not in str(err)
            continue
        except ArmkitError as err:  # pragma: no cover - a failure names the wrong kind
            pytest.fail(f"not a SceneError: {err!r}")
        assert list(xylo.notes) == sorted(set(xylo.notes)) and xylo.tops.shape[1] == 3


def _toml(value: object) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return f'"{value}"'
    if isinstance(value, dict):
        return "{}"
    return repr(value)


def test_the_shipped_glockenspiel_is_laid_out_like_a_real_one() -> None:
    (xylo,) = [i for i in load_scene("xylophone").instruments if isinstance(i, Xylophone)]
    naturals = [n for n in xylo.notes if n % 12 not in SHARPS]
    sharps = [n for n in xylo.notes if n % 12 in SHARPS]
    assert xylo.notes == tuple(range(naturals[0], naturals[-1] + 1))  # chromatic
    for n in xylo.notes:
        assert 0.020 <= xylo.bar_size(n)[1] <= 0.025  # bar width [m]
    gaps = [float(np.linalg.norm(np.diff([xylo.bar_top(n) for n in naturals], axis=0)[k])) for k in range(len(naturals) - 1)]  # fmt: skip
    assert all(0.023 <= g <= 0.027 for g in gaps)
    front = max(xylo.bar_top(n)[0] for n in naturals)
    for s in sharps:  # behind the naturals, raised, between its two neighbours
        top = xylo.bar_top(s)
        assert top[0] > front and 0.010 <= top[2] - xylo.bar_top(s - 1)[2] <= 0.015
        assert min(xylo.bar_top(s - 1)[1], xylo.bar_top(s + 1)[1]) < top[1]
        assert top[1] < max(xylo.bar_top(s - 1)[1], xylo.bar_top(s + 1)[1])
    for name in ("ode_to_joy.mid", "twinkle.rtttl", "frere_jacques.txt"):
        pitches = {n.pitch for n in load_score(TUNES / name).notes if not n.drum}
        assert pitches <= set(xylo.notes), name
