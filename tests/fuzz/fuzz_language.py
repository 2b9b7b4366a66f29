"""What a fuzzed input language is: its shipped files, the nasty cases written by
hand, its words, how it nests, and the command lines that read a case.

Case ``i`` of a language is the same on every run and every budget (its own seed,
``"NAME:i"``), so a bigger budget runs the smaller one's cases first, and a case is
found again by its number. Even numbers go to the hand-written cases while they
last; the rest mutate a shipped file (or, where the language has a generator, make
one from its grammar).
"""

from __future__ import annotations

import random
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

from fuzz_engine import ROOT, Case, Step
from fuzz_mutate import Nest, mutate

Steps = Callable[[random.Random, str, bytes], tuple[Step, ...]]


def files(*patterns: str) -> dict[str, bytes]:
    """The repository's files matching ``patterns`` (relative to its root), by name."""
    found = {p.name: p.read_bytes() for pat in patterns for p in sorted(ROOT.glob(pat))}
    assert found, f"no files match {patterns}"
    return found


@dataclass(frozen=True)
class Language:
    """One input language and how its cases are made.

    Attributes:
        name: as the table shows it.  suffix: the case file's suffix.
        seeds: shipped files to mutate, by name.
        nasty: hand-written cases (label, bytes).
        words: the language's words, inserted by the mutator.
        nesting: how it nests (None: it does not).
        steps: the command lines run on a case file.
        companions: files put beside every case (a script's SVG, its tune).
        grammar: makes a case from the grammar instead of a seed (or None).
        skip: mutations not made (the shell runs each line: a thousand copies of a
            line that moves are a thousand moves, work, not a hang).
    """

    name: str
    suffix: str
    seeds: dict[str, bytes]
    nasty: Sequence[tuple[str, bytes]]
    words: Sequence[str]
    nesting: Nest | None
    steps: Steps
    companions: dict[str, bytes] = field(default_factory=dict)
    grammar: Callable[[random.Random], bytes] | None = None
    skip: frozenset[str] = frozenset()

    def case(self, i: int) -> Case:
        """Case number ``i`` (the same on every run)."""
        rng = random.Random(f"{self.name}:{i}")
        if i % 2 == 0 and i // 2 < len(self.nasty):
            label, data = self.nasty[i // 2]
            label = f"{self.name} #{i} {label}"
        elif self.grammar is not None and rng.random() < 0.25:
            data = self.grammar(rng)
            label = f"{self.name} #{i} from the grammar"
        else:
            seed = rng.choice(sorted(self.seeds))
            data, how = mutate(
                rng,
                self.seeds[seed],
                list(self.seeds.values()),
                self.words,
                self.nesting,
                self.skip,
            )
            label = f"{self.name} #{i} {how} of {seed}"
        name = f"case{self.suffix}"
        return Case(label, {**self.companions, name: data}, self.steps(rng, name, data))

    def cases(self, n: int) -> list[Case]:
        """The first ``n`` cases."""
        return [self.case(i) for i in range(n)]


def one(*argv: str, when: str = "always", stdin: bytes | None = None) -> Step:
    return Step(tuple(argv), when, stdin, whole=stdin is None)  # type: ignore[arg-type]


def last(cases: Sequence[tuple[str, bytes]], slow: Sequence[str]) -> tuple[tuple[str, bytes], ...]:
    """``cases`` with those labelled in ``slow`` moved to the end, in their order."""
    assert set(slow) <= {label for label, _ in cases}, set(slow) - {label for label, _ in cases}
    return tuple(sorted(cases, key=lambda c: c[0] in slow))
