"""The WAV of a performance (issue 28 item 4): it was quiet (-18 to -22 dBFS) and
clicked 1.6 s after every note (each bar's sound cut off at a level). Now the whole
is normalised to a -1 dBFS peak and every sound fades to zero at its end."""

from __future__ import annotations

import numpy as np
import pytest

from armkit.music import Contact, render
from armkit.music._synth import RATE


def _contacts(speed: float) -> list[Contact]:
    return [
        Contact(0.0, "xylophone", 72, speed),
        Contact(0.25, "xylophone", 76, speed / 2),
        Contact(0.5, "snare", 38, speed, drum=True),
    ]


@pytest.mark.parametrize("speed", [0.05, 0.3, 2.0])
def test_the_peak_is_minus_one_dbfs_however_soft_the_strokes(speed: float) -> None:
    audio = render(_contacts(speed))
    peak_db = 20.0 * np.log10(np.max(np.abs(audio)))
    assert peak_db == pytest.approx(-1.0, abs=0.01)


def test_no_click_where_a_sound_ends() -> None:
    audio = render([Contact(0.0, "xylophone", 72, 0.3)], decay=0.4)
    end = round(1.6 * RATE)  # where the bar's sound ends (4 decay times)
    step = np.abs(np.diff(audio))
    ringing = step[round(0.5 * RATE) : round(0.6 * RATE)].max()  # the tone itself
    assert step[end - 50 : end + 50].max() < 0.05 * ringing  # smooth to silence
    assert np.all(audio[end + 1 :] == 0.0)
    assert abs(audio[end - 1]) < 1e-4
