"""Issue 10, done-when: thousands of random command lines and hundreds of mutated
model files through ``armkit.cli.main``, in-process. For every one: no traceback;
a refusal is a non-zero exit with exactly one ``armkit: error:`` line on stderr;
and a refused command leaves every simulated arm where it was (its state files
unchanged). Fixed seed (derandomized), bounded: 2,000 command lines and 500 model files
under ``ARMKIT_PROFILE=ci`` (.ci/run), 400 and 100 in ``make test`` (tests/budget.py)."""

from __future__ import annotations

import contextlib
import io
import os
import re
from importlib import resources
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from armkit.cli import main
from budget import cases

CLI_CASES = cases(full=2000, quick=400)
MODEL_CASES = cases(full=500, quick=100)
FUZZ = dict(
    derandomize=True,  # the fixed seed: the same cases on every run
    database=None,
    deadline=None,
    suppress_health_check=list(HealthCheck),
)

ARMS = ["openmanipulator_x", "lynx6", "owi535", "planar2", "al5d", "puma560"]
BAD_ARMS = ["nosucharm", "", "../x", "/nonexistent/arm.toml", "x.toml"]
DRIVERS = ["sim", "sim", "sim", "sim", "ssc32", "maestro", "dynamixel", "owi535", "nope"]
PORTS = [None, None, None, None, "emu", "/dev/nonexistent", "", "{tmp}/state.json"]
NUMBERS = [
    "0", "-0", "1", "-1", "0.1", "2", "10", "20", "30", "45", "-45", "60", "90", "-90",
    "100", "150", "170", "200", "-200", "250", "300", "450", "1000", "1e6", "-1e6", "1e15",
    "1e308", "-1e308", "1e-300", "nan", "inf", "-inf", "x", "", "1e", "0x10", "--", "1,5",
]  # fmt: skip
FILES = ["{tmp}/out.csv", "{tmp}/pic.png", "/nonexistent/dir/f.png", "{tmp}", "f.nosuch", ""]
OPTIONS = {
    "--pitch": NUMBERS, "--speed": NUMBERS, "--duration": NUMBERS, "--spacing": NUMBERS,
    "--radius": NUMBERS, "--sweep": NUMBERS, "--start": NUMBERS, "--fraction": NUMBERS,
    "--mode": ["naive", "early", "timed", "fast"], "--method": ["auto", "lm", "ccd", "newton"],
    "--record": FILES, "-o": FILES, "--plot": FILES, "--lift": NUMBERS,
    "--n": ["0", "1", "3", "-1", "1000000000", "x"], "--repeats": ["0", "1", "2", "99"],
    "--time-ms": ["0", "20", "-5", "70000", "x"], "--ids": ["11-15", "1", "300", "x", "5-1"],
    "--json": None, "--all": None, "--help": None,
}  # fmt: skip
COMMANDS: dict[str, tuple[int, list[str]]] = {  # command: (usual number of values, its options)
    "arms": (0, []),
    "show": (0, []),
    "fk": (4, ["--json"]),
    "ik": (3, ["--pitch", "--all", "--method", "--json"]),
    "plot": (4, ["-o"]),
    "move": (3, ["--pitch", "--speed", "--duration"]),
    "joints": (4, ["--speed", "--duration"]),
    "grip": (1, []),
    "home": (0, []),
    "where": (0, []),
    "draw circle": (
        0,
        [
            "--center",
            "--radius",
            "--sweep",
            "--start",
            "--pitch",
            "--spacing",
            "--speed",
            "--mode",
            "--record",
        ],
    ),
    "draw line": (6, ["--pitch", "--spacing", "--speed", "--mode", "--fraction", "--record"]),
    "draw rect": (0, ["--center", "--size", "--pitch", "--spacing", "--mode"]),
    "draw cube": (0, ["--corner", "--size", "--pitch", "--spacing"]),
    "servo": (2, ["--time-ms"]),
    "servo-table": (0, []),
    "compare-ik": (0, ["--n", "--repeats", "--plot", "--method"]),
    "rehome": (0, []),
    "light": (1, []),
    "pick-place": (6, ["--lift"]),
    "dxl-scan": (0, ["--ids"]),
    "nosuchcommand": (0, []),
}
TRIPLES = {"--center", "--corner"}
# what an error line must never show: numpy reprs, arrays, 309-digit numbers, Python internals
LEAKS = re.compile(r"np\.float64|array\(|\d{25,}|cannot convert|object has no attribute")


