"""Every input language the fuzzers try, by name."""

from __future__ import annotations

from fuzz_cli import CLI
from fuzz_drawings import GCODE, SVG
from fuzz_scores import MIDI, NOTELIST, RTTTL
from fuzz_scripts import SCRIPTS, SHELL
from fuzz_tables import MODELS, SCENES

LANGUAGES = {
    lang.name: lang
    for lang in (SCRIPTS, SCENES, MODELS, SVG, GCODE, MIDI, RTTTL, NOTELIST, SHELL, CLI)
}
