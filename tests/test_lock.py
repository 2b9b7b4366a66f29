"""One process per arm: the lock refuses a second holder and dies with its holder."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from armkit import DeviceError
from armkit._lock import exclusive, held, lock_path_for


def test_second_holder_is_refused_with_the_pid(tmp_path: Path) -> None:
    state = tmp_path / "state.json"
    code = (
        "import sys, time; from armkit._lock import exclusive; "
        f"lock = exclusive({str(state)!r}, 'x'); print('held', flush=True); time.sleep(30)"
    )
    child = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    try:
        assert child.stdout is not None and child.stdout.readline().strip() == "held"
        with pytest.raises(DeviceError, match=rf"the arm is in use by process {child.pid}"):
            exclusive(state, "the arm")
    finally:
        child.kill()
        child.wait()
    with held(state, "the arm") as lock:  # the kernel released the dead holder's lock
        assert lock.held
    assert not lock.held


def test_release_is_idempotent_and_relock_works(tmp_path: Path) -> None:
    lock = exclusive(tmp_path / "s.json", "s")
    lock.release()
    lock.release()
    exclusive(tmp_path / "s.json", "s").release()


def test_device_paths_lock_in_the_config_dir(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path))
    assert lock_path_for("/dev/ttyUSB0") == tmp_path / "locks" / "dev_ttyUSB0.lock"
    assert lock_path_for(tmp_path / "a.json") == tmp_path / "a.json.lock"


def test_unwritable_directory_is_a_device_error(tmp_path: Path) -> None:
    blocker = tmp_path / "file"
    blocker.write_text("")
    with pytest.raises(DeviceError, match="cannot create the lock"):
        exclusive(blocker / "sub" / "state.json", "x")
