"""Drawings: SVG and G-code files drawn on the ``drawing`` scene's sheet."""

from __future__ import annotations

import random

from fuzz_engine import Step
from fuzz_language import Language, files, last, one
from fuzz_mutate import Nest

SVG_HEAD = b'<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 100 100">\n'
SVG_WORDS = (
    "<", ">", "/>", '"', "=", "&", "&amp;", "&lt;", "&#0;", "&#x110000;", "&e;", "<!--", "-->",
    "<![CDATA[", "]]>", "<?xml ?>", "<g>", "</g>", "<path d='M0 0 L1e308 1e308'/>",
    "<circle r='1e30'/>", "<use xlink:href='#a'/>", "<text>x</text>", "<image href='x.png'/>",
    " d='M 0 0 A 1e-300 1e300 0 1 1 1 1'", " transform='scale(1e308)'", " viewBox='0 0 0 0'",
    " width='1e308mm'", " style='display:none'", " id='a'", "M", "L", "C", "Q", "A", "Z", "z",
)  # fmt: skip


def _svg(body: bytes, head: bytes = SVG_HEAD) -> bytes:
    return head + body + b"\n</svg>\n"


def _laughs(levels: int) -> bytes:
    ents = b'<!ENTITY lol0 "lol">\n' + b"".join(
        b'<!ENTITY lol%d "%s">\n' % (k, b"".join(b"&lol%d;" % (k - 1) for _ in range(10)))
        for k in range(1, levels)
    )
    return (
        b"<?xml version='1.0'?>\n<!DOCTYPE svg [\n"
        + ents
        + b"]>\n"
        + _svg(b"<text>&lol%d;</text>" % (levels - 1))
    )


def _uses(levels: int) -> bytes:
    """``use`` elements that each show the group before ten times: 10**levels paths."""
    body = b'<defs><g id="u0"><path d="M0 0 L1 1"/></g>\n'
    for k in range(1, levels):
        body += b'<g id="u%d">' % k + b'<use xlink:href="#u%d"/>' % (k - 1) * 10 + b"</g>\n"
    return _svg(body + b'</defs><use xlink:href="#u%d"/>' % (levels - 1))


SVG_NASTY = (
    ("a billion laughs", _laughs(10)),
    (
        "an external entity",
        b'<?xml version="1.0"?>\n<!DOCTYPE svg [<!ENTITY x SYSTEM "file:///etc/passwd">]>\n'
        + _svg(b"<text>&x;</text>"),
    ),
    (
        "an external entity over the network",
        b'<!DOCTYPE svg [<!ENTITY x SYSTEM "http://127.0.0.1:9/x">]>' + _svg(b"<text>&x;</text>"),
    ),
    ("an external DTD", b'<!DOCTYPE svg SYSTEM "http://127.0.0.1:9/svg.dtd">' + _svg(b"")),
    (
        "a parameter entity",
        b'<!DOCTYPE svg [<!ENTITY % p SYSTEM "file:///etc/passwd"> %p;]>' + _svg(b""),
    ),
    ("an undefined entity", _svg(b"<text>&nope;</text>")),
    ("groups nested 1000 deep", _svg(b"<g>" * 1000 + b'<path d="M0 0 L9 9"/>' + b"</g>" * 1000)),
    ("groups nested 100 000 deep", _svg(b"<g>" * 100_000 + b"</g>" * 100_000)),
    ("uses of uses: 10**8 paths", _uses(8)),
    ("a use that shows itself", _svg(b'<g id="a"><use xlink:href="#a"/></g>')),
    ("a circle of 1e30 px", _svg(b'<circle cx="50" cy="50" r="1e30"/>')),
    ("a scale of 1e308", _svg(b'<g transform="scale(1e308)"><circle r="10"/></g>')),
    ("an arc of 1e300 px", _svg(b'<path d="M0 0 A 1e300 1e300 0 1 1 1 0"/>')),
    ("100 000 circles", _svg(b'<circle cx="50" cy="50" r="10"/>' * 100_000)),
    ("a path of a million segments", _svg(b'<path d="M0 0' + b" L1 1 L0 0" * 500_000 + b'"/>')),
    ("a number of 5000 digits", _svg(b'<path d="M0 0 L' + b"9" * 5000 + b' 1"/>')),
    ("NaN and infinity", _svg(b'<path d="M nan inf L -inf 1e309"/><circle r="nan"/>')),
    ("UTF-16", _svg(b'<path d="M0 0 L9 9"/>').decode().encode("utf-16")),
    ("nothing", b""),
)
SVG_NASTY = last(
    SVG_NASTY, ["100 000 circles", "a path of a million segments", "groups nested 100 000 deep"]
)  # cheap cases first: `make test` runs the first few


