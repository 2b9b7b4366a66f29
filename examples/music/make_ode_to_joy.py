"""Write ode_to_joy.mid: the opening of Beethoven's "Ode to Joy" (public domain),
four bars with the first beat of each accented, a ritardando (a tempo change) in
the last bar and a closing snare hit on channel 10 (one stick plays both, so the
drum comes after the melody, never with it). Re-running it rewrites the same bytes.

Run: .venv/bin/python examples/music/make_ode_to_joy.py
"""

from __future__ import annotations

from pathlib import Path

import mido

BEAT = 480  # ticks per quarter note
TUNE = (  # (note, beats): E E F G | G F E D | C C D E | E. D D (half)
    "E5 E5 F5 G5 G5 F5 E5 D5 C5 C5 D5 E5 E5 D5 D5",
    (1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1.5, 0.5, 2),
)
STEPS = {"C": 0, "D": 2, "E": 4, "F": 5, "G": 7, "A": 9, "B": 11}


def midi_number(name: str) -> int:
    return 12 * (int(name[1:]) + 1) + STEPS[name[0]]


def events() -> list[tuple[int, mido.Message | mido.MetaMessage]]:
    """(absolute tick, message): the melody, the closing snare, the tempo map."""
    out: list[tuple[int, mido.Message | mido.MetaMessage]] = [
        (0, mido.MetaMessage("track_name", name="Ode to Joy (Beethoven)")),
        (0, mido.MetaMessage("set_tempo", tempo=mido.bpm2tempo(100))),
        (0, mido.MetaMessage("time_signature", numerator=4, denominator=4)),
    ]
    tick = 0
    names, beats = TUNE
    for i, (name, length) in enumerate(zip(names.split(), beats, strict=True)):
        velocity = 96 if i % 4 == 0 else 72
        out.append((tick, mido.Message("note_on", note=midi_number(name), velocity=velocity)))
        end = tick + round(length * BEAT)
        out.append((end, mido.Message("note_on", note=midi_number(name), velocity=0)))
        tick = end
    out.append((tick, mido.Message("note_on", channel=9, note=38, velocity=110)))
    out.append((tick + BEAT // 2, mido.Message("note_off", channel=9, note=38)))
    out.append((12 * BEAT, mido.MetaMessage("set_tempo", tempo=mido.bpm2tempo(70))))
    return out


def build() -> mido.MidiFile:
    """The tune as a type 1 MIDI file with one track."""
    track = mido.MidiTrack()
    last = 0
    for tick, msg in sorted(events(), key=lambda e: (e[0], e[1].type != "set_tempo")):
        track.append(msg.copy(time=tick - last))
        last = tick
    track.append(mido.MetaMessage("end_of_track", time=0))
    return mido.MidiFile(type=1, ticks_per_beat=BEAT, tracks=[track])


def main() -> None:
    path = Path(__file__).with_name("ode_to_joy.mid")
    build().save(path)
    print(f"wrote {path} ({path.stat().st_size} bytes)")


if __name__ == "__main__":
    main()
