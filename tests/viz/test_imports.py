"""``import armkit`` and ``armkit --help`` load neither viser nor matplotlib (nor scipy)."""

from __future__ import annotations

import subprocess
import sys

HEAVY = ("viser", "matplotlib", "scipy")
PROBE = """
import sys
{action}
heavy = sorted({{m.split('.')[0] for m in sys.modules}} & set({heavy!r}))
print(','.join(heavy))
"""


def _loaded_after(action: str) -> str:
    code = PROBE.format(action=action, heavy=HEAVY)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    return out.stdout.strip().splitlines()[-1] if out.stdout.strip() else ""


def test_import_armkit_loads_no_viewer_or_plotting() -> None:
    assert _loaded_after("import armkit, armkit.viz") == ""


def test_armkit_help_loads_no_viewer_or_plotting() -> None:
    action = (
        "from armkit.cli import main\n"
        "import contextlib, io\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        "    try:\n"
        "        main(['--help'])\n"
        "    except SystemExit:\n"
        "        pass\n"
        "    try:\n"
        "        main(['view', '--help'])\n"
        "    except SystemExit:\n"
        "        pass\n"
    )
    assert _loaded_after(action) == ""


def test_the_probe_sees_a_module_when_it_is_loaded() -> None:
    assert _loaded_after("import viser") == "viser"
