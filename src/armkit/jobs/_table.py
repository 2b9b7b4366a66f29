"""The table of jobs: one ``JobSpec`` each (``_spec``), read by the script's grammar,
checker and runner (``armkit.script._jobs``) and by the CLI (``armkit.cli._jobs``)."""

from __future__ import annotations

from . import _calls as calls
from . import _calls as checks
from ._options import (
    ANGLES,
    CUBE,
    DRAW_EPILOG,
    DRAW_FORMS,
    DRAW_OPTIONS,
    DRAW_SUFFIXES,
    PICK_HINT,
    PITCH,
    PLAY_EPILOG,
    PLAY_OPTIONS,
    PLAY_SUFFIXES,
    REACH,
    SEARCH,
    SENSOR_OPTIONS,
    STACK_ON,
    TASK_OPTIONS,
    TASKS_EPILOG,
    TO,
    TO_HELP,
)
from ._spec import JobParam, JobSpec

JOBS: dict[str, JobSpec] = {
    "pick": JobSpec(
        (JobParam("cube", "object", hint=PICK_HINT, help=CUBE), PITCH, *TASK_OPTIONS),
        calls.pick,
        "pick a cube of the scene up by its name and stay above it (001: from the top "
        "where reachable, else the side)",
        check=checks.check_pick,
        plans=True,
        epilog=TASKS_EPILOG,
    ),
    "place": JobSpec(
        (
            JobParam(
                "cube",
                "object",
                help="the cube in the gripper (a script: the one it picked)",
                surface="cli",
            ),
            TO,
            PITCH,
            *TASK_OPTIONS,
        ),
        calls.place,
        "put the picked cube down at a scene place, board[ROW,COL], a cube, a container, "
        "a pose or an xyz point",
        check=checks.check_place,
        plans=True,
        epilog=TASKS_EPILOG + TO_HELP,
    ),
    "move-item": JobSpec(
        (
            JobParam("item", "where", help=CUBE, metavar="CUBE"),
            JobParam("to", "where", keyword="to", point="--xyz", help=TO.help),
            JobParam(
                "lift",
                "length",
                option="--lift",
                required=False,
                surface="cli",
                default=40.0,
                low=0.0,
                high=300.0,
                help="lift before travelling",
            ),
            PITCH,
            *TASK_OPTIONS,
        ),
        calls.move_item,
        "000's moveItem: pick an item up, lift it, carry it and put it down",
        check=checks.check_move_item,
        plans=True,
        epilog=TASKS_EPILOG + TO_HELP,
    ),
    "rotate-cube": JobSpec(
        (
            JobParam("cube", "object", help=CUBE),
            JobParam(
                "direction",
                "choice",
                required=False,
                choices=("forward", "backward"),
                default="forward",
                help="forward: pick from the side, put down from the top; backward: the other way",
            ),
            *TASK_OPTIONS,
        ),
        calls.rotate_cube,
        "001: turn a cube onto its side (forward) or back up (backward) where it stands",
        check=checks.check_rotate_cube,
        plans=True,
        epilog=TASKS_EPILOG,
    ),
    "stack": JobSpec(
        (
            JobParam(
                "cubes", "objects", metavar="CUBE", help="two or more cubes, the first stays below"
            ),
            JobParam(
                "rotate_first",
                "choice",
                option="--rotate",
                required=False,
                surface="cli",
                choices=("forward", "backward", "none"),
                default="forward",
                help="how to turn them first",
            ),
            *TASK_OPTIONS,
        ),
        calls.stack,
        "001: turn every cube in place, then stack them on the first, each on the one before",
        check=checks.check_stack,
        plans=True,
        refused=(("on", STACK_ON),),
        epilog=TASKS_EPILOG,
    ),
    "search": JobSpec(
        (
            JobParam(
                "start",
                "angle",
                keyword="from",
                option="--from",
                required=False,
                default=30.0,
                help="first scan angle",
            ),
            JobParam(
                "stop",
                "angle",
                keyword="to",
                option="--to",
                required=False,
                default=120.0,
                help="last scan angle",
            ),
            JobParam(
                "step",
                "angle",
                keyword="step",
                option="--step",
                required=False,
                default=5.0,
                help="coarse step of the scan angle",
            ),
            JobParam(
                "into",
                "object",
                keyword="into",
                option="--into",
                required=False,
                metavar="NAME",
                help="the container to drop it in (default: the scene's only one)",
            ),
            *SENSOR_OPTIONS,
        ),
        calls.search,
        "002: scan with the distance sensor, pick up what is found, drop it in a container",
        check=checks.check_search,
        epilog=ANGLES.strip() + " " + SEARCH,
    ),
    "draw": JobSpec(
        (
            JobParam("file", "file", choices=DRAW_SUFFIXES, metavar="FILE", help="the drawing"),
            JobParam(
                "sheet",
                "object",
                keyword="on",
                option="--sheet",
                required=False,
                metavar="NAME",
                help="the scene's sheet (default: its only one)",
            ),
            JobParam(
                "pen",
                "object",
                keyword="with",
                option="--pen",
                required=False,
                metavar="NAME",
                help="the scene's pen (default: its only one)",
            ),
            JobParam(
                "fit",
                "flag",
                keyword="fit",
                option="--fit",
                required=False,
                help="scale the drawing to fill the sheet inside the margins (default: the file's real size from its units, viewBox and width/height, centred on the sheet)",
            ),
            *DRAW_OPTIONS,
        ),
        calls.draw,
        "draw an SVG or G-code file on a sheet at its real size (fit: scaled to the sheet), "
        "picking the pen up and putting it back",
        check=checks.check_draw,
        epilog=DRAW_EPILOG,
        cli_forms=DRAW_FORMS,
    ),
    "play": JobSpec(
        (
            JobParam(
                "file",
                "file",
                choices=PLAY_SUFFIXES,
                metavar="FILE",
                cli_optional=True,
                help="the score (.mid, .midi, .rtttl, .txt); optional with --calibrate",
            ),
            JobParam(
                "on",
                "object",
                keyword="on",
                option="--on",
                required=False,
                metavar="NAME",
                help="play on this instrument only (its scene name)",
            ),
            JobParam(
                "tempo",
                "percent",
                keyword="tempo",
                option="--tempo",
                required=False,
                default=100.0,
                low=10.0,
                high=400.0,
                help="the piece's tempo, a percentage of the written one (80 = slower)",
            ),
            JobParam(
                "transpose",
                "count",
                keyword="transpose",
                option="--transpose",
                required=False,
                low=-48,
                high=48,
                help="move every pitched note by this many semitones (12 = an octave up)",
            ),
            *PLAY_OPTIONS,
        ),
        calls.play,
        "play a MIDI, RTTTL or note-list tune on the scene's xylophone and drums",
        check=checks.check_play,
        epilog=PLAY_EPILOG,
    ),
}

