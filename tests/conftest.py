"""Suite-wide: every test's own armkit config folder (``_own_config_dir``), and the tests
that talk to an emulator over a pseudo-terminal in wall-clock time.

Those tests check bytes and protocol behaviour, never a time, but the other end is a
thread of this process answering through the kernel's pty: on a machine whose cores
are busy it can answer after the client's (real-device) timeout, and the client then
sees "no reply". Such a test is run again, up to twice, before it counts as failed
(pytest-rerunfailures); a protocol mistake fails all three runs. While such a test
runs, the interpreter switches threads every 0.5 ms instead of 5 ms, because clients
such as the dynamixel-sdk poll the port in a busy loop that would otherwise keep the
emulator's thread waiting for the GIL. Everything in virtual
time (``--driver sim``, the World) is deterministic and never rerun.
"""

from __future__ import annotations

import sys
from collections.abc import Iterator

import pytest

PTY_FIXTURES = {"emu", "bus", "sdk_port", "ssc32_emu", "maestro_emu"}
PTY_MODULES = {"test_emulate.py", "test_port_lock.py", "test_search.py", "test_dxl_emulator.py"}


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    for item in items:
        fixtures = set(getattr(item, "fixturenames", ()))
        if fixtures & PTY_FIXTURES or item.path.name in PTY_MODULES:
            item.add_marker(pytest.mark.flaky(reruns=2, reruns_delay=0.5))


@pytest.fixture(autouse=True)
def _own_config_dir(
    tmp_path_factory: pytest.TempPathFactory, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Every test keeps armkit's files (simulated arms' state, calibrations, locks) in a
    folder of its own, never in the user's ``~/.config/armkit`` (a package's conftest may
    point it elsewhere)."""
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path_factory.mktemp("armkit-config")))


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
