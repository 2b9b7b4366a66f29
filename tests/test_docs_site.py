"""The documentation site's own rules, checked without building it (``make docs`` builds
it with --strict in CI): every page is in the navigation, the navigation names only
pages that exist, and the command reference covers every command the parser has."""

from __future__ import annotations

import importlib.util
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
HOOK = DOCS / "_hooks" / "cli_reference.py"


def _nav_pages() -> list[str]:
    text = (ROOT / "mkdocs.yml").read_text(encoding="utf-8")
    nav = text[text.index("\nnav:") :]
    return re.findall(r"([\w./-]+\.md)\s*$", nav, flags=re.M)


def _pages() -> set[str]:
    return {
        str(p.relative_to(DOCS))
        for p in DOCS.rglob("*.md")
        if not any(part.startswith("_") for part in p.relative_to(DOCS).parts)
    }


def test_every_page_is_in_the_navigation() -> None:
    missing = _pages() - set(_nav_pages())
    assert not missing, f"add these pages to the nav of mkdocs.yml: {sorted(missing)}"


def test_the_navigation_names_pages_that_exist() -> None:
    assert set(_nav_pages()) <= _pages()
    assert len(_nav_pages()) == len(set(_nav_pages()))


def _hook():  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location("cli_reference", HOOK)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_command_reference_has_every_command_with_its_help() -> None:
    from armkit.cli._app import build_parser

    hook = _hook()
    text = hook.markdown()
    parser = build_parser()
    words = [w for w, _, _ in hook.commands(parser)]
    assert len(words) >= 40 and ("draw", "circle") in words and ("scene", "reset") in words
    for command in words:
        assert re.search(rf"^#+ armkit {' '.join(command)}$", text, flags=re.M), command
        assert f"usage: armkit {' '.join(command)}" in text
    page = (DOCS / "reference" / "cli.md").read_text(encoding="utf-8")
    filled = hook.on_page_markdown(page, page=None)
    assert hook.MARKER not in filled and "armkit draw circle" in filled
