"""The options only the CLI's job commands take (what the script language leaves to
its own statements or does not need: ``--dry-run``, the files a command writes, the
sensor's wiring), declared as ``JobParam``s beside the jobs' own parameters in
``_jobs.JOBS``, and the commands' closing help paragraphs."""

from __future__ import annotations

from ._spec import JobParam

PICK_HINT = (
    "pick takes a cube of the scene by its name (pick red); an item known only by "
    "its point is carried with move-item xyz X Y Z to WHERE"
)
NOTHING_PICKED = (
    "place puts down the cube the script picked, and no cube is picked here; "
    "write 'pick CUBE' before it"
)
STACK_ON = (
    "stack takes no 'on WHERE': the first cube named stays where it is and the others "
    "go on it (stack red green blue puts green on red, blue on green)"
)


TASKS_EPILOG = (
    "Needs --scene FILE|NAME before the command (see 'armkit scene list'). The whole task "
    "is planned first (every point solved, every move checked against the table and the "
    "scene); a step that cannot be done is named and nothing moves. Positions in mm, "
    "angles in degrees."
)
TO_HELP = " TO is a place, board[ROW,COL], a cube to stack on or a container."
SEARCH_EPILOG = (
    "Needs --scene (shipped: search_002, reach_003). The distance sensor (a Sharp GP2D120 on the "
    "hand, 4..30 cm) is read through the SSC-32's VA..VD on a Lynx6, else a serial ADC "
    "board (emulated on a pty in the simulator). Angles in degrees, distances in mm. Exit "
    "status: 0 {found}; 1 {none} (one line on stderr says what was scanned and what to "
    "try); 2 a mistake or a step that cannot be done (one line, 'armkit: error: ...')."
)
DRAW_EPILOG = (
    "Needs --scene FILE|NAME before 'draw' (a scene with a sheet and a pen, e.g. 'drawing'). "
    "The whole job is planned first (the file read at its real size, or scaled to the sheet "
    "with --fit, placed on the sheet, cut to the arm's "
    "reach with a note saying what was cut, every move checked); nothing moves on a bad "
    "file, name or output path. On a simulated arm, what the pen drew is measured."
)
PLAY_EPILOG = (
    "Needs --scene FILE|NAME before the command (the shipped 'xylophone' has 13 bars, "
    "C5..C6, and a snare). Scores: MIDI (.mid, .midi), RTTTL (.rtttl) or a note list "
    "(.txt: 'tempo 120' then notes such as 'C4 q  E4 e  R q'). Times in seconds, "
    "onset errors in milliseconds. A piece the arm cannot play in time is refused "
    "with every late note listed and a --tempo that fits; nothing moves. Latency tables "
    "(--calibrate, --latency) hold each bar's onset delay in milliseconds."
)


def _cli(name: str, kind: str, option: str, help: str, **more: object) -> JobParam:
    """A parameter only the CLI's command takes."""
    return JobParam(name, kind, required=False, option=option, help=help, surface="cli", **more)  # type: ignore[arg-type]


