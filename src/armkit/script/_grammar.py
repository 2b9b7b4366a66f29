"""One parser per statement: the words of the language and how each is written.

``COMMANDS`` maps each command word to its usage and the function that reads
the rest of the line into a statement. Jobs come from ``_jobs.JOBS``.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Literal

from ._ast import (
    Grip,
    Header,
    Job,
    JobArg,
    Move,
    PoseDef,
    PoseName,
    Quantity,
    RunMotor,
    Simple,
    Statement,
    Turn,
)
from ._cursor import Cursor, Problem
from ._jobs import JOBS, QUANTITY_KINDS, JobParam, job_keywords
from ._lexer import Token, is_cell
from ._units import UNITS

Reader = Callable[[Cursor, Token], Statement]

DIRECTIONS = {"forward": 1, "backward": -1, "back": -1, "right": 1, "left": -1}


def _move(c: Cursor, t: Token) -> Statement:
    target = c.target()
    c.end()
    return Move(target, t.text == "line", c.loc(t))


def _joints(c: Cursor, t: Token) -> Statement:
    c.i -= 1  # 'joints' starts its own target
    return _move(c, Token("word", "move", t.col))


def _turn(c: Cursor, t: Token) -> Statement:
    joint = c.name("a joint name")
    relative = c.accept("by") is not None
    angle = c.value("angle", "an angle [deg]")
    c.end()
    return Turn(joint.text, angle, relative, c.loc(t), c.loc(joint))


def _grip(c: Cursor, t: Token) -> Statement:
    nxt = c.peek()
    if nxt is not None and nxt.text in ("open", "close", "closed"):
        c.i += 1
        c.end()
        return Grip(None, "open" if nxt.text == "open" else "close", c.loc(t))
    width = c.value("length", "a width [mm] or open or close")
    c.end()
    return Grip(width, None, c.loc(t))


def _simple(c: Cursor, t: Token) -> Statement:
    if t.text == "home":
        c.end()
        return Simple("home", None, c.loc(t))
    if t.text == "light":
        flag = c.word(("on", "off"), "on or off")
        c.end()
        return Simple("light", None, c.loc(t), flag.text == "on")
    if t.text == "wait":
        value = c.value("time", "a time [s]")
        c.end()
        return Simple("wait", value, c.loc(t))
    return _speed(c, t)


def _speed(c: Cursor, t: Token) -> Statement:
    nxt = c.peek()
    unit = None if nxt is None else nxt.unit
    after = c.peek(1)
    if unit is None and after is not None and after.text in UNITS:
        unit = after.text
    if unit is not None and unit in UNITS and UNITS[unit][0] == "speed":
        value = c.value("speed", "a tool speed [mm/s]")
        c.end()
        return Simple("tool-speed", value, c.loc(t))
    value = c.value("percent", "a speed [%] or a tool speed [mm/s]")
    c.end()
    return Simple("speed", value, c.loc(t))


def _run(c: Cursor, t: Token) -> Statement:
    joint = c.name("a joint name")
    direction = c.word(tuple(DIRECTIONS), "a direction")
    seconds = c.value("time", "a time [s]")
    c.end()
    return RunMotor(
        joint.text, DIRECTIONS[direction.text], direction.text, seconds, c.loc(t), c.loc(joint)
    )


def _pose(c: Cursor, t: Token) -> Statement:
    name = c.name("a pose name")
    eq = c.take("'='")
    if eq.text != "=":
        raise Problem(eq.col, f"expected '=' after the pose name, got {eq.text!r}; {c.usage}")
    target = c.target()
    c.end()
    return PoseDef(name.text, target, c.loc(t))


def _header(c: Cursor, t: Token) -> Statement:
    what = {"arm": "an arm name", "driver": "a driver name", "scene": "a scene file or name"}
    value = c.take(what[t.text])
    port = None
    if t.text == "driver" and c.accept("port"):
        port = c.take("a port").text
    c.end()
    kinds: dict[str, Literal["arm", "driver", "scene"]] = {
        "arm": "arm",
        "driver": "driver",
        "scene": "scene",
    }
    return Header(kinds[t.text], value.text, port, c.loc(t), c.loc(value))


COMMANDS: dict[str, tuple[str, Reader]] = {
    "move": ("move TARGET   (TARGET: xyz X Y Z [pitch P] | joints A B ... | POSE | here)", _move),
    "line": ("line TARGET   (straight, at the tool speed)", _move),
    "joints": ("joints A B ...   (one angle per joint [deg])", _joints),
    "turn": ("turn JOINT ANGLE | turn JOINT by ANGLE", _turn),
    "grip": ("grip WIDTH | grip open | grip close", _grip),
    "home": ("home", _simple),
    "wait": ("wait TIME   (0..3600 s)", _simple),
    "speed": ("speed PERCENT (joint moves) | speed MM/S mm/s (lines)", _simple),
    "light": ("light on | light off", _simple),
    "run": ("run JOINT forward|backward|left|right TIME   (timed motors)", _run),
    "pose": ("pose NAME = TARGET", _pose),
    "arm": ("arm NAME", _header),
    "driver": ("driver NAME [port PORT]", _header),
    "scene": ("scene FILE", _header),
}
BLOCKS = {
    "repeat": "repeat COUNT ... end   (COUNT 0..10000)",
    "define": "define NAME(PARAM, ...) ... end",
    "end": "end",
}
KEYWORDS = {"xyz", "joints", "pitch", "here", "by", "open", "close", "closed", "on", "off", "port"}
RESERVED = frozenset(
    set(COMMANDS) | set(BLOCKS) | set(JOBS) | KEYWORDS | job_keywords() | set(UNITS)
)


def usage_of(command: str) -> str:
    """The usage line of a command, job or block word ('' if unknown)."""
    if command in COMMANDS:
        return COMMANDS[command][0]
    if command in JOBS:
        return JOBS[command].usage(command)
    return BLOCKS.get(command, "")


def read_job(c: Cursor, t: Token) -> Statement:
    """A job's arguments: the positional ones in order, then keyword ones in any order."""
    spec = JOBS[t.text]
    args: list[JobArg] = []
    positional = [p for p in spec.params if p.keyword is None]
    keyed = {p.keyword: p for p in spec.params if p.keyword is not None}
    for p in positional:
        if not p.required and (c.at_end() or c.peek() is None or _is_keyword(c, keyed)):
            continue
        args.append(_job_arg(c, p))
    refused = dict(spec.refused)
    while not c.at_end():
        nxt = c.peek()
        if nxt is not None and nxt.text in refused and nxt.text not in keyed:
            raise Problem(nxt.col, refused[nxt.text])
        if nxt is not None and not keyed:  # every argument is written: one too many
            raise Problem(
                nxt.col, f"{t.text} takes nothing more, got {nxt.text!r}; usage: {c.usage}"
            )
        word = c.word(tuple(keyed), "an argument keyword")
        p = keyed.pop(word.text)
        args.append(JobArg(p.name, True, c.loc(word)) if p.kind == "flag" else _job_arg(c, p))
    written = {a.name for a in args}
    for p in spec.params:
        if p.required and p.name not in written:
            raise Problem(c.end_col, f"{t.text} needs {p.usage}; usage: {c.usage}")
    return Job(t.text, tuple(args), c.loc(t))


