"""Errors of the scene package."""

from __future__ import annotations

from .._errors import ModelError


class SceneError(ModelError, ValueError):
    """A scene file is missing, malformed or inconsistent; the message names the
    file and the field. Also a ``ValueError``: it is a bad value the user gave."""
