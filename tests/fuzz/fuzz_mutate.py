"""Mutations of a file's bytes, the same for every input language: byte flips,
truncation, spans deleted or repeated, splices from another file, huge numbers,
NaN and infinity, unicode, deep nesting, very long lines, many lines, CRLF, a BOM,
UTF-16. A language gives its words (inserted as they are) and how it nests."""

from __future__ import annotations

import random
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass

NUMBERS = (
    "0", "-0", "1", "-1", "0.5", "1e15", "-1e15", "1e300", "1e308", "1e309", "-1e400", "1e-400",
    "nan", "NaN", "inf", "-inf", "+inf", "Infinity", "18446744073709551617", "9" * 400,
    "9" * 5000, "1" + "0" * 4400, "0x10", "1_000", "1e99999999999", "٣", "１", "-", ".", "1e",
    "1.2.3", "007",
)  # fmt: skip
UNICODE = (
    "é", "\u202e", "\ufeff", "\x00", "\U0001f600", "e\u0301", "\u2028", "\x85", "\u00a0", "\t",
    "\r", "\x0c", "\x1b[2J", "ß", "𝟙", "\uffff", "\\", '"', "'", "\u0663",
)  # fmt: skip
_NUMBER = re.compile(rb"[-+]?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?")


@dataclass(frozen=True)
class Nest:
    """How a language nests: ``open`` repeated ``n`` times, ``inner``, ``close`` ``n`` times."""

    open: str
    close: str
    inner: str = ""


def _span(rng: random.Random, data: bytes) -> tuple[int, int]:
    if not data:
        return 0, 0
    i = rng.randrange(len(data))
    return i, min(len(data), i + rng.choice((1, 2, 5, 20, 100, 1000)))


def flip(rng: random.Random, data: bytes) -> bytes:
    out = bytearray(data or b" ")
    for _ in range(rng.choice((1, 1, 2, 4, 8))):
        out[rng.randrange(len(out))] ^= 1 << rng.randrange(8)
    return bytes(out)


def truncate(rng: random.Random, data: bytes) -> bytes:
    return data[: rng.randrange(len(data) + 1)]


def delete(rng: random.Random, data: bytes) -> bytes:
    i, j = _span(rng, data)
    return data[:i] + data[j:]


def repeat(rng: random.Random, data: bytes) -> bytes:
    i, j = _span(rng, data)
    return data[:j] + data[i:j] * rng.choice((2, 3, 10, 100)) + data[j:]


def number(rng: random.Random, data: bytes) -> bytes:
    spots = list(_NUMBER.finditer(data))
    if not spots:
        return insert(rng, data, rng.choice(NUMBERS))
    m = rng.choice(spots)
    return data[: m.start()] + rng.choice(NUMBERS).encode() + data[m.end() :]


def insert(rng: random.Random, data: bytes, text: str) -> bytes:
    i = rng.randrange(len(data) + 1)
    return data[:i] + text.encode("utf-8", "surrogatepass") + data[i:]


def long_line(rng: random.Random, data: bytes, word: str) -> bytes:
    size = rng.choice((10_000, 100_000, 1_000_000))
    if rng.random() < 0.5:
        word = rng.choice(("x", "9", " ", "#", "(", ",", "1 ", "\t", "é"))
    line = (word * (size // max(1, len(word)) + 1))[:size]
    lines = data.split(b"\n")
    k = rng.randrange(len(lines) + 1)
    return b"\n".join([*lines[:k], line.encode(), *lines[k:]])


def many_lines(rng: random.Random, data: bytes) -> bytes:
    lines = data.split(b"\n")
    k = rng.randrange(len(lines))
    n = rng.choice((1000, 10_000, 100_000))
    return b"\n".join([*lines[:k], *[lines[k]] * n, *lines[k + 1 :]])


def nest(rng: random.Random, data: bytes, how: Nest) -> bytes:
    n = rng.choice((40, 100, 300, 1000, 5000, 100_000))
    deep = how.open * n + how.inner + how.close * n * (rng.random() < 0.8)
    return insert(rng, data, deep) if rng.random() < 0.3 else data + b"\n" + deep.encode()


def splice(rng: random.Random, data: bytes, other: bytes) -> bytes:
    i, _ = _span(rng, data)
    j, k = _span(rng, other)
    return data[:i] + other[j:k] + data[i:]


def encoding(rng: random.Random, data: bytes) -> bytes:
    how = rng.choice(("crlf", "cr", "bom", "utf16", "utf16le", "latin1", "nul"))
    if how == "crlf":
        return data.replace(b"\n", b"\r\n")
    if how == "cr":
        return data.replace(b"\n", b"\r")
    if how == "bom":
        return b"\xef\xbb\xbf" + data
    if how == "nul":
        return data.replace(b" ", b"\x00", 3)
    text = data.decode("utf-8", "replace")
    if how == "latin1":
        return (text + "é").encode("latin-1", "replace")
    return text.encode("utf-16" if how == "utf16" else "utf-16-le")


def mutate(
    rng: random.Random,
    data: bytes,
    others: Sequence[bytes],
    words: Sequence[str],
    nesting: Nest | None,
    skip: frozenset[str] = frozenset(),
) -> tuple[bytes, str]:
    """``data`` with one to four mutations (none of those named in ``skip``); the bytes
    and their names."""
    ops: list[tuple[str, float, Callable[[bytes], bytes]]] = [
        ("flip", 3, lambda d: flip(rng, d)),
        ("truncate", 1, lambda d: truncate(rng, d)),
        ("delete", 2, lambda d: delete(rng, d)),
        ("repeat", 1, lambda d: repeat(rng, d)),
        ("number", 4, lambda d: number(rng, d)),
        ("word", 4, lambda d: insert(rng, d, rng.choice(words) + rng.choice((" ", "\n", "")))),
        ("unicode", 1, lambda d: insert(rng, d, rng.choice(UNICODE))),
        ("long-line", 0.4, lambda d: long_line(rng, d, rng.choice(words))),
        ("many-lines", 0.3, lambda d: many_lines(rng, d)),
        ("splice", 1, lambda d: splice(rng, d, rng.choice(others))),
        ("encoding", 0.5, lambda d: encoding(rng, d)),
    ]
    if nesting is not None:
        ops.append(("nest", 0.6, lambda d: nest(rng, d, nesting)))
    ops = [op for op in ops if op[0] not in skip]
    names = []
    for _ in range(rng.choice((1, 1, 2, 3, 4))):
        name, _w, op = rng.choices(ops, weights=[w for _, w, _ in ops])[0]
        data = op(data)
        names.append(name)
        if len(data) > 4_000_000:  # a case stays a case: a few MB at most
            data = data[:4_000_000]
    return data, "+".join(names)
