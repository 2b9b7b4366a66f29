"""The command language as files (``armkit check``/``run``) and as lines typed at
``armkit shell``."""

from __future__ import annotations

import random

from fuzz_engine import Step
from fuzz_language import Language, files, last, one
from fuzz_mutate import Nest

WORDS = (
    "move", "line", "joints", "turn", "grip", "home", "wait", "speed", "light", "run", "pose",
    "repeat", "define", "end", "xyz", "pitch", "by", "open", "close", "here", "above", "rest",
    "waist", "wrist", "elbow", "=", "(", ")", ",", "#", '"', "mm", "cm", "deg", "s", "%", "mm/s",
    "pick", "place", "draw", "play", "stack", "search", "move-item", "rotate-cube", "a", "f",
    "-x", "on", "to", "arm", "scene", "driver", "lynx6", "owi535", "board_001", "xylophone",
    "square.svg", "ode.txt", "A5", "tempo", "red", "green", "board[1,1]", "board[99999999999,0]",
    "1e400", "-1e400", "nan", "inf", "9" * 400, "1e308", "0", "-90", "1000000", "10000", "3600",
)  # fmt: skip
SHELL_WORDS = ("where", "poses", "save p", "write out.arm", "jog", "limp", "hold", "help",
               "help move", "quit", "exit", "run case.arm", "run nofile.arm")  # fmt: skip


def _soup(rng: random.Random, words: tuple[str, ...]) -> bytes:
    """Lines of the language's words and numbers, mostly wrong."""
    lines = []
    for _ in range(rng.randint(1, 12)):
        line = [rng.choice(words) if rng.random() < 0.7 else f"{rng.uniform(-500, 500):g}"]
        line += [rng.choice(words) for _ in range(rng.randint(0, 6))]
        lines.append(" ".join(line))
    return "\n".join(lines).encode()


def _nested(depth: int, line: str = "turn waist by 1") -> bytes:
    return ("repeat 2\n" * depth + line + "\n" + "end\n" * depth).encode()


def _calls(depth: int) -> bytes:
    """Procedures each calling the next twice: 2**depth calls from one line."""
    text = f"define p{depth}\n  turn waist by 0\nend\n"
    for k in range(depth - 1, -1, -1):
        text += f"define p{k}\n  p{k + 1}\n  p{k + 1}\nend\n"
    return (text + "p0\n").encode()


NASTY = (
    ("repeats nested 100 deep", _nested(100)),
    ("repeats nested 100 000 deep", _nested(100_000)),
    ("three repeats of 10 000 nested", _nested(3).replace(b"repeat 2", b"repeat 10000")),
    ("a procedure that calls itself", b"define f\n  turn waist by 1\n  f\nend\nf\n"),
    ("two procedures calling each other", b"define f\n  g\nend\ndefine g\n  f\nend\nf\n"),
    ("2**60 calls from one line", _calls(60)),
    ("a line of a million characters", b"move " + b"1 " * 500_000 + b"\n"),
    ("an unclosed string of 10**6 characters", b'pose "' + b"x" * 1_000_000 + b"\n"),
    ("100 000 lines", b"turn waist by 0\n" * 100_000),
    (
        "huge numbers",
        b"move xyz 1e400 -1e400 nan\nwait " + b"9" * 5000 + b"\nturn waist by 1e308\n",
    ),
    ("a repeat count beyond any integer", b"repeat " + b"9" * 5000 + b"\n  home\nend\n"),
    ("a socket beyond any integer", b"scene board_001\npick board[" + b"9" * 5000 + b",1]\n"),
    ("UTF-16 with a BOM", "home\nmove xyz 180 0 80\n".encode("utf-16")),
    ("CRLF, a BOM and a NUL", b"\xef\xbb\xbfhome\r\nmove xyz 180 0 80\r\n\x00\r\n"),
    ("speed and waits at the edges", b"speed 1e-300%\nspeed 1e-300 mm/s\nwait 1e-300\nhome\n"),
    (
        "many procedures with many parameters",
        b"define f(" + b",".join(b"p%d" % k for k in range(10_000)) + b")\nend\n",
    ),
    ("a define 1000 deep in repeats", _nested(1000, "define f\nend")),
)
NASTY = last(
    NASTY,
    [
        "repeats nested 100 deep",
        "three repeats of 10 000 nested",
        "a line of a million characters",
        "an unclosed string of 10**6 characters",
        "100 000 lines",
        "many procedures with many parameters",
        "a define 1000 deep in repeats",
        "repeats nested 100 000 deep",
        "2**60 calls from one line",
    ],
)  # cheap cases first: `make test` runs the first few


def _script_steps(rng: random.Random, name: str, data: bytes) -> tuple[Step, ...]:
    steps = [one("check", name), one("run", "-q", name, when="refused")]
    if rng.random() < 0.5 and b"draw" not in data:  # the simulator draws slowly
        steps.append(one("run", "-q", name, when="short"))
    return tuple(steps)


SCRIPTS = Language(
    name="scripts (.arm)",
    suffix=".arm",
    seeds=files("examples/scripts/*.arm", "examples/scripts/mistakes/*.arm"),
    nasty=NASTY,
    words=WORDS,
    nesting=Nest("repeat 2\n", "end\n", "home\n"),
    steps=_script_steps,
    companions=files("examples/scripts/square.svg", "examples/scripts/ode.txt"),
    grammar=lambda rng: _soup(rng, WORDS),
)


def _shell_steps(rng: random.Random, name: str, data: bytes) -> tuple[Step, ...]:
    scene = rng.choice(((), (), ("--scene", "board_001"), ("--scene", "xylophone")))
    return (one(*scene, "shell", "--no-history", stdin=data),)


SHELL_NASTY = (
    ("bytes that are not UTF-8", b"home\n\xff\xfe\x80\nwhere\n"),
    ("a NUL in a line", b"move xyz 180 0 80\x00\nwhere\n"),
    ("a line of a million characters", b"x" * 1_000_000 + b"\nwhere\n"),
    ("an open block never closed", b"repeat 3\n" * 1000 + b"where\n"),
    ("repeats nested 100 000 deep", _nested(100_000)),
    ("jog and limp on a pipe", b"jog\nlimp\nhold\njog 1e400\nsave \xe2\x80\xae\nwhere\n"),
    ("write to nowhere", b"write /nonexistent/dir/x.arm\nwrite \nwrite " + b"x" * 5000 + b"\n"),
    ("run itself", b"run case.arm\n"),
    ("help for everything", b"help\nhelp move\nhelp " + b"x" * 100_000 + b"\nhelp help\n"),
    ("2**60 calls", _calls(60)),
    ("UTF-16", "home\nwhere\n".encode("utf-16")),
    ("CR line ends", b"home\rwhere\rquit\r"),
)
SHELL_NASTY = last(
    SHELL_NASTY, ["repeats nested 100 000 deep", "2**60 calls", "a line of a million characters"]
)  # cheap cases first: `make test` runs the first few


SHELL = Language(
    name="shell lines",
    suffix=".arm",
    # the scripts without jobs: a line of the shell runs as it is read, and jobs take seconds
    seeds=files(*(f"examples/scripts/0{k}_*.arm" for k in range(1, 7))),
    nasty=SHELL_NASTY,
    words=(*WORDS, *SHELL_WORDS),
    nesting=Nest("repeat 2\n", "end\n", "home\n"),
    steps=_shell_steps,
    companions=files("examples/scripts/square.svg", "examples/scripts/ode.txt"),
    grammar=lambda rng: _soup(rng, (*WORDS, *SHELL_WORDS)),
    skip=frozenset({"many-lines", "repeat"}),
)
