"""The root conftest's leak check fails a test that leaves a driver, an OWI exit guard, a
signal handler, a thread, an environment variable or a config file behind for the next
test, and leaves a test that cleans up alone. Each case runs a small test file through
pytest in this process (pytester), with the suite's own conftest and leak check."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

pytest_plugins = ["pytester"]
HERE = Path(__file__).parent

OWI = """
from armkit.devices.owi535 import open_device
from armkit.drivers.timed import TimedDriver, state_path
from armkit.model import load_model
from armkit.sim.owi_sim import build_sim

def owi():
    model = load_model("owi535")
    sim = build_sim(model, seed=7)
    return TimedDriver(model, open_device(sim.backend), sim.clock, state_path("t"), "t", durable=False)
"""
CASES = {
    "a driver left open: TimedDriver": OWI + "\nKEEP = []\ndef test_it():\n    KEEP.append(owi())\n",
    "an OWI exit guard": "from armkit.drivers.timed._safety import ExitGuard\ndef test_it():\n    ExitGuard(lambda: None).install()\n",
    "the SIGTERM handler": "import signal\ndef test_it():\n    signal.signal(signal.SIGTERM, lambda *a: None)\n",
    "a thread still running": "import threading\nE = threading.Event()\ndef test_it():\n    threading.Thread(target=E.wait, args=(3,), daemon=True).start()\n",
    "os.environ changed: ARMKIT_X": "import os\ndef test_it():\n    os.environ['ARMKIT_X'] = '1'\n",
    "session's config folder": "import os, pathlib\ndef test_it(monkeypatch):\n    monkeypatch.undo()\n    pathlib.Path(os.environ['ARMKIT_CONFIG_DIR'], 'sim_x.json').write_text('{}')\n",
}  # fmt: skip
OPTIONS = (
    "-p",
    "no:cacheprovider",
    "-p",
    "no:rerunfailures",
    "-p",
    "no:xdist",
)  # no server threads
CLEAN = OWI + "\ndef test_it():\n    d = owi()\n    d.read()\n    d.close()\n"


@pytest.fixture
def suite(pytester: pytest.Pytester) -> pytest.Pytester:
    for name in ("conftest.py", "leaks.py", "budget.py"):
        shutil.copy(HERE / name, pytester.path / name)
    return pytester


@pytest.mark.parametrize("leak", list(CASES))
def test_a_test_that_leaks_fails(suite: pytest.Pytester, leak: str) -> None:
    suite.makepyfile(test_one=CASES[leak])
    result = suite.runpytest_inprocess(*OPTIONS)
    result.assert_outcomes(passed=1, errors=1)
    assert "this test leaks state into later tests" in result.stdout.str()
    assert leak in result.stdout.str()


def test_a_test_that_cleans_up_passes(suite: pytest.Pytester) -> None:
    suite.makepyfile(test_one=CLEAN)
    result = suite.runpytest_inprocess(*OPTIONS)
    result.assert_outcomes(passed=1)