def _state_files(config: Path) -> dict[str, bytes]:
    """Every file that holds a simulated arm's pose (or an OWI's estimate)."""
    if not config.exists():
        return {}
    return {
        str(p.relative_to(config)): p.read_bytes() for p in config.rglob("*.json") if p.is_file()
    }


def run(argv: list[str], config: Path) -> tuple[int, str, str]:
    """``main(argv)`` in-process; fails the test on an exception (a traceback)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main(argv)
        except SystemExit as exc:  # only --help style exits; refusals return
            code = exc.code if isinstance(exc.code, int) else 1
        except BaseException as exc:
            pytest.fail(f"armkit {' '.join(argv)!r} raised {type(exc).__name__}: {exc}")
    return code, out.getvalue(), err.getvalue()


def check(argv: list[str], config: Path) -> int:
    """Run one command line and check the contract; returns its exit code."""
    before = _state_files(config)
    code, _out, err = run(argv, config)
    shown = f"armkit {' '.join(repr(a) if not a or ' ' in a else a for a in argv)}"
    assert "Traceback" not in err, f"{shown}\n{err}"
    errors = [line for line in err.splitlines() if not line.startswith("armkit: warning: ")]
    if code != 0:
        assert len(err.splitlines()) == 1, f"{shown}: exit {code} with stderr\n{err}"
        assert re.fullmatch(r"armkit: (error: .+|interrupted)", err.strip()), f"{shown}: {err}"
        assert not LEAKS.search(err), f"{shown}: not in the user's terms: {err}"
        assert _state_files(config) == before, f"{shown} was refused but moved the arm"
    else:
        assert errors == [], f"{shown}: exit 0 with errors\n{err}"
    return code


def _value(draw: st.DrawFn, choices: list[str]) -> str:
    return draw(st.sampled_from(choices))


@st.composite
def command_lines(draw: st.DrawFn) -> list[str]:
    """A command line a hurried new user might type: mostly plausible, often wrong."""
    argv: list[str] = []
    if draw(st.integers(0, 3)):
        argv += ["--arm", _value(draw, ARMS if draw(st.integers(0, 5)) else BAD_ARMS)]
    driver = _value(draw, DRIVERS)
    if driver != "sim" or draw(st.booleans()):
        argv += ["--driver", driver]
    port = draw(st.sampled_from(PORTS))
    if port is not None:
        argv += ["--port", port]
    command = draw(st.sampled_from(sorted(COMMANDS)))
    count, options = COMMANDS[command]
    argv += command.split()
    if command == "compare-ik":  # always a small --n: the default 1000 targets take seconds
        argv += _option(draw, "--n")
    count = max(0, count + draw(st.sampled_from([0, 0, 0, 0, -1, 1, -2])))
    argv += [_value(draw, NUMBERS) for _ in range(count)]
    if command == "light" and count:
        argv[-1] = draw(st.sampled_from(["on", "off", argv[-1]]))
    for option in draw(st.lists(st.sampled_from(options or ["--help"]), max_size=4)):
        argv += _option(draw, option)
    if draw(st.integers(0, 9)) == 0:  # a global option after the command
        argv += ["--arm", _value(draw, ARMS)]
    return argv


def _option(draw: st.DrawFn, option: str) -> list[str]:
    if option in TRIPLES:
        return [option, *(_value(draw, NUMBERS) for _ in range(draw(st.sampled_from([3, 3, 2]))))]
    if option == "--size":
        return [option, *(_value(draw, NUMBERS) for _ in range(draw(st.integers(1, 2))))]
    values = OPTIONS.get(option)
    return [option] if values is None else [option, _value(draw, values)]


@pytest.fixture(scope="module")
def fuzz_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("fuzz")


@pytest.fixture
def home(fuzz_dir: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """One config dir for the whole run (arms keep their pose from command to command)."""
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(fuzz_dir / "config"))
    monkeypatch.chdir(fuzz_dir)
    return fuzz_dir


def _expand(argv: list[str], tmp: Path) -> list[str]:
    return [a.replace("{tmp}", str(tmp)) for a in argv]


def test_random_command_lines(home: Path) -> None:
    codes: list[int] = []

    @settings(max_examples=CLI_CASES, **FUZZ)  # type: ignore[arg-type]
    @given(command_lines())
    def one(argv: list[str]) -> None:
        codes.append(check(_expand(argv, home), home / "config"))

    one()
    assert len(codes) >= CLI_CASES
    accepted = codes.count(0)
    assert accepted > CLI_CASES // 10 and len(codes) - accepted > CLI_CASES // 2  # both sides


def _shipped(name: str) -> str:
    return (resources.files("armkit.model") / "arms" / f"{name}.toml").read_text()


NUMBER = re.compile(r"(?<![\w.])-?\d+(\.\d+)?(e-?\d+)?(?![\w.])")
REPLACEMENTS = [
    "0", "0.0", "-1", "-130.0", "1e300", "-1e300", "1e-300", "nan", "inf", '"x"', "true",
    "[]", "[1, 2]", "{}", "90.0", "500", "4096", "-0.0", '"../../evil"', "3",
]  # fmt: skip


@st.composite
def mutated_models(draw: st.DrawFn) -> bytes:
    """A shipped model file with one to three mutations: a number replaced, a line
    dropped or doubled, a key renamed, a value's type changed, a stray byte."""
    text = _shipped(draw(st.sampled_from(ARMS)))
    for _ in range(draw(st.integers(1, 3))):
        text = _mutate(draw, text)
    data = text.encode()
    if draw(st.integers(0, 30)) == 0:
        k = draw(st.integers(0, len(data)))
        data = data[:k] + b"\xff\xfe" + data[k:]
    return data


