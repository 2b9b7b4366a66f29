"""Command lines a hurried new user might type: mostly plausible, often wrong (the
issue 10 fuzzer, on the one engine)."""

from __future__ import annotations

import random
from dataclasses import dataclass

from fuzz_engine import Case, Step

ARMS = ["openmanipulator_x", "lynx6", "owi535", "planar2", "al5d", "puma560"]
BAD_ARMS = ["nosucharm", "", "../x", "/nonexistent/arm.toml", "x.toml", "case.toml", "."]
DRIVERS = ["sim", "sim", "sim", "sim", "ssc32", "maestro", "dynamixel", "owi535", "nope"]
PORTS = [None, None, None, None, "emu", "/dev/nonexistent", "", "state.json", "/dev/null"]
NUMBERS = [
    "0", "-0", "1", "-1", "0.1", "2", "10", "20", "30", "45", "-45", "60", "90", "-90",
    "100", "150", "170", "200", "-200", "250", "300", "450", "1000", "1e6", "-1e6", "1e15",
    "1e308", "-1e308", "1e-300", "nan", "inf", "-inf", "x", "", "1e", "0x10", "--", "1,5",
    "9" * 5000, "1e400", "1_0", "٣", "１",
]  # fmt: skip
FILES = [
    "out.csv",
    "pic.png",
    "/nonexistent/dir/f.png",
    ".",
    "f.nosuch",
    "",
    "/dev/full",
    "x" * 5000,
]
OPTIONS = {
    "--pitch": NUMBERS, "--speed": NUMBERS, "--duration": NUMBERS, "--spacing": NUMBERS,
    "--radius": NUMBERS, "--sweep": NUMBERS, "--start": NUMBERS, "--fraction": NUMBERS,
    "--mode": ["naive", "early", "timed", "fast"], "--method": ["auto", "lm", "ccd", "newton"],
    "--record": FILES, "-o": FILES, "--plot": FILES, "--lift": NUMBERS,
    "--n": ["0", "1", "3", "-1", "1000000000", "x"], "--repeats": ["0", "1", "2", "99"],
    "--time-ms": ["0", "20", "-5", "70000", "x"], "--ids": ["11-15", "1", "300", "x", "5-1"],
    "--json": None, "--all": None, "--help": None, "--plan": None,
}  # fmt: skip
COMMANDS: dict[str, tuple[int, list[str]]] = {  # command: (usual number of values, its options)
    "arms": (0, []),
    "show": (0, []),
    "fk": (4, ["--json"]),
    "ik": (3, ["--pitch", "--all", "--method", "--json"]),
    "plot": (4, ["-o"]),
    "move": (3, ["--pitch", "--speed", "--duration"]),
    "joints": (4, ["--speed", "--duration"]),
    "grip": (1, []),
    "home": (0, []),
    "where": (0, []),
    "draw circle": (
        0,
        [
            "--center",
            "--radius",
            "--sweep",
            "--start",
            "--pitch",
            "--spacing",
            "--speed",
            "--mode",
            "--record",
        ],
    ),
    "draw line": (6, ["--pitch", "--spacing", "--speed", "--mode", "--fraction", "--record"]),
    "draw rect": (0, ["--center", "--size", "--pitch", "--spacing", "--mode"]),
    "draw cube": (0, ["--corner", "--size", "--pitch", "--spacing"]),
    "servo": (2, ["--time-ms"]),
    "servo-table": (0, []),
    "compare-ik": (0, ["--n", "--repeats", "--plot", "--method"]),
    "rehome": (0, []),
    "light": (1, []),
    "pick-place": (6, ["--lift"]),
    "dxl-scan": (0, ["--ids"]),
    "scene show": (0, []),
    "check": (0, ["--plan"]),
    "nosuchcommand": (0, []),
}
TRIPLES = {"--center", "--corner"}
NASTY = (
    ("an argument of a million characters", ["move", "1" * 1_000_000, "0", "0"]),
    ("a NUL in a file name", ["--arm", "x\x00.toml", "show"]),
    ("a NUL in a script's name", ["check", "a\x00b.arm"]),
    ("a file name that is not UTF-8", ["check", "\udcff\udcfe.arm"]),
    ("a scene that is a folder", ["--scene", ".", "scene", "show"]),
    ("a scene that is a device", ["--scene", "/dev/zero", "scene", "show"]),
    ("an arm that is a device", ["--arm", "/dev/zero", "show"]),
    ("a script that is a device", ["check", "/dev/zero"]),
    ("a score that is a device", ["--scene", "xylophone", "play", "/dev/zero.mid"]),
    ("10 000 arguments", ["fk", *["1"] * 10_000]),
)


def _option(rng: random.Random, option: str) -> list[str]:
    if option in TRIPLES:
        return [option, *(rng.choice(NUMBERS) for _ in range(rng.choice((3, 3, 2))))]
    if option == "--size":
        return [option, *(rng.choice(NUMBERS) for _ in range(rng.randint(1, 2)))]
    values = OPTIONS.get(option)
    return [option] if values is None else [option, rng.choice(values)]


def command_line(rng: random.Random) -> list[str]:
    """One command line (``armkit`` left out)."""
    argv: list[str] = []
    if rng.randint(0, 3):
        argv += ["--arm", rng.choice(ARMS if rng.randint(0, 5) else BAD_ARMS)]
    driver = rng.choice(DRIVERS)
    if driver != "sim" or rng.random() < 0.5:
        argv += ["--driver", driver]
    port = rng.choice(PORTS)
    if port is not None:
        argv += ["--port", port]
    command = rng.choice(sorted(COMMANDS))
    count, options = COMMANDS[command]
    argv += command.split()
    if command == "check":
        argv.append(rng.choice(("case.arm", "case.arm", "nofile.arm", "", ".")))
    if command == "compare-ik":  # always a small --n: the default 1000 targets take seconds
        argv += _option(rng, "--n")
    count = max(0, count + rng.choice((0, 0, 0, 0, -1, 1, -2)))
    argv += [rng.choice(NUMBERS) for _ in range(count)]
    if command == "light" and count:
        argv[-1] = rng.choice(("on", "off", argv[-1]))
    for _ in range(rng.randint(0, 4)):
        argv += _option(rng, rng.choice(options or ["--help"]))
    if rng.randint(0, 9) == 0:  # a global option after the command
        argv += ["--arm", rng.choice(ARMS)]
    return argv


@dataclass(frozen=True)
class CommandLines:
    """The command line as an input language (same interface as ``Language``)."""

    name: str = "command lines"

    def case(self, i: int) -> Case:
        rng = random.Random(f"{self.name}:{i}")
        if i % 2 == 0 and i // 2 < len(NASTY):
            label, argv = NASTY[i // 2]
        else:
            label, argv = "random", command_line(rng)
        script = {"case.arm": b"home\n"} if "check" in argv else {}
        return Case(f"{self.name} #{i} {label}", script, (Step(tuple(argv)),))

    def cases(self, n: int) -> list[Case]:
        return [self.case(i) for i in range(n)]


CLI = CommandLines()
