"""A wheel (pip install without -e, an sdist) carries every data file armkit reads:
each file under src/armkit that is not Python source, a C source or a build product
matches one of pyproject.toml's package-data globs (the scene files were missing: a
wheel's `armkit --help` crashed listing the shipped scenes)."""

from __future__ import annotations

import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "src" / "armkit"
NOT_DATA = {".py", ".c", ".so", ".pyc"}


def test_every_data_file_is_in_package_data() -> None:
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())
    globs = config["tool"]["setuptools"]["package-data"]["armkit"]
    data = [
        p.relative_to(PACKAGE)
        for p in PACKAGE.rglob("*")
        if p.is_file() and p.suffix not in NOT_DATA and "__pycache__" not in p.parts
    ]
    assert data, "no data files found: the test reads the wrong folder"
    missing = [str(p) for p in data if not any(p.match(g) for g in globs)]
    assert not missing, f"add to [tool.setuptools.package-data] in pyproject.toml: {missing}"