def _mutate(draw: st.DrawFn, text: str) -> str:
    kind = draw(st.sampled_from(["number", "number", "number", "drop", "double", "rename", "name"]))
    lines = text.splitlines()
    if kind == "number":
        spots = list(NUMBER.finditer(text))
        if spots:
            m = draw(st.sampled_from(spots))
            return text[: m.start()] + draw(st.sampled_from(REPLACEMENTS)) + text[m.end() :]
    k = draw(st.integers(0, len(lines) - 1))
    if kind == "drop":
        del lines[k]
    elif kind == "double":
        lines.insert(k, lines[k])
    elif kind == "rename" and "=" in lines[k]:
        key, _, rest = lines[k].partition("=")
        lines[k] = key.rstrip() + "x =" + rest
    elif kind == "name":
        first = next(i for i, ln in enumerate(lines) if ln.startswith("name = "))
        lines[first] = 'name = "x/../../evil/out"'
    return "\n".join(lines) + "\n"


MODEL_COMMANDS = [
    ["show"],
    ["ik", "200", "0", "50"],
    ["fk", "0", "0", "0", "0"],
    ["move", "150", "0", "100"],
    ["where"],
    ["joints", "0", "30", "30", "0"],
    ["--driver", "ssc32", "servo-table"],
    ["home"],
]


def test_mutated_model_files(home: Path) -> None:
    path = home / "mutated.toml"
    loaded: list[bool] = []

    @settings(max_examples=MODEL_CASES, **FUZZ)  # type: ignore[arg-type]
    @given(mutated_models(), st.sampled_from(MODEL_COMMANDS))
    def one(data: bytes, command: list[str]) -> None:
        path.write_bytes(data)
        loaded.append(check(["--arm", str(path), "show"], home / "config") == 0)
        check(["--arm", str(path), *command], home / "config")

    one()
    assert len(loaded) >= MODEL_CASES
    assert 0 < sum(loaded) < len(loaded)  # some mutations are harmless, most are caught
    evil = [p for p in home.parent.rglob("*") if "evil" in p.name]
    assert evil == [], f"a model name wrote outside the config dir: {evil}"
    assert os.environ["ARMKIT_CONFIG_DIR"].startswith(str(home))