def _svg_grammar(rng: random.Random) -> bytes:
    tags = ("path", "rect", "circle", "ellipse", "line", "polyline", "polygon", "g", "use")
    attrs = ("d", "transform", "points", "r", "cx", "cy", "x", "y", "width", "height", "rx")
    values = ("M 0 0 L 10 10", "M0,0 C 1 1 2 2 3 3 Z", "scale(2) rotate(30)", "0", "-5", "1e3",
              "1e400", "nan", "10 20 30", "matrix(1,0,0,1,0)", "#a", "", "50%", "2mm")  # fmt: skip
    body = b""
    for _ in range(rng.randint(1, 8)):
        tag = rng.choice(tags)
        a = " ".join(
            f'{rng.choice(attrs)}="{rng.choice(values)}"' for _ in range(rng.randint(0, 4))
        )
        body += f"<{tag} {a}/>\n".encode()
    return _svg(body)


def _draw_steps(kind: str) -> object:
    def steps(rng: random.Random, name: str, data: bytes) -> tuple[Step, ...]:
        draw = ("--scene", "drawing", "draw", kind, name)
        return (one(*draw, "--dry-run"), one(*draw, when="refused"))

    return steps


SVG = Language(
    name="SVG",
    suffix=".svg",
    seeds=files("examples/drawings/*.svg", "examples/scripts/square.svg"),
    nasty=SVG_NASTY,
    words=SVG_WORDS,
    nesting=Nest("<g>", "</g>", "<path d='M0 0 L1 1'/>"),
    steps=_draw_steps("svg"),  # type: ignore[arg-type]
    grammar=_svg_grammar,
)

GCODE_WORDS = (
    "G0", "G1", "G2", "G3", "G4 P1", "G17", "G18", "G20", "G21", "G28", "G90", "G91", "M2", "M3",
    "M5", "M30", "M300 S30", "M300 S50", "X", "Y", "Z", "I", "J", "F", "P", "S", "N", "(", ")",
    ";", "%", "X1e300", "I1e-300", "G2 X0 Y0 I1e9 J0", "G4 P1e300", "F0", "N99999999999999999999",
)  # fmt: skip
GCODE_NASTY = (
    ("a full circle of 1e9 mm", b"G21 G90\nM3\nG2 X0 Y0 I1e9 J0\nM5\n"),
    ("a full circle of 1e300 mm", b"M3\nG2 X0 Y0 I1e300 J0\n"),
    ("a dwell of 1e300 s", b"G4 P1e300\nG4 S1e300\n"),
    ("a number of 5000 digits", b"G1 X" + b"9" * 5000 + b" Y0\n"),
    ("a block number beyond any integer", b"N" + b"9" * 5000 + b" G0 X1\n"),
    ("a G code beyond any integer", b"G" + b"9" * 5000 + b"\n"),
    ("comments nested 100 000 deep", b"(" * 100_000 + b")" * 100_000 + b"\nG0 X1\n"),
    ("a line of a million characters", b"G1" + b" X1" * 333_333 + b"\n"),
    ("a million lines", b"M3\n" + b"G1 X1 Y1\nG1 X0 Y0\n" * 500_000),
    ("NaN and infinity", b"G1 Xnan Yinf\nG1 X-inf\nG1 X1e309\n"),
    ("UTF-16", "G21\nG1 X10 Y10\n".encode("utf-16")),
    ("nothing", b""),
)
GCODE_NASTY = last(
    GCODE_NASTY, ["a million lines", "a line of a million characters"]
)  # cheap cases first: `make test` runs the first few


GCODE = Language(
    name="G-code",
    suffix=".gcode",
    seeds=files("examples/drawings/*.gcode"),
    nasty=GCODE_NASTY,
    words=GCODE_WORDS,
    nesting=Nest("(", ")", "x"),
    steps=_draw_steps("gcode"),  # type: ignore[arg-type]
    grammar=lambda rng: "\n".join(
        " ".join(
            rng.choice(GCODE_WORDS)
            + (f"{rng.uniform(-300, 300):.3f}" if rng.random() < 0.5 else "")
            for _ in range(rng.randint(1, 5))
        )
        for _ in range(rng.randint(1, 30))
    ).encode(),
)