DRY_RUN = _cli("dry_run", "flag", "--dry-run", "print the plan, move nothing", passed=False)
PITCH = _cli(
    "pitch",
    "angle",
    "--pitch",
    "gripper pitch (-90 from the top, 0 from the side; default: 001's choice)",
    low=-90.0,
    high=90.0,
)
TASK_OPTIONS = (
    DRY_RUN,
    _cli(
        "clearance",
        "length",
        "--clearance",
        "first waypoint above each grasp (>= 30)",
        default=30.0,
        low=30.0,
        high=500.0,
    ),
    _cli(
        "calibration",
        "file",
        "--calibration",
        "the unit's offsets (height_offset_mm, perpendicular_offset_mm); default <config>/<arm>_tasks.toml if present",
        metavar="FILE",
    ),
)
SENSOR_OPTIONS = (
    _cli(
        "port",
        "text",
        "--adc-port",
        "the serial ADC board the sensor is wired to (arms without an SSC-32, real hardware; default: none, the SSC-32's own inputs or the simulator's)",
        metavar="PORT",
    ),
    _cli(
        "channel",
        "count",
        "--channel",
        "the sensor's analog input (SSC-32 VA..VD)",
        default=0,
        low=0,
        high=3,
    ),
)
DRAW_OPTIONS = (
    _cli(
        "held",
        "flag",
        "--held",
        "the pen is in the gripper already (on the simulator: taken to be, the stand's pen not used)",
        passed=False,
    ),
    _cli("preview", "file", "--preview", "draw the plan to this picture, then move", metavar="PNG"),
    _cli("result", "file", "--result", "simulated arms: picture what was drawn", metavar="PNG"),
    _cli("dry_run", "flag", "--dry-run", "plan (and --preview) only; no motion", passed=False),
    _cli(
        "tolerance",
        "length",
        "--tolerance",
        "curves flattened within this",
        default=0.1,
        low=0.001,
        high=5.0,
        passed=False,
    ),
    _cli(
        "margin",
        "length",
        "--margin",
        "blank border on the sheet",
        default=10.0,
        low=0.0,
        high=100.0,
        passed=False,
    ),
    _cli(
        "pen_up",
        "length",
        "--pen-up",
        "pen height above the paper between strokes",
        default=10.0,
        low=1.0,
        high=100.0,
        passed=False,
    ),
    _cli(
        "pitch",
        "angle",
        "--pitch",
        "pen angle above the horizontal while drawing",
        default=-60.0,
        low=-90.0,
        high=0.0,
        passed=False,
    ),
    _cli(
        "speed",
        "speed",
        "--speed",
        "tool (pen) speed along lines",
        default=30.0,
        low=1.0,
        high=500.0,
        passed=False,
    ),
)
PLAY_OPTIONS = (
    _cli(
        "hover",
        "length",
        "--hover",
        "the mallet head's height above a bar before the loudest stroke (default 30; softer notes start lower, down to 10): lower plays faster and softer",
        low=2.0,
        high=200.0,
    ),
    _cli(
        "chords",
        "choice",
        "--chords",
        "notes written together: top keeps the highest and says what was dropped, arpeggio plays them one after another, refuse refuses the piece",
        choices=("top", "arpeggio", "refuse"),
        default="top",
    ),
    _cli(
        "wav",
        "file",
        "--wav",
        "write the contacts the simulated mallet made as sound (.wav, 16-bit mono 44.1 kHz)",
        metavar="OUT",
        passed=False,
    ),
    _cli(
        "plot",
        "file",
        "--plot",
        "plot planned against played onsets [s] and their errors [ms] (.png, .svg, .pdf)",
        metavar="OUT",
        passed=False,
    ),
    _cli(
        "calibrate",
        "file",
        "--calibrate",
        "first strike every bar once in the simulator, measure each bar's onset delay [ms] and write the table (.toml); then play FILE, if given, with it",
        metavar="OUT",
        passed=False,
    ),
    _cli(
        "latency",
        "file",
        "--latency",
        "plan with this per-bar latency table (.toml, delays in ms, from --calibrate)",
        metavar="TABLE",
        passed=False,
    ),
    _cli(
        "dry_run",
        "flag",
        "--dry-run",
        "plan and check only; print the plan, move nothing, write nothing",
        passed=False,
    ),
)

DRAW_SUFFIXES = (".svg", ".gcode", ".nc", ".ngc", ".gc")
PLAY_SUFFIXES = (".mid", ".midi", ".rtttl", ".txt")
CUBE = "the cube's name in the scene"
TO = JobParam(
    "to",
    "where",
    point="--xyz",
    help="a place, board[ROW,COL], a cube or a container (or --xyz: a point for the cube's bottom [mm])",
)
ANGLES = " Scan angles are the base servo's, as in 002: 90 deg is straight ahead."
SEARCH = SEARCH_EPILOG.format(found="found, picked up and dropped", none="nothing found")
REACH = SEARCH_EPILOG.format(found="the hand found, come near and shaken", none="no hand found")
DRAW_FORMS = (
    ("svg", "an SVG file", (".svg",)),
    ("gcode", "a G-code file (.gcode .nc .ngc)", (".gcode", ".nc", ".ngc", ".gc", ".g", ".tap")),
)
