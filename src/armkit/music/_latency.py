"""The per-bar latency table as a file, and the calibration pass that measures it.

A calibration pass strikes every bar and drum of the scene's instruments once,
one a second, at a steady loudness, and hears the contacts (the simulator's
``Listener``); each bar's mean delay between the planned and the heard contact
is added to the delay it was planned with (``LatencyTable.from_run``). The table
is written as TOML, delays in milliseconds::

    default_ms = 10.0          # a bar or drum not listed below
    [delays_ms.xylophone]      # one table per instrument, its name in the scene
    72 = 9.87                  # MIDI note (a drum's General MIDI number) = delay [ms]

Every error names the file, the line and the key, in one line.
"""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .._errors import ArmkitError
from .._files import check_output_path
from .._toml_files import read_toml
from ._onsets import LatencyTable
from ._score import Note, Score

if TYPE_CHECKING:
    from ..arm import Arm
    from ..scene import Scene

MAX_DELAY_MS = 500.0  # the largest delay a table may hold, either way [ms]
CALIBRATION_GAP_S = 1.0  # time between the strikes of a calibration pass [s]
CALIBRATION_VELOCITY = 96  # MIDI loudness of a calibration strike (mf..f)


class LatencyError(ArmkitError, ValueError):
    """A latency table file that cannot be read: names the file, line and key."""


def save_latency(table: LatencyTable, path: str | Path) -> Path:
    """Write ``table`` to ``path`` (TOML, delays [ms]); the Path written. InputError
    (nothing written) if ``path`` does not end in .toml or cannot be written."""
    out = check_output_path(path, suffixes=(".toml",))
    lines = [
        "# armkit per-bar latency table: onset delay of each bar [ms] from a calibration run",
        f"default_ms = {table.default * 1000:.3f}",
    ]
    for instrument in sorted({key[0] for key, _ in table.delays}):
        lines.append(f"\n[delays_ms.{_quoted(instrument)}]")
        for (name, note), delay in table.delays:
            if name == instrument:
                lines.append(f"{note} = {delay * 1000:.3f}")
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return out


def _quoted(name: str) -> str:
    return name if re.fullmatch(r"[A-Za-z0-9_-]+", name) else '"' + name.replace('"', '\\"') + '"'


def load_latency(path: str | Path) -> LatencyTable:
    """The table in ``path`` (see the module doc). Raises LatencyError naming the file,
    line and key of the first problem."""
    file = Path(path)
    data, text = read_toml(file, LatencyError, "latency table")
    lines = text.splitlines()
    for key in data:
        if key not in ("default_ms", "delays_ms"):
            _fail(file, lines, key, "", "unknown key; a table has default_ms and [delays_ms.NAME]")
    default = _delay(file, lines, "default_ms", "", data.get("default_ms", 0.0))
    delays = []
    tables = data.get("delays_ms", {})
    if not isinstance(tables, dict):
        _fail(file, lines, "delays_ms", "", "must be tables [delays_ms.INSTRUMENT]")
    for name, table in tables.items():
        if not isinstance(table, dict):
            _fail(file, lines, name, "", "must be a table of note = delay_ms")
        for note, value in table.items():
            if not re.fullmatch(r"\d{1,3}", note) or int(note) > 127:
                _fail(file, lines, note, name, "a bar is its MIDI note number 0..127")
            delays.append(((name, int(note)), _delay(file, lines, note, name, value)))
    return LatencyTable(tuple(sorted(delays)), default)


def _delay(file: Path, lines: list[str], key: str, section: str, value: Any) -> float:
    """``value`` [ms] as seconds, or LatencyError."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        _fail(file, lines, key, section, f"must be a number of milliseconds, got {value!r}")
    if abs(value) > MAX_DELAY_MS:
        _fail(
            file,
            lines,
            key,
            section,
            f"{value} ms is outside -{MAX_DELAY_MS:g}..{MAX_DELAY_MS:g} ms",
        )
    return float(value) / 1000.0


def _fail(file: Path, lines: list[str], key: str, section: str, problem: str) -> None:
    """Raise LatencyError at the line where ``key`` is written (in ``[delays_ms.section]``)."""
    name = f"delays_ms.{section}.{key}" if section else key
    raise LatencyError(f"{file}:{_line(lines, key, section)}: {name}: {problem}")


def _line(lines: list[str], key: str, section: str) -> int:
    """1-based line of ``key`` (under the header naming ``section``, if any); 1 if not found."""
    inside = not section
    for number, line in enumerate(lines, 1):
        text = line.split("#", 1)[0].strip()
        if text.startswith("["):
            inside = not section or section in text
            if not section and key in text:
                return number
            continue
        if inside and re.match(rf'^"?{re.escape(key)}"?\s*=', text):
            return number
    return 1


def calibration_score(scene: Scene, on: str | None = None) -> Score:
    """One strike on every bar and drum of the scene's instruments (only ``on``, if
    given), ``CALIBRATION_GAP_S`` apart: the calibration pass. From the lowest bar,
    each next strike is on the nearest surface not yet struck (a glockenspiel's front
    row, then its back row, then the drums), so no move crosses the whole layout."""
    from ._listen import surfaces
    from ._play import instruments

    left = list(surfaces(instruments(scene, on)))
    order = [left.pop(0)]
    while left:
        here = order[-1].centre
        order.append(left.pop(min(range(len(left)), key=lambda k: math.dist(left[k].centre, here))))
    notes = tuple(
        Note(k * CALIBRATION_GAP_S, s.note, CALIBRATION_VELOCITY, CALIBRATION_GAP_S, s.drum)
        for k, s in enumerate(order)
    )
    return Score(notes, "calibration pass")


def calibrate(arm: Arm, scene: Scene, on: str | None = None) -> LatencyTable:
    """Play the calibration pass and return the table it measures (the simulator's
    Listener hears the contacts). Raises ArmkitError on an arm with no simulator (no
    contacts to measure) before anything moves."""
    from ._play import play

    if arm.world is None:
        raise ArmkitError(
            "--calibrate measures the contacts the simulator hears; this arm has no "
            "simulator: calibrate the same arm and scene without --driver/--port, then --latency FILE"
        )
    played = play(arm, scene, calibration_score(scene, on))
    return LatencyTable.from_run(played.performance.contacts(), played.contacts, played.latency)
