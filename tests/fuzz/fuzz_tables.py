"""TOML inputs: scene files (``--scene FILE``) and arm model files (``--arm FILE``)."""

from __future__ import annotations

import random

from fuzz_engine import Step
from fuzz_language import Language, files, one
from fuzz_mutate import Nest

TOML_WORDS = (
    "=", "[", "]", "{", "}", ",", '"', "'", '"""', "#", ".", "[[cubes]]", "[[boards]]",
    "[[xylophones]]", "[[drums]]", "[[sheets]]", "[[pens]]", "[[hands]]", "[[containers]]",
    "[base]", "[tool]", "[gripper]", "[[joints]]", "[drivers.ssc32]", "[links]", "name = \"x\"",
    "true", "false", "1979-05-27T07:32:00Z", "[]", "{}", "size_mm = [1e308, 1e308, 1e308]",
    "rows = 50", "cols = 50", "position_mm = [0, 0, 0]", "on = \"red\"", "note = 200",
    "bars = [{ note = \"C5\", top_mm = [1, 2, 3], size_mm = [1, 1] }]", "limits_deg = [-1e9, 1e9]",
)  # fmt: skip


def _deep(opener: str, closer: str, depth: int, key: str = "name") -> bytes:
    return f"{key} = {opener * depth}{closer * depth}\n".encode()


def _many(table: str, body: str, count: int) -> bytes:
    return "".join(f"[[{table}]]\n{body.format(k=k)}\n" for k in range(count)).encode()


CUBE = 'name = "c{k}"\nsize_mm = 25\nposition_mm = [200, 0, {z}]'
TABLE_NASTY = (
    ("arrays nested 1000 deep", _deep("[", "]", 1000)),
    ("arrays nested 100 000 deep", _deep("[", "]", 100_000)),
    ("inline tables nested 1000 deep", b"name = " + b"{a = " * 1000 + b"1" + b"}" * 1000 + b"\n"),
    ("a dotted header 10 000 keys deep", b"[" + b".".join([b"a"] * 10_000) + b"]\nb = 1\n"),
    ("an integer of 5000 digits", b'name = "x"\ntable_z_mm = ' + b"9" * 5000 + b"\n"),
    ("an integer beyond a float", b'name = "x"\ntable_z_mm = 1' + b"0" * 400 + b"\n"),
    ("infinity and NaN", b'name = "x"\ntable_z_mm = inf\n[base]\nxyz_mm = [nan, -inf, 1e309]\n'),
    ("a line of a million characters", b'name = "' + b"x" * 1_000_000 + b'"\n'),
    ("a comment of ten megabytes", b"#" + b"x" * 10_000_000 + b"\n"),
    ("a BOM and CRLF", b'\xef\xbb\xbfname = "x"\r\n'),
    ("UTF-16", 'name = "x"\n'.encode("utf-16")),
    ("a NUL", b'name = "x\x00"\n'),
)
SCENE_NASTY = (
    *TABLE_NASTY,
    ("10 000 cubes", _many("cubes", CUBE.replace("{z}", "0"), 10_000).replace(b"{k}", b"")),
    (
        "1000 cubes stacked",
        b'name = "s"\n'
        + b"".join(
            f'[[cubes]]\nname = "c{k}"\nsize_mm = 25\n'.encode()
            + (b"position_mm = [200, 0, 0]\n" if k == 0 else f'on = "c{k - 1}"\n'.encode())
            for k in range(1000)
        ),
    ),
    (
        "a 50 x 50 board of 10 m",
        b'name = "b"\n[[boards]]\nname = "b"\norigin_mm = [0, 0, 0]\n'
        b"rows = 50\ncols = 50\npitch_mm = 199\nsocket_size_mm = 198\nsocket_depth_mm = 1\n"
        b"thickness_mm = 2\nsize_mm = [10000, 10000]\n",
    ),
    (
        "a xylophone of 10 000 bars",
        b'name = "x"\n[[xylophones]]\nname = "x"\nbars = ['
        + b",".join(
            b'{ note = "C5", top_mm = [180, 0, 20], size_mm = [60, 20] }' for _ in range(10_000)
        )
        + b"]\n",
    ),
    (
        "a sheet of 10 m by 1e-9 mm",
        b'name = "s"\n[[sheets]]\nname = "s"\nsize_mm = [10000, 1e-9]\n'
        b"origin_mm = [100, 0, 0]\nu = [1, 0, 0]\nv = [0, 1, 0]\n",
    ),
)
MODEL_NASTY = (
    *TABLE_NASTY,
    ("12 joints of 10 m", b'name = "m"\ndh_convention = "standard"\n' + b"".join(
        f'[[joints]]\nname = "j{k}"\nlimits_deg = [-180, 180]\nhome_deg = 0\n'
        "dh = { a_mm = 10000, alpha_deg = 90, d_mm = 10000 }\n".encode() for k in range(12))),
    ("1000 joints", b'name = "m"\ndh_convention = "standard"\n' + b"".join(
        f'[[joints]]\nname = "j{k}"\nlimits_deg = [-180, 180]\nhome_deg = 0\n'
        "dh = { a_mm = 10, alpha_deg = 0, d_mm = 0 }\n".encode() for k in range(1000))),
)  # fmt: skip

SCENE_MOVES = (("move", "180", "0", "120"), ("home",), ("where",), ("joints", "0", "0", "0", "0"))


def _scene_steps(rng: random.Random, name: str, data: bytes) -> tuple[Step, ...]:
    return (one("--scene", name, "scene", "show"), one("--scene", name, *rng.choice(SCENE_MOVES)))


SCENES = Language(
    name="scene files",
    suffix=".toml",
    seeds=files("src/armkit/scene/scenes/*.toml"),
    nasty=SCENE_NASTY,
    words=TOML_WORDS,
    nesting=Nest("[", "]", "1"),
    steps=_scene_steps,
)

MODEL_COMMANDS = (
    ("show",), ("ik", "200", "0", "50"), ("fk", "0", "0", "0", "0"), ("move", "150", "0", "100"),
    ("where",), ("joints", "0", "30", "30", "0"), ("--driver", "ssc32", "servo-table"), ("home",),
)  # fmt: skip


def _model_steps(rng: random.Random, name: str, data: bytes) -> tuple[Step, ...]:
    return (one("--arm", name, "show"), one("--arm", name, *rng.choice(MODEL_COMMANDS)))


MODELS = Language(
    name="model files",
    suffix=".toml",
    seeds=files("src/armkit/model/arms/*.toml"),
    nasty=MODEL_NASTY,
    words=TOML_WORDS,
    nesting=Nest("[", "]", "1"),
    steps=_model_steps,
)
