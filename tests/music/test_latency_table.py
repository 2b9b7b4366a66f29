"""The per-bar latency table: its TOML file (read back as written, every mistake named
by file, line and key), the calibration pass that measures it in the simulator, and
``armkit play --calibrate OUT.toml`` / ``--latency TABLE.toml``."""

from __future__ import annotations

from pathlib import Path

import pytest

from armkit.cli import main
from armkit.music import LatencyError, LatencyTable, load_latency, save_latency

TUNES = Path(__file__).parents[2] / "examples" / "music"


def test_a_table_reads_back_as_written(tmp_path: Path) -> None:
    table = LatencyTable(((("snare", 38), 0.0123), (("xylophone", 72), -0.0015)), 0.01)
    back = load_latency(save_latency(table, tmp_path / "t.toml"))
    assert back.default == pytest.approx(0.01)
    assert [k for k, _ in back.delays] == [("snare", 38), ("xylophone", 72)]
    assert [d for _, d in back.delays] == pytest.approx([0.0123, -0.0015])
    assert back.of(("xylophone", 60)) == pytest.approx(0.01)


@pytest.mark.parametrize(
    ("text", "where", "problem"),
    [
        (
            "default_ms = 10\n[delays_ms.xylophone]\n72 = 'fast'\n",
            ":3: delays_ms.xylophone.72",
            "number of milliseconds",
        ),
        (
            "default_ms = 10\n\n[delays_ms.xylophone]\n72 = 900\n",
            ":4: delays_ms.xylophone.72",
            "outside -500..500 ms",
        ),
        (
            "default_ms = 10\n[delays_ms.xylophone]\nC5 = 9\n",
            ":3: delays_ms.xylophone.C5",
            "MIDI note number",
        ),
        ("default_ms = 10\ndelay = 3\n", ":2: delay", "unknown key"),
        ("default_ms = nan\n", ":1: default_ms", "number of milliseconds"),
        ("default_ms = \n", ":1:14: not valid TOML", "Invalid value"),
    ],
)
def test_a_bad_table_is_named_by_file_line_and_key(
    tmp_path: Path, text: str, where: str, problem: str
) -> None:
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(LatencyError) as caught:
        load_latency(path)
    message = str(caught.value)
    assert message.startswith(f"{path}{where}") and problem in message and "\n" not in message


def test_cli_calibrates_then_plays_with_the_table(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path))
    table = tmp_path / "lynx6.toml"
    base = ["--arm", "lynx6", "--scene", "xylophone.toml", "play"]
    assert main([*base, "--calibrate", str(table)]) == 0
    assert "calibrated 14 bars and drums" in capsys.readouterr().out  # 13 bars, a snare
    measured = load_latency(table)
    assert len(measured.delays) == 14 and 0.015 < measured.default < 0.04  # the SSC-32's lag
    assert main([*base, str(TUNES / "twinkle.rtttl"), "--latency", str(table)]) == 0
    out = capsys.readouterr().out
    assert "heard 14 contacts" in out and "0 missed, 0 extra" in out


def test_cli_refuses_a_bad_table_or_output_before_opening_the_arm(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    config = tmp_path / "config"
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(config))
    bad = tmp_path / "bad.toml"
    bad.write_text("default_ms = 10\n[delays_ms.xylophone]\n72 = 'fast'\n")
    tune = str(TUNES / "twinkle.rtttl")
    assert main(["--scene", "xylophone", "play", tune, "--latency", str(bad)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "bad.toml:3: delays_ms.xylophone.72" in err
    out = tmp_path / "none" / "t.toml"
    assert main(["--scene", "xylophone", "play", "--calibrate", str(out)]) == 2
    assert "does not exist" in capsys.readouterr().err
    assert main(["--scene", "xylophone", "play", "--calibrate", str(tmp_path / "t.txt")]) == 2
    assert "must end in .toml" in capsys.readouterr().err
    assert not config.exists()  # the simulated arm was not even opened


def test_cli_refuses_a_tune_too_fast_listing_its_notes(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path))
    wav = tmp_path / "out.wav"
    tune = str(TUNES / "twinkle.rtttl")
    assert main(["--scene", "xylophone", "play", tune, "--tempo", "300", "--wav", str(wav)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "notes of" in err and "needs" in err and "--tempo" in err
    assert not wav.exists()
