"""Parse a whole script into statements, collecting every problem on the way.

Lines are read one at a time; ``repeat`` and ``define`` open a block that
``end`` closes. A line with a problem is reported and skipped, and parsing goes
on, so one run of ``armkit check`` lists every mistake.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .._input_limits import MAX_LINE_CHARS, MAX_NESTING, MAX_STATEMENTS
from ._ast import Call, Define, Header, Loc, Num, PoseName, Program, Repeat, Source, Statement
from ._cursor import Cursor, Problem
from ._diagnostics import Diagnostic
from ._grammar import BLOCKS, COMMANDS, RESERVED, read_job, usage_of
from ._jobs import JOBS
from ._lexer import LexError, Token, tokenize
from ._units import UNITS


@dataclass
class _Block:
    kind: str  # "repeat", "define" or "top"
    loc: Loc
    head: Num | Statement | tuple[str, tuple[str, ...]] | None
    body: list[Statement] = field(default_factory=list)


@dataclass
class _State:
    stack: list[_Block]
    diagnostics: list[Diagnostic] = field(default_factory=list)
    commands_seen: bool = False
    headers: dict[str, Loc] = field(default_factory=dict)
    broken: set[str] = field(default_factory=set)
    statements: int = 0  # read so far (a block's statements count once)

    def error(self, loc: Loc, message: str) -> None:
        self.diagnostics.append(Diagnostic(loc, message))


def parse(source: Source) -> tuple[Program, list[Diagnostic]]:
    """Every statement of ``source`` and every problem found (the program holds the
    lines that parsed)."""
    state = _State([_Block("top", Loc(source.first_line, 1), None)])
    for number, text in enumerate(source.lines, start=source.first_line):
        _line(state, number, text)
        if state.statements > MAX_STATEMENTS:
            state.error(
                Loc(number, 1),
                f"more than {MAX_STATEMENTS} statements in one script; split it into "
                "scripts (run FILE) or use repeat and define",
            )
            del state.stack[1:]
            break
    while len(state.stack) > 1:
        block = state.stack[-1]
        state.error(block.loc, f"this {block.kind} has no 'end'; add 'end' after its last line")
        _close(state)
    program = Program(tuple(state.stack[0].body), source, frozenset(state.broken))
    return program, state.diagnostics


def _line(state: _State, number: int, text: str) -> None:
    if len(text) > MAX_LINE_CHARS:
        state.error(
            Loc(number, MAX_LINE_CHARS + 1),
            f"a line longer than {MAX_LINE_CHARS} characters; break it into shorter lines",
        )
        return
    try:
        tokens = tokenize(text)
    except LexError as exc:
        state.error(Loc(number, exc.col), str(exc))
        if text.split()[:1] in (["repeat"], ["define"]):  # its 'end' still closes it
            _open(state, _Block(text.split()[0], Loc(number, 1), None))
        return
    if not tokens:
        return
    cursor = Cursor(tokens, number, len(text.rstrip()) + 1, RESERVED)
    try:
        stmt = _statement(state, cursor)
    except Problem as p:
        state.error(Loc(number, p.col), p.message)
        _broken(state, tokens, number)
        stmt = None
    for col, message in cursor.soft:
        state.error(Loc(number, col), message)
    if stmt is not None and not cursor.soft:
        _add(state, stmt)


def _broken(state: _State, tokens: list[Token], number: int) -> None:
    """Remember the name a failed ``pose``/``define`` line meant to define; a failed
    ``repeat``/``define`` still opens its block so that its ``end`` matches."""
    first = tokens[0].text
    if first in ("pose", "define") and len(tokens) > 1 and tokens[1].is_name:
        state.broken.add(tokens[1].text)
    if first in ("repeat", "define"):
        _open(state, _Block(first, Loc(number, 1), None))
    if first == "repeat":
        state.commands_seen = True


def _statement(state: _State, c: Cursor) -> Statement | None:
    t = c.take("a command")
    c.usage = usage_of(t.text)
    if t.text in BLOCKS:
        _block_word(state, c, t)
        return None
    if t.text in COMMANDS:
        return COMMANDS[t.text][1](c, t)
    if t.text in JOBS:
        return read_job(c, t)
    if not t.is_name:
        raise Problem(t.col, f"expected a command, got {t.text!r}")
    return _call(c, t)


def _call(c: Cursor, t: Token) -> Call:
    """``NAME ARG ...``: numbers keep their units until the parameter is used."""
    args: list[Num | PoseName] = []
    while not c.at_end():
        nxt = c.take("an argument")
        if nxt.kind == "number":
            unit = nxt.unit
            after = c.peek()
            if unit is None and after is not None and after.kind == "word" and after.text in UNITS:
                unit = after.text
                c.i += 1
            args.append(Num(nxt.value, unit, c.loc(nxt)))
        elif nxt.is_name and nxt.text not in RESERVED:
            args.append(PoseName(nxt.text, c.loc(nxt)))
        else:
            raise Problem(nxt.col, f"expected an argument (a number or a name), got {nxt.text!r}")
    return Call(t.text, tuple(args), c.loc(t))


def _block_word(state: _State, c: Cursor, t: Token) -> None:
    loc = c.loc(t)
    if t.text == "end":
        if len(state.stack) == 1:
            raise Problem(t.col, "'end' without a 'repeat' or 'define' to close")
        _close(state)
        c.end()
        return
    if t.text == "repeat":
        count = c.value("count", "a repeat count")
        c.end()
        _open(state, _Block("repeat", loc, Repeat(count, (), loc)))
        state.commands_seen = True
        return
    if len(state.stack) > 1:
        raise Problem(t.col, "define procedures at the top level, not inside a repeat or define")
    name = c.name("a procedure name")
    params = _params(c)
    state.commands_seen = True
    _open(state, _Block("define", loc, (name.text, params)))


def _open(state: _State, block: _Block) -> None:
    """Open ``block``; one more than ``MAX_NESTING`` deep is reported once and opened
    empty (its statements are dropped, its ``end`` still closes it)."""
    if len(state.stack) > MAX_NESTING:
        if len(state.stack) == MAX_NESTING + 1:
            state.error(
                block.loc,
                f"blocks nested deeper than {MAX_NESTING} (repeat and define inside each "
                "other); use define to name the inner part",
            )
        block = _Block(block.kind, block.loc, None)
    state.stack.append(block)


def _params(c: Cursor) -> tuple[str, ...]:
    """``(a, b)`` after a procedure's name, or nothing."""
    if c.at_end():
        return ()
    opening = c.take("'('")
    if opening.text != "(":
        raise Problem(opening.col, "expected '(' and the parameters, e.g. define dip(depth)")
    params: list[str] = []
    if c.accept_punct(")"):
        c.end()
        return ()
    while True:
        t = c.take("a parameter name")
        if not t.is_name or t.text in RESERVED:
            raise Problem(t.col, f"expected a parameter name, got {t.text!r}")
        if t.text in params:
            raise Problem(t.col, f"parameter {t.text!r} is named twice")
        params.append(t.text)
        sep = c.take("',' or ')'")
        if sep.text == ")":
            break
        if sep.text != ",":
            raise Problem(sep.col, f"expected ',' or ')' after {t.text!r}, got {sep.text!r}")
    c.end()
    return tuple(params)


def _close(state: _State) -> None:
    block = state.stack.pop()
    body = tuple(block.body)
    if isinstance(block.head, Repeat):
        done: Statement = Repeat(block.head.count, body, block.loc)
    elif isinstance(block.head, tuple):
        done = Define(block.head[0], block.head[1], body, block.loc)
    else:
        return
    state.stack[-1].body.append(done)


def _add(state: _State, stmt: Statement) -> None:
    if isinstance(stmt, Header):
        if state.commands_seen or len(state.stack) > 1:
            state.error(stmt.loc, f"'{stmt.kind}' must come before the first command")
            return
        if stmt.kind in state.headers:
            first = state.headers[stmt.kind].line
            state.error(stmt.loc, f"'{stmt.kind}' was already chosen on line {first}")
            return
        state.headers[stmt.kind] = stmt.loc
    else:
        state.commands_seen = True
    state.statements += 1
    state.stack[-1].body.append(stmt)
