"""Xylophones and drums made in code are checked as a scene file's are: MIDI notes
0..127, sizes more than 0 and at most 10 m, finite positions. Was:
``Xylophone.interpolated(lowest_note=200)``, ``Drum(note=1000)`` and ``Drum(radius=0)``
were accepted."""

from __future__ import annotations

import math

import numpy as np
import pytest

from armkit import InputError
from armkit.scene import Drum, Xylophone

FIRST, LAST = np.array([0.2, -0.1, 0.05]), np.array([0.2, 0.1, 0.05])
HERE = np.array([0.15, 0.15, 0.0])


def _xylo(**change: object) -> Xylophone:
    args: dict[str, object] = {
        "name": "x", "first_bar": FIRST, "last_bar": LAST, "lowest_note": 72, "bar_count": 8,
        "bar_size": (0.06, 0.02),
    }  # fmt: skip
    args.update(change)
    return Xylophone.interpolated(**args)  # type: ignore[arg-type]


@pytest.mark.parametrize(
    "change, message",
    [
        ({"lowest_note": 200}, r"x: lowest_note must be a MIDI note 0\.\.127 \(60 = C4\), got 200"),
        ({"lowest_note": -1}, r"x: lowest_note must be a MIDI note 0\.\.127"),
        ({"lowest_note": 72.0}, r"x: lowest_note must be a MIDI note number, an integer"),
        ({"lowest_note": "C5"}, r"for a note name use armkit\.music\.parse_pitch"),
        ({"lowest_note": 125}, r"x: bar_count must be 1\.\.3 from lowest_note 125 \(F9\).*got 8"),
        ({"bar_count": 0}, r"x: bar_count must be 1\.\.56"),
        ({"bar_count": 2.5}, r"x: bar_count must be a whole number >= 1, got 2\.5"),
        ({"bar_size": (0.0, 0.02)}, r"x: bar_size\[0\] \(the length across the row\) must be more than 0 and at most 10 m"),
        ({"bar_size": (0.06, 20)}, r"x: bar_size\[1\] .*got 20 m \(20000\.0 mm\); is 20 in mm\? give 0\.02"),
        ({"bar_size": (0.06,)}, r"x: bar_size must have shape \(2,\)"),
        ({"first_bar": [0.2, math.nan, 0.05]}, r"x: first_bar must be finite"),
    ],
)  # fmt: skip
def test_an_interpolated_xylophone_out_of_midi_or_size_is_refused(
    change: dict[str, object], message: str
) -> None:
    with pytest.raises(InputError, match=message):
        _xylo(**change)


def test_a_xylophone_given_bar_by_bar_is_checked_too() -> None:
    tops, rows = np.tile(FIRST, (2, 1)), np.zeros(2)
    with pytest.raises(InputError, match=r"x: notes\[1\] must be a MIDI note 0\.\.127"):
        Xylophone("x", (60, 128), tops, np.full((2, 2), 0.02), rows)
    with pytest.raises(InputError, match=r"x: the width of bar 1 must be more than 0"):
        Xylophone("x", (60, 61), tops, np.array([[0.06, 0.02], [0.06, -0.02]]), rows)
    with pytest.raises(InputError, match=r"x: rows must be finite"):
        Xylophone("x", (60, 61), tops, np.full((2, 2), 0.02), np.array([0.0, math.inf]))
    assert Xylophone("x", (0, 127), tops, np.full((2, 2), 0.02), rows).notes == (0, 127)
    assert _xylo(lowest_note=120, bar_count=8).notes[-1] == 127


@pytest.mark.parametrize(
    "change, message",
    [
        ({"note": 1000}, r"d: note must be a MIDI note 0\.\.127 \(General MIDI percussion: 38 = snare\), got 1000"),
        ({"note": -1}, r"d: note must be a MIDI note 0\.\.127"),
        ({"note": True}, r"d: note must be a MIDI note number, an integer"),
        ({"radius": 0}, r"d: radius must be more than 0 and at most 10 m, given in metres, got 0 m \(0\.0 mm\)$"),
        ({"radius": -0.06}, r"d: radius must be more than 0"),
        ({"radius": 60}, r"d: radius .*got 60 m \(60000\.0 mm\); is 60 in mm\? give 0\.06"),
        ({"radius": math.nan}, r"d: radius .*got nan"),
        ({"radius": "0.06"}, r"d: radius .*got '0\.06'"),
        ({"top_z": math.inf}, r"d: top_z must be a height within 10 m of the table"),
        ({"position": [0.15, 0.15]}, r"d: position must have shape \(3,\)"),
    ],
)  # fmt: skip
def test_a_drum_out_of_midi_or_size_is_refused(change: dict[str, object], message: str) -> None:
    args: dict[str, object] = {
        "name": "d",
        "position": HERE,
        "radius": 0.06,
        "top_z": 0.08,
        "note": 38,
    }
    args.update(change)
    with pytest.raises(InputError, match=message):
        Drum(**args)  # type: ignore[arg-type]


def test_a_plausible_drum_is_kept_as_given() -> None:
    drum = Drum("snare", HERE, 0.06, 0.08, 38)
    assert drum.radius == 0.06 and drum.note == 38 and drum.position is HERE
    assert drum.head == pytest.approx([0.15, 0.15, 0.08])
    assert Drum("big", HERE, 10.0, 0.0, 0).note == 0
