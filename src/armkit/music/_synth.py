"""Hear what was played: a tone per bar (or a drum sound) at each contact, as
loud as the contact was fast, decaying like a struck bar; written as a WAV file
with Python's wave module. The whole is normalised to a peak of ``PEAK_DBFS``, and
every sound fades to silence over its last ``FADE_S`` (cut off at a level, a sound
ends with a step: a click)."""

from __future__ import annotations

import math
import wave
from collections.abc import Sequence
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from .._files import check_output_path
from ..scene import midi_note
from ._onsets import Contact

F64 = NDArray[np.float64]
RATE = 44100  # samples per second
FULL_SPEED = 0.5  # contact speed [m/s] that sounds at full loudness
PEAK_DBFS = -1.0  # the rendering's loudest sample [dB full scale]
FADE_S = 0.05  # [s] every sound's last part, faded to zero by a raised cosine
_XYLOPHONE_PARTIALS = (
    (1.0, 1.0, 1.0),
    (3.0, 0.3, 0.35),
    (6.0, 0.08, 0.2),
)  # ratio, level, decay share


def frequency(note: int) -> float:
    """Pitch [Hz] of MIDI ``note`` (A4 = 69 = 440 Hz)."""
    return float(440.0 * 2.0 ** ((midi_note(note) - 69) / 12.0))


def render(contacts: Sequence[Contact], rate: int = RATE, decay: float = 0.4, seed: int = 0) -> F64:
    """Mono audio [-1, 1], shape (N,), ``rate`` samples/s: every contact struck at its
    time, loudness ``min(speed / 0.5 m/s, 1)`` relative to the others, bars ringing with
    time constant ``decay`` [s], drums as a short pitched noise burst (seeded, so
    repeatable), each faded out at its end; the whole scaled to a ``PEAK_DBFS`` peak."""
    if rate < 8000 or not 0.01 <= decay <= 5.0:
        raise InputError(f"rate must be >= 8000 Hz and decay 0.01..5 s, got {rate}, {decay}")
    end = max((c.time for c in contacts), default=0.0) + 4.0 * decay + 0.2
    out = np.zeros(round(end * rate) + 1)
    rng = np.random.default_rng(seed)
    for c in sorted(contacts, key=lambda c: c.time):
        sound = _drum(c.note, rate, rng) if c.drum else _bar(c.note, rate, decay)
        start = round(max(c.time, 0.0) * rate)
        piece = sound[: len(out) - start] * min(max(c.speed, 0.0) / FULL_SPEED, 1.0)
        out[start : start + len(piece)] += piece
    peak = float(np.max(np.abs(out), initial=0.0))
    return out * (10.0 ** (PEAK_DBFS / 20.0) / peak) if peak > 0.0 else out


def _faded(sound: F64, rate: int) -> F64:
    """``sound`` with its last ``FADE_S`` going smoothly to zero (no step at its end)."""
    n = min(len(sound), round(FADE_S * rate))
    if n > 1:
        sound[-n:] *= 0.5 * (1.0 + np.cos(np.linspace(0.0, math.pi, n)))
    return sound


def _bar(note: int, rate: int, decay: float) -> F64:
    t = np.arange(round(4.0 * decay * rate)) / rate
    f0, attack = frequency(note), np.minimum(t / 0.002, 1.0)
    tone = sum(
        level * np.sin(2 * math.pi * f0 * ratio * t) * np.exp(-t / (decay * share))
        for ratio, level, share in _XYLOPHONE_PARTIALS
        if f0 * ratio < rate / 2
    )
    return _faded(np.asarray(0.3 * attack * tone, dtype=np.float64), rate)


def _drum(note: int, rate: int, rng: np.random.Generator) -> F64:
    t = np.arange(round(0.4 * rate)) / rate
    body = np.sin(2 * math.pi * frequency(note) * 1.5 * t) * np.exp(-t / 0.12)
    noise = rng.uniform(-1.0, 1.0, t.size) * np.exp(-t / 0.05)
    return _faded(np.asarray(0.3 * (0.7 * body + 0.5 * noise), dtype=np.float64), rate)


def write_wav(path: str | Path, samples: F64, rate: int = RATE) -> Path:
    """Write mono ``samples`` in [-1, 1] as a 16-bit PCM WAV file; the path written.
    InputError (nothing written) if ``path`` does not end in .wav or cannot be written."""
    out = check_output_path(path, suffixes=(".wav",))
    pcm = np.round(np.clip(samples, -1.0, 1.0) * 32767).astype("<i2")
    # the file is opened here, not by wave: wave.open(name) that fails to open it leaves
    # a half-made Wave_write whose __del__ prints a traceback
    with out.open("wb") as raw, wave.open(raw, "wb") as handle:
        handle.setnchannels(1)
        handle.setsampwidth(2)
        handle.setframerate(rate)
        handle.writeframes(pcm.tobytes())
    return out
