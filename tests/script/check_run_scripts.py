"""Random ``.arm`` scripts for the check = run property (tests/script/test_check_equals_run.py,
benchmarks/check_run.py): moves, straight lines, joint moves, turns, grips, speeds, waits,
poses, repeats, procedures, every job the language has (pick, place, move-item,
rotate-cube, stack, search, draw, play) and mistakes (unreachable points, points under the
table, joints beyond their limits, taken sockets, a place with nothing picked, unknown
objects, out-of-range values), on the OpenManipulator-X, the Lynx6 and the OWI-535.

A script is a pure function of (arm, seed, search): ``generate(arm, seed)`` draws
everything from ``numpy.random.default_rng`` seeded with the arm and the seed, so a
failing seed is rerun alone; scripts with ``search`` (a sensing job, planned only when
it runs) are drawn apart (``search=True``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from armkit.model import load_model

Rng = np.random.Generator
ARMS = ("openmanipulator_x", "lynx6", "owi535")
ARM_SALT = {name: k for k, name in enumerate(ARMS)}
CUBES = ("red", "green", "blue")
NOTES = ("C5", "D5", "E5", "F5", "G5", "A5", "B5", "C6")
# the scenes each arm's scripts are written for (None: no scene line), with their weights
SCENES: dict[str, tuple[tuple[str | None, float], ...]] = {
    "openmanipulator_x": (
        ("board_001", 4.0),
        (None, 2.0),
        ("drawing", 1.0),
        ("xylophone", 1.0),
        ("search_002", 1.0),
    ),
    "lynx6": (
        ("board_001", 2.0),
        (None, 2.0),
        ("drawing", 1.0),
        ("xylophone", 1.0),
        ("search_002", 2.0),
    ),
    "owi535": ((None, 4.0), ("board_001", 1.0), ("drawing", 1.0), ("search_002", 1.0)),
}


@dataclass
class Script:
    """A generated script: its text, the files it names (name -> text, written next to
    it) and the kinds of statement it has (``features``: "move", "pick", "mistake", ...)."""

    arm: str
    seed: int
    text: str = ""
    files: dict[str, str] = field(default_factory=dict)
    features: set[str] = field(default_factory=set)


class Writer:
    """Draws one script's lines for an arm and a scene."""

    def __init__(self, arm: str, scene: str | None, rng: Rng) -> None:
        self.arm, self.scene, self.rng = arm, scene, rng
        self.model = load_model(arm)
        self.script = Script(arm, 0)
        self.poses: list[str] = []
        self.procs: list[tuple[str, int]] = []  # name, number of parameters
        self.holding = False  # a pick written and no place after it yet

    # -- values ------------------------------------------------------------
    def choose(self, *options: str) -> str:
        """One of ``options``, uniformly."""
        return options[int(self.rng.integers(len(options)))]

    def chance(self, p: float) -> bool:
        """True with probability ``p``."""
        return bool(self.rng.random() < p)

    def mistake(self, p: float = 0.08) -> bool:
        """True with probability ``p``: write a mistake here (noted in the features)."""
        if self.chance(p):
            self.script.features.add("mistake")
            return True
        return False

    def point(self) -> str:
        """An ``xyz`` target [mm]: mostly in front of the arm above the table; sometimes
        out of reach or under it (a mistake)."""
        if self.mistake():
            return self.choose("xyz 900 0 100", "xyz 200 0 -30", "xyz 0 0 5")
        reach = sum(row.a for row in self.model.dh) + self.model.tool_length
        r = float(self.rng.uniform(0.4, 0.75)) * reach * 1000.0
        yaw = float(self.rng.uniform(-50.0, 50.0))
        if self.arm == "lynx6":  # its base turns 15..165 deg: the half plane in front
            yaw = float(self.rng.uniform(-60.0, 60.0))
        x, y = r * math.cos(math.radians(yaw)), r * math.sin(math.radians(yaw))
        z = float(self.rng.uniform(40.0, 180.0))
        text = f"xyz {x:.0f} {y:.0f} {z:.0f}"
        if self.chance(0.08 if self.arm == "owi535" else 0.3):  # the OWI's pitch is narrow
            text += f" pitch {self.choose('-90', '-45', '0')}"
        return text

    def joints(self) -> str:
        """``joints ...`` [deg] near home, inside the limits (sometimes beyond: a mistake)."""
        home = np.degrees(self.model.home)
        angles = home + self.rng.uniform(-35.0, 35.0, self.model.dof)
        lo = np.array([math.degrees(j.lower) for j in self.model.joints])
        hi = np.array([math.degrees(j.upper) for j in self.model.joints])
        angles = np.clip(angles, lo + 1.0, hi - 1.0)
        if self.mistake():
            j = int(self.rng.integers(self.model.dof))
            angles[j] = hi[j] + 20.0
        return "joints " + " ".join(f"{a:.0f}" for a in angles)

    def target(self) -> str:
        """A point, a joint list or a pose defined before."""
        if self.poses and self.chance(0.25):
            return self.choose(*self.poses)
        return self.joints() if self.chance(0.25) else self.point()

    def cube(self) -> str:
        """A cube of board_001 (sometimes one it has not: a mistake)."""
        return "purple" if self.mistake(0.05) else self.choose(*CUBES)

    def where(self) -> str:
        """Where a cube goes: a socket, a cube, a point on the board or the table."""
        row, col = self.rng.integers(3, size=2)
        kind = self.choose("socket", "socket", "cube", "xyz")
        if kind == "socket":
            return f"board[{row},{col}]"
        if kind == "cube":
            return self.choose(*CUBES)
        x, y = self.rng.uniform(150.0, 230.0), self.rng.uniform(-130.0, -90.0)  # off the board
        return f"xyz {x:.0f} {y:.0f} 0"

    # -- statements --------------------------------------------------------
    def motion(self) -> str:
        """One statement that moves, grips, waits or sets a speed."""
        kind = self.choose(*MOTIONS[self.arm])
        self.script.features.add(kind)
        return STATEMENTS[kind](self)

    def job(self) -> str:
        """One job of the script's scene."""
        jobs = JOBS_OF.get(self.scene, ())
        if not jobs:
            return self.motion()
        kind = self.choose(*jobs)
        if kind in BOARD and not self.mistake(0.05):  # place after pick, else another job
            kind = "place" if self.holding else self.choose(*(j for j in jobs if j != "place"))
        self.script.features.add(kind)
        return STATEMENTS[kind](self)

    def statement(self, depth: int = 0) -> list[str]:
        """A statement, a repeat block, a pose definition or a procedure call."""
        roll = self.rng.random()
        if roll < 0.08 and depth == 0:
            return self.repeat(depth)
        if roll < 0.14:
            return [self.pose()]
        if roll < 0.2 and self.procs:
            return [self.call()]
        if roll < 0.45 and JOBS_OF.get(self.scene):
            return [self.job()]
        return [self.motion()]

    def repeat(self, depth: int) -> list[str]:
        """``repeat N`` around one to three statements."""
        self.script.features.add("repeat")
        n = int(self.rng.integers(0, 4))
        if self.mistake(0.03):
            n = 20000
        body = [
            line for _ in range(int(self.rng.integers(1, 4))) for line in self.statement(depth + 1)
        ]
        return [f"repeat {n}", *(f"  {line}" for line in body), "end"]

    def pose(self) -> str:
        """``pose NAME = target``."""
        name, target = f"p{len(self.poses)}", self.target()
        self.poses.append(name)
        self.script.features.add("pose")
        return f"pose {name} = {target}"

    def define(self) -> list[str]:
        """``define hopK(h)``: a move to a height given by its caller, and a wait."""
        name = f"hop{len(self.procs)}"
        self.procs.append((name, 1))
        self.script.features.add("define")
        return [f"define {name}(h)", f"  move {self.point_xy()} h", "  wait 0.1", "end"]

    def point_xy(self) -> str:
        """``xyz X Y`` of a point in front of the arm (the caller gives the height)."""
        return " ".join(self.point().split()[:3])

    def call(self) -> str:
        """A call of a procedure defined before, with a height [mm]."""
        name, _ = self.procs[int(self.rng.integers(len(self.procs)))]
        return f"{name} {self.rng.uniform(30.0, 160.0):.0f}"


