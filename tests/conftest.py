"""Suite-wide: every test's own armkit config folder (``config_dir``), hypothesis profiles,
a check that no test leaks state into another, and the tests that talk to an emulator
over a pseudo-terminal in wall-clock time.

**Config folder.** Every test keeps armkit's files (simulated arms' state, calibrations,
locks) in ``tmp_path / "config"`` (the ``config_dir`` fixture, autouse), never in the
user's ``~/.config/armkit`` nor in another test's folder.

**Profiles.** ``ARMKIT_PROFILE=ci`` (``.ci/run``) runs the full fuzz and property budgets;
without it (``make test``, a developer) the quick ones (``budget.cases(full, quick)``
for the tests that set their own number of cases, hypothesis' ``dev`` profile for the
others). Both derandomize: the same cases on every run, as the project's tests require.

**Leaks.** After each test (its fixtures torn down), ``_no_leaks`` fails the test if it left
behind what would change another test: a driver still open, an exit guard (an ``atexit``
hook, or a SIGTERM/SIGHUP/SIGINT/SIGTSTP handler: a leaked OWI guard once turned a SIGTERM
into ``SystemExit: 143`` inside an unrelated test), a thread still running, ``os.environ``
changed (``ARMKIT_CONFIG_DIR`` included), or files written into the session's guard folder
(where armkit's files would go outside a test's own folder). The leak is undone before the
next test, so one leak fails one test.

**Pseudo-terminals.** Tests that talk to an emulator over a pty check bytes and protocol
behaviour, never a time, but the other end is a thread of this process answering through
the kernel's pty: on a machine whose cores are busy it can answer after the client's
(real-device) timeout, and the client then sees "no reply". Such a test is run again, up to
twice, before it counts as failed (pytest-rerunfailures); a protocol mistake fails all
three runs. While such a test runs, the interpreter switches threads every 0.5 ms instead
of 5 ms, because clients such as the dynamixel-sdk poll the port in a busy loop that would
otherwise keep the emulator's thread waiting for the GIL. Everything in virtual time
(``--driver sim``, the World) is deterministic and never rerun.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Protocol, TypeVar

import pytest
from hypothesis import HealthCheck, settings

from alone import turn
from leaks import Snapshot, track_drivers


class Closeable(Protocol):
    def close(self) -> None: ...


PTY_FIXTURES = {"emu", "bus", "sdk_port", "ssc32_emu", "maestro_emu"}
PTY_MODULES = {"test_emulate.py", "test_port_lock.py", "test_search.py", "test_dxl_emulator.py"}
ALONE_FOLDERS = {"emulate"}  # tests/emulate/: emulators under a deliberate CPU load (alone.py)

settings.register_profile(
    "ci", derandomize=True, database=None, deadline=None, max_examples=100
)  # hypothesis' own default number of examples
settings.register_profile(
    "dev",
    derandomize=True,
    database=None,
    deadline=None,
    max_examples=40,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.load_profile("ci" if os.environ.get("ARMKIT_PROFILE") == "ci" else "dev")


def pytest_configure(config: pytest.Config) -> None:
    """Start keeping count of the drivers and exit guards that tests open."""
    config.addinivalue_line("markers", "alone: no other test runs beside it (tests/alone.py)")
    track_drivers()


@pytest.fixture(autouse=True)
def _turn(
    request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory
) -> Iterator[None]:
    """Beside other tests, or alone (the ``alone`` marker), across pytest-xdist's workers."""
    base = tmp_path_factory.getbasetemp()  # under xdist, its parent is the run's, shared
    shared = base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base
    with turn(shared, alone=request.node.get_closest_marker("alone") is not None):
        yield


@pytest.fixture(scope="session")
def _guard_folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The folder ``ARMKIT_CONFIG_DIR`` names between tests: it must stay empty."""
    folder = tmp_path_factory.mktemp("armkit-config-guard")
    os.environ["ARMKIT_CONFIG_DIR"] = str(folder)
    return folder


@pytest.fixture(autouse=True)
def _no_leaks(_guard_folder: Path) -> Iterator[None]:
    """Fail the test that leaves a driver, exit guard, thread, environment change or
    config file behind (see the module's docstring)."""
    before = Snapshot.take()
    yield
    problems = before.leaks_since(guard=_guard_folder)
    if problems:
        pytest.fail("this test leaks state into later tests:\n- " + "\n- ".join(problems))


@pytest.fixture(autouse=True)
def config_dir(_no_leaks: None, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """This test's own armkit config folder, ``tmp_path / "config"`` (``ARMKIT_CONFIG_DIR``;
    created by armkit when it first writes there)."""
    folder = tmp_path / "config"
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(folder))
    return folder


C = TypeVar("C", bound=Closeable)


@pytest.fixture
def closes(request: pytest.FixtureRequest) -> Callable[[C], C]:
    """``arm = closes(Arm(...))``: the arm (a driver, anything with ``close``) is closed when
    the test ends, however it ends, so no driver or exit guard outlives its test."""

    def register(thing: C) -> C:
        request.addfinalizer(thing.close)
        return thing

    return register


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    for item in items:
        if item.path.parent.name in ALONE_FOLDERS:
            item.add_marker(pytest.mark.alone)
        fixtures = set(getattr(item, "fixturenames", ()))
        if fixtures & PTY_FIXTURES or item.path.name in PTY_MODULES:
            item.add_marker(pytest.mark.flaky(reruns=2, reruns_delay=0.5))


@pytest.fixture(autouse=True)
def _quick_thread_switches(request: pytest.FixtureRequest) -> Iterator[None]:
    if not set(request.fixturenames) & PTY_FIXTURES and request.path.name not in PTY_MODULES:
        yield
        return
    before = sys.getswitchinterval()
    sys.setswitchinterval(0.0005)
    try:
        yield
    finally:
        sys.setswitchinterval(before)
