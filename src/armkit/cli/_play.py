"""``armkit --scene xylophone play FILE``: play a tune on the scene's instruments.

The whole piece is planned and checked (every note on a bar or drum, in reach,
clear of the table, reachable in time) and the output files are checked before
anything moves; in the simulator the contacts the mallet really makes are heard,
written as sound (``--wav``) and plotted against the plan (``--plot``).
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from .._errors import ArmkitError
from .._terminal import count
from ._jobs import add_job, job_arguments
from ._watch import watched_arm


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add ``play`` (from its job spec, ``armkit.script._jobs.JOBS["play"]``)."""
    add_job(sub, "play", _run)


def _run(args: argparse.Namespace) -> int:
    from .. import music
    from ._scene import scene_of

    scene = scene_of(args)
    outputs = _outputs(args)
    table = music.load_latency(args.latency) if args.latency else None
    with watched_arm(args, scene) as arm:
        if (args.wav or args.plot) and not args.dry_run and arm.world is None:
            raise ArmkitError(
                "--wav and --plot need the contacts the simulator hears; on hardware "
                "record the arm with a microphone instead (drop --wav/--plot)"
            )
        if "calibrate" in outputs:
            table = _calibrate(arm, scene, args, outputs["calibrate"], music)
            if args.file is None:
                return 0
        played = _play(arm, scene, args, table, music, dry_run=True)
        _say_plan(played.performance)
        if args.dry_run:
            _say_strikes(played.performance)
            return 0
        played = _play(arm, scene, args, table, music, dry_run=False)
    _report(played, outputs, music)
    return 0


def _play(arm: Any, scene: Any, args: argparse.Namespace, table: Any, music: Any, dry_run: bool) -> Any:  # fmt: skip
    return music.play(arm, scene, **job_arguments(args), dry_run=dry_run, latency=table)


def _calibrate(arm: Any, scene: Any, args: argparse.Namespace, out: Path, music: Any) -> Any:
    """Play the calibration pass, write its table to ``out``, say what it measured."""
    if args.file is not None and not args.dry_run:  # the piece is checked before the pass
        _play(arm, scene, args, None, music, dry_run=True)
    table = music.calibrate(arm, scene, args.on)
    music.save_latency(table, out)
    delays = [d * 1000 for _, d in table.delays] or [table.default * 1000]
    print(
        f"calibrated {len(table.delays)} bars and drums: onset delay {min(delays):.2f}.."
        f"{max(delays):.2f} ms; wrote {out}"
    )
    return table


def _outputs(args: argparse.Namespace) -> dict[str, Path]:
    """Every output path, checked before anything moves."""
    from .._files import check_output_path
    from ..music import PLOT_SUFFIXES as SUFFIXES

    out = {}
    if args.file is None and not args.calibrate:
        raise ArmkitError("play needs a score FILE (or --calibrate OUT.toml to measure the bars)")
    if args.calibrate:
        out["calibrate"] = check_output_path(args.calibrate, "--calibrate", (".toml",))
    if args.wav:
        out["wav"] = check_output_path(args.wav, "--wav", (".wav",))
    if args.plot:
        out["plot"] = check_output_path(args.plot, "--plot", SUFFIXES)
    return out


def _say_plan(perf: Any) -> None:
    strikes = perf.strikes
    end = strikes[-1].time if strikes else 0.0
    hovers = [s.hover * 1000 for s in strikes]
    print(
        f"{perf.source}: {count(len(strikes), 'strike')} in {end:.2f} s at tempo {perf.tempo * 100:g}%, "
        f"{count(len(perf.moves), 'servo command')}, hover {min(hovers, default=0):.0f}.."
        f"{max(hovers, default=0):.0f} mm; every note reachable in time"
    )


def _say_strikes(perf: Any) -> None:
    """One line per strike: when [s], what, where, hover [mm], predicted speed [m/s]."""
    for s in perf.strikes:
        note = s.target.note
        print(
            f"  {s.time:8.3f} s  {note.name:7s} on {s.target.instrument:10s} hover "
            f"{s.hover * 1000:4.1f} mm, contact at {s.speed:.2f} m/s"
        )


def _report(played: Any, outputs: dict[str, Path], music: Any) -> None:
    stats = played.stats
    if stats is None:
        print("played (no simulator: nothing listened)")
        return
    longest = max(played.dwell, default=0.0) * 1000
    print(
        f"heard {count(len(played.contacts), 'contact')}: onset error RMS {stats.rms * 1000:.2f} ms, "
        f"max {stats.max * 1000:.2f} ms, {len(stats.missed)} missed, {len(stats.extra)} "
        f"extra; longest on a bar {longest:.0f} ms"
    )
    if "wav" in outputs:
        path = music.write_wav(outputs["wav"], music.render(played.contacts))
        print(f"wrote {path}")
    if "plot" in outputs:
        path = music.plot_onsets(played.performance.contacts(), played.contacts, outputs["plot"])
        print(f"wrote {path}")