# -- the statements, one function each ----------------------------------------
def _move(w: Writer) -> str:
    return f"move {w.target()}"


def _line(w: Writer) -> str:
    return f"line {w.point()}"


def _joints(w: Writer) -> str:
    return w.joints()


def _turn(w: Writer) -> str:
    j = int(w.rng.integers(w.model.dof))
    name = "elbw" if w.mistake(0.03) else w.model.joint_names[j]
    if w.chance(0.5):
        return f"turn {name} by {w.rng.uniform(-25.0, 25.0):.0f}"
    limit = w.model.joints[j]
    angle = math.degrees(float(w.rng.uniform(limit.lower, limit.upper)))
    return f"turn {name} {angle:.0f}"


def _grip(w: Writer) -> str:
    g = w.model.gripper
    if g.kind == "timed" or w.chance(0.5):
        return f"grip {w.choose('open', 'close')}"
    if w.mistake():
        return f"grip {g.width_max * 1000.0 + 30.0:.0f}"
    return f"grip {w.rng.uniform(g.width_min, g.width_max) * 1000.0:.0f}"


def _home(w: Writer) -> str:
    return "home"


def _wait(w: Writer) -> str:
    if w.mistake(0.04):
        return "wait 5000"
    return f"wait {w.rng.uniform(0.0, 1.5):.2f}"


def _speed(w: Writer) -> str:
    if w.mistake(0.04):
        return w.choose("speed 0%", "speed 150%", "speed 2000 mm/s")
    if w.chance(0.3):
        return f"speed {w.rng.uniform(10.0, 120.0):.0f} mm/s"
    return f"speed {w.rng.uniform(20.0, 100.0):.0f}%"


