"""--driver sim with a device as --port is refused (it was silently taken as the state
file), naming the port and the driver that opens it; a state file still works."""

from __future__ import annotations

from pathlib import Path

import pytest

from armkit import InputError, load_model
from armkit.cli import main
from armkit.connect import open_driver


@pytest.mark.parametrize(
    ("arm", "port", "driver"),
    [("openmanipulator_x", "/dev/ttyUSB0", "dynamixel"), ("owi535", "COM3", "owi535"),
     ("puma560", "/dev/null", "one of owi535, ssc32, maestro, dynamixel, feetech")],
)  # fmt: skip
def test_a_device_port_with_the_simulator_is_refused(
    arm: str, port: str, driver: str, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["--arm", arm, "--driver", "sim", "--port", port, "where"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert (
        f"driver sim simulates the {arm} and opens no port, but {port} looks like a device: " in err
    )
    assert f"(--driver {driver})" in err
    with pytest.raises(InputError, match="opens no port"):
        open_driver(load_model(arm), "sim", port)


def test_a_state_file_port_still_keeps_the_simulated_arm(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    state = tmp_path / "omx.json"
    assert main(["--port", str(state), "joints", "10", "0", "0", "0"]) == 0
    assert main(["--port", str(state), "where"]) == 0
    assert "waist 10.00" in capsys.readouterr().out
