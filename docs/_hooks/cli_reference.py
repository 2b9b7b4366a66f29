"""MkDocs hook: the CLI reference page, written from the ``armkit`` parser at every build.

``docs/reference/cli.md`` holds the marker ``<!-- armkit-cli-reference -->``; this hook puts
in its place one section per command (and per sub-command, as ``draw circle``), each with
the help text argparse prints for it. The page is built from the parser that ``armkit``
runs, so it cannot drift from it. ``markdown()`` is what tests/test_docs_site.py reads.
"""

from __future__ import annotations

import argparse
import os
from collections.abc import Iterator
from typing import Any

MARKER = "<!-- armkit-cli-reference -->"
WIDTH = "100"  # columns argparse formats help for, whatever the terminal that builds


def commands(
    parser: argparse.ArgumentParser, words: tuple[str, ...] = ()
) -> Iterator[tuple[tuple[str, ...], argparse.ArgumentParser, str]]:
    """(words, sub-parser, one-line help) for every command and sub-command, in order."""
    for action in parser._actions:
        if not isinstance(action, argparse._SubParsersAction):
            continue
        helps = {a.dest: a.help or "" for a in action._choices_actions}
        for name, sub in action.choices.items():
            yield (*words, name), sub, helps.get(name, "")
            yield from commands(sub, (*words, name))


def markdown() -> str:
    """The reference: the global options, then every command's --help."""
    from armkit.cli._app import build_parser

    saved = os.environ.get("COLUMNS")
    os.environ["COLUMNS"] = WIDTH
    try:
        parser = build_parser()
        parts = ["## Global options", "", "```text", parser.format_help().rstrip(), "```", ""]
        for words, sub, help_ in commands(parser):
            title = " ".join(words)
            level = "#" * (1 + len(words))
            text = sub.format_help().rstrip()
            parts += [f"{level} armkit {title}", "", help_, ""]
            parts += ["```text", text, "```", ""]
        return "\n".join(parts)
    finally:
        if saved is None:
            del os.environ["COLUMNS"]
        else:
            os.environ["COLUMNS"] = saved


def on_page_markdown(text: str, page: Any, **_: Any) -> str:
    """MkDocs' page hook: fill the marker of the CLI reference page."""
    return text.replace(MARKER, markdown()) if MARKER in text else text