def _run(w: Writer) -> str:
    j = int(w.rng.integers(w.model.dof))
    words = ("left", "right") if j == 0 else ("forward", "backward")
    return f"run {w.model.joint_names[j]} {w.choose(*words)} {w.rng.uniform(0.2, 1.5):.1f}s"


def _light(w: Writer) -> str:
    return f"light {w.choose('on', 'off')}"


def _pick(w: Writer) -> str:
    w.holding = True
    return f"pick {w.cube()}"


def _place(w: Writer) -> str:
    w.holding = False
    return f"place {w.where()}"


def _move_item(w: Writer) -> str:
    return f"move-item {w.cube()} to {w.where()}"


def _rotate(w: Writer) -> str:
    return f"rotate-cube {w.cube()} {w.choose('forward', 'backward')}"


def _stack(w: Writer) -> str:
    cubes = list(CUBES)
    w.rng.shuffle(cubes)
    return "stack " + " ".join(cubes[: int(w.rng.integers(2, 4))])


def _search(w: Writer) -> str:
    if w.mistake(0.1):
        return w.choose("search step 0", "search into basket")
    if w.chance(0.5):
        return "search into bin"
    a = w.rng.uniform(20.0, 60.0)
    return f"search from {a:.0f} to {a + w.rng.uniform(30.0, 90.0):.0f} step {w.choose('5', '10')}"


def _draw(w: Writer) -> str:
    name = f"d{len(w.script.files)}.svg"
    w.script.files[name] = _svg(w.rng)
    sheet = "A7" if w.mistake(0.05) else "A5"
    return f"draw {name} on {sheet}" + (" fit" if w.chance(0.2) else "")


def _play(w: Writer) -> str:
    name = f"t{len(w.script.files)}.txt"
    notes = [w.choose(*NOTES) for _ in range(int(w.rng.integers(2, 6)))]
    if w.mistake(0.05):
        notes.append("C8")
    w.script.files[name] = "tempo 100\n" + " ".join(f"{n} q" for n in notes) + "\n"
    tempo = "400%" if w.mistake(0.05) else f"{w.rng.uniform(50.0, 100.0):.0f}%"
    return f"play {name} tempo {tempo}"


def _svg(rng: Rng) -> str:
    """One to three straight lines in a 40 mm square."""
    lines = []
    for _ in range(int(rng.integers(1, 4))):
        x1, y1, x2, y2 = rng.uniform(2.0, 38.0, 4)
        lines.append(
            f'  <line x1="{x1:.1f}" y1="{y1:.1f}" x2="{x2:.1f}" y2="{y2:.1f}" stroke="black"/>'
        )
    body = "\n".join(lines)
    return (
        '<svg xmlns="http://www.w3.org/2000/svg" width="40mm" height="40mm" '
        f'viewBox="0 0 40 40">\n{body}\n</svg>\n'
    )


STATEMENTS: dict[str, Callable[[Writer], str]] = {
    "move": _move,
    "line": _line,
    "joints": _joints,
    "turn": _turn,
    "grip": _grip,
    "home": _home,
    "wait": _wait,
    "speed": _speed,
    "run": _run,
    "light": _light,
    "pick": _pick,
    "place": _place,
    "move-item": _move_item,
    "rotate-cube": _rotate,
    "stack": _stack,
    "search": _search,
    "draw": _draw,
    "play": _play,
}
COMMON = ("move", "move", "line", "joints", "turn", "grip", "home", "wait", "speed")
MOTIONS: dict[str, tuple[str, ...]] = {
    "openmanipulator_x": COMMON,
    "lynx6": COMMON,
    "owi535": (*COMMON, "run", "run", "light"),
}
BOARD = ("pick", "pick", "place", "place", "move-item", "rotate-cube", "stack")
JOBS_OF: dict[str | None, tuple[str, ...]] = {
    "board_001": BOARD,
    "drawing": ("draw",),
    "xylophone": ("play",),
    "search_002": ("search",),
}


def generate(arm: str, seed: int, search: bool | None = False) -> Script:
    """The script of ``seed`` for ``arm``: its header, maybe a procedure, then 3 to 9
    statements (blocks counted as one). ``search``: False, on a scene other than
    search_002 (no ``search``); True, on search_002; None, on any."""
    rng = np.random.default_rng([seed, ARM_SALT[arm]])
    scenes = [(s, p) for s, p in SCENES[arm] if search is None or (s == "search_002") == search]
    names = [s for s, _ in scenes]
    weights = np.array([p for _, p in scenes])
    scene = names[int(rng.choice(len(names), p=weights / weights.sum()))]
    w = Writer(arm, scene, rng)
    w.script.seed = seed
    lines = [f"arm {arm}"] + ([] if scene is None else [f"scene {scene}"])
    if w.chance(0.2):
        lines += w.define()
    for _ in range(int(rng.integers(3, 10))):
        lines += w.statement()
    w.script.text = "\n".join(lines) + "\n"
    return w.script