# Jobs the CLI has and the script language does not take: ``reach`` would make a word
# of the language of a name scripts give their poses (examples/scripts/02_poses.arm).
CLI_JOBS: dict[str, JobSpec] = {
    "reach": JobSpec(
        (
            JobParam(
                "height",
                "length",
                keyword="height",
                option="--height",
                required=False,
                default=110.0,
                low=1.0,
                high=500.0,
                help="height of the scan, the hand's",
            ),
            JobParam(
                "near",
                "length",
                keyword="near",
                option="--near",
                required=False,
                default=60.0,
                low=40.0,
                high=300.0,
                help="stop when the sensor reads this",
            ),
            JobParam(
                "shakes",
                "count",
                keyword="shakes",
                option="--shakes",
                required=False,
                default=3,
                low=0,
                high=20,
                help="up-and-down shakes",
            ),
            *SENSOR_OPTIONS,
        ),
        calls.reach,
        "003: find a hand held out with the distance sensor, come near it and shake it",
        epilog="It scans the base from 30 to 120 deg every 5 deg (90 is straight ahead). " + REACH,
    ),
}


def job_spec(command: str) -> JobSpec:
    """The spec of job ``command``, the script's or the CLI's alone (KeyError if none)."""
    return JOBS[command] if command in JOBS else CLI_JOBS[command]
