"""The drawing package's error and warning.

A ``DrawingError`` is an ``ArmkitError`` and a ``ValueError`` (the input is a
bad value). It names the file and, where the format has them, the line and
column (1-based) of the problem, so one line at the CLI says where to look.
"""

from __future__ import annotations

from .._errors import ArmkitError, ArmkitWarning


class DrawingError(ArmkitError, ValueError):
    """A drawing (SVG, G-code, shapes) cannot be read or planned; the message starts
    with ``FILE:LINE:COL:`` where the format has lines, else ``FILE:``.

    Attributes:
        file: the file's name as given ("" for drawings made in code).
        line: 1-based line of the problem, or None where the format has none.
        column: 1-based column, or None.
    """

    def __init__(
        self, what: str, *, file: str = "", line: int | None = None, column: int | None = None
    ) -> None:
        where = file
        if line is not None:  # FILE:LINE:COL, as editors and terminals read it
            where = f"{file or '<drawing>'}:{line}:{column or 1}"
        super().__init__(f"{where.strip()}: {what}" if where else what)
        self.file, self.line, self.column = file, line, column


class DrawingWarning(ArmkitWarning):
    """Something in a drawing was left out (text in an SVG, a part cut at the sheet's edge)."""