def _is_keyword(c: Cursor, keyed: dict[str, JobParam]) -> bool:
    t = c.peek()
    return t is not None and t.text in keyed


def _job_arg(c: Cursor, p: JobParam) -> JobArg:
    loc = c.loc()
    if p.kind == "where":
        t = c.peek()
        if t is not None and t.kind == "word" and "[" in t.text:  # board[ROW,COL]
            if not is_cell(t.text):
                raise Problem(
                    t.col,
                    f"expected a board's socket as NAME[ROW,COL] (board[0,1]), got {t.text!r}",
                )
            c.take(p.name.upper())
            return JobArg(p.name, t.text, loc)
        return JobArg(p.name, c.target(p.name.upper()), loc)
    if p.kind == "object":
        t = c.peek()
        if p.hint and t is not None and (not t.is_name or t.text in c.reserved):
            raise Problem(t.col, f"expected {p.name.upper()}, got {t.text!r}: {p.hint}")
        return JobArg(p.name, PoseName(c.name(p.name.upper()).text, loc), loc)
    if p.kind == "objects":
        names = [PoseName(c.name(p.name.upper()).text, loc)]
        while c.has_value():
            token = c.name(p.name.upper())
            names.append(PoseName(token.text, c.loc(token)))
        return JobArg(p.name, tuple(names), loc)
    if p.kind == "choice":
        return JobArg(p.name, c.word(p.choices, p.name).text, loc)
    if p.kind == "file":
        token = c.take(f"a file ({', '.join(p.choices)})")
        if not token.text.lower().endswith(p.choices):
            c.soft.append((token.col, f"{token.text!r} is not one of {', '.join(p.choices)}"))
        return JobArg(p.name, token.text, loc)
    dim = QUANTITY_KINDS[p.kind]
    return JobArg(p.name, Quantity(c.value(dim, p.name), dim), loc)
