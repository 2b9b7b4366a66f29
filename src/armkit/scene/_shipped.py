"""The scenes shipped with armkit (their names only: listing them loads no geometry)."""

from __future__ import annotations

from .._toml_files import shipped


def shipped_scenes() -> list[str]:
    """Names of the scenes shipped with armkit, sorted."""
    return shipped("armkit.scene", "scenes")
