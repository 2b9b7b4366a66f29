"""Listening and measuring: WAV rendering, onset statistics, latency tables, plots."""

from __future__ import annotations

import wave
from pathlib import Path

import numpy as np
import pytest

from armkit import ArmkitError
from armkit.music import (
    Contact,
    LatencyTable,
    frequency,
    onset_stats,
    plot_onsets,
    render,
    write_wav,
)

RATE = 22050


def _dominant(samples: np.ndarray, start: float, rate: int = RATE) -> float:
    """Strongest frequency [Hz] in the 0.1 s after ``start`` [s]."""
    piece = samples[round(start * rate) : round((start + 0.1) * rate)]
    spectrum = np.abs(np.fft.rfft(piece * np.hanning(piece.size)))
    return float(np.fft.rfftfreq(piece.size, 1 / rate)[np.argmax(spectrum)])


def test_each_contact_sounds_its_bar_at_its_time() -> None:
    contacts = [Contact(0.2, "x", 69, 0.4), Contact(0.8, "x", 76, 0.4)]
    audio = render(contacts, rate=RATE, decay=0.2)
    assert np.max(np.abs(audio[: round(0.199 * RATE)])) == 0.0  # silence before the first hit
    assert _dominant(audio, 0.2) == pytest.approx(440.0, rel=0.03)
    assert _dominant(audio, 0.8) == pytest.approx(frequency(76), rel=0.03)


def test_loudness_follows_contact_speed() -> None:
    both = render([Contact(0.1, "x", 72, 0.1), Contact(2.1, "x", 72, 0.4)], rate=RATE)
    soft, loud = both[: round(2.0 * RATE)], both[round(2.1 * RATE) :]
    assert np.max(np.abs(loud)) == pytest.approx(4 * np.max(np.abs(soft)), rel=1e-6)


def test_drums_are_noisy_and_repeatable() -> None:
    hit = [Contact(0.1, "snare", 38, 0.5, drum=True)]
    a, b = render(hit, rate=RATE), render(hit, rate=RATE)
    assert np.array_equal(a, b)
    piece = a[round(0.1 * RATE) : round(0.15 * RATE)]
    # ten times the zero crossings of its tone: noise
    assert np.mean(np.abs(np.diff(np.sign(piece))) > 0) > 0.05


def test_wav_file_round_trip(tmp_path: Path) -> None:
    audio = render([Contact(0.05, "x", 81, 0.5)], rate=RATE)
    path = write_wav(tmp_path / "out.wav", audio, RATE)
    with wave.open(str(path)) as handle:
        assert (handle.getnchannels(), handle.getsampwidth(), handle.getframerate()) == (1, 2, RATE)
        data = np.frombuffer(handle.readframes(handle.getnframes()), dtype="<i2")
    assert data.size == audio.size
    assert np.max(np.abs(data / 32767 - audio)) < 1e-4


@pytest.mark.parametrize(
    ("name", "problem"),
    [
        ("missing/out.wav", "does not exist"),
        ("out.mp3", "must end in .wav"),
        (".", "is a directory"),
    ],
)
def test_bad_output_paths_are_refused_before_anything(
    tmp_path: Path, name: str, problem: str
) -> None:
    with pytest.raises(ArmkitError, match=problem):
        write_wav(tmp_path / name, np.zeros(10), RATE)


def test_a_wav_that_cannot_be_opened_leaves_no_half_made_writer(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The file is opened before wave sees it: a failed open is one OSError, with no
    'Exception ignored in: Wave_write.__del__' traceback afterwards."""
    import gc
    import sys

    with pytest.raises(ArmkitError, match=r"does not take new files|does not exist"):
        write_wav(
            "/proc/x.wav" if Path("/proc").is_dir() else tmp_path / "no" / "x.wav", np.zeros(10)
        )
    ignored: list[object] = []
    monkeypatch.setattr(sys, "unraisablehook", ignored.append)
    monkeypatch.setattr("armkit.music._synth.check_output_path", lambda path, suffixes: Path(path))
    with pytest.raises(OSError):  # a folder that vanished after the check
        write_wav(tmp_path / "gone" / "x.wav", np.zeros(10))
    gc.collect()
    assert ignored == []


def test_onset_statistics_match_by_bar() -> None:
    planned = [Contact(1.0, "x", 60), Contact(2.0, "x", 62), Contact(3.0, "x", 60)]
    played = [
        Contact(1.002, "x", 60),
        Contact(2.0, "x", 64),
        Contact(2.996, "x", 60),
        Contact(5.0, "x", 60),
    ]
    stats = onset_stats(planned, played)
    assert stats.errors == pytest.approx((0.002, -0.004))
    assert stats.rms == pytest.approx(np.sqrt((0.002**2 + 0.004**2) / 2))
    assert stats.max == pytest.approx(0.004)
    assert [c.note for c in stats.missed] == [62]
    assert sorted((c.note, c.time) for c in stats.extra) == [(60, 5.0), (64, 2.0)]
    assert [(r.key, r.count) for r in stats.per_note] == [(("x", 60), 2)]


def test_a_calibration_run_cancels_each_bars_delay() -> None:
    planned = [Contact(t, "x", n) for t, n in [(1.0, 60), (2.0, 62), (3.0, 60), (4.0, 62)]]
    played = [Contact(c.time + (0.010 if c.note == 60 else 0.004), "x", c.note) for c in planned]
    table = LatencyTable.from_run(planned, played)
    assert table.of(("x", 60)) == pytest.approx(0.010) and table.of(("x", 62)) == pytest.approx(
        0.004
    )
    assert table.default == pytest.approx(0.007)
    # a second run, planned with the table, that is now 1 ms early on bar 60:
    again = LatencyTable.from_run(
        planned, [Contact(c.time - 0.001, "x", c.note) for c in planned[::2]], table
    )
    assert again.of(("x", 60)) == pytest.approx(0.009) and again.of(("x", 62)) == pytest.approx(
        0.004
    )


def test_plot_of_planned_against_played(tmp_path: Path) -> None:
    planned = [Contact(t, "x", 60 + i) for i, t in enumerate([0.5, 1.0, 1.5])]
    played = [Contact(c.time + 0.003, "x", c.note) for c in planned]
    path = plot_onsets(planned, played, tmp_path / "onsets.png")
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(ArmkitError, match="must end in"):
        plot_onsets(planned, played, tmp_path / "onsets.txt")


def test_importing_music_loads_no_plotting_or_midi_library() -> None:
    import subprocess
    import sys

    code = "import sys, armkit.music; print(sorted(m for m in sys.modules if m.split('.')[0] in ('matplotlib', 'mido', 'scipy')))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"
