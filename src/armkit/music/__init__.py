"""Music: scores, instrument mapping, strike planning and listening (pure, SI units).

Scores come from MIDI files (the ``midi`` extra), RTTTL or a plain note list and
become one typed ``Score`` (onsets in seconds, MIDI pitches). Notes map to the
bars and drums of a scene's instruments; ``plan_performance`` schedules every
strike backwards from its note time with the arm's motion model, and lists the
notes it cannot reach in time. Contacts (time, note, speed) become a WAV file
and onset-error statistics.
"""

from ._layout import Bars as Bars
from ._layout import DrumLike as DrumLike
from ._layout import RangeError as RangeError
from ._layout import Target as Target
from ._layout import best_transpose as best_transpose
from ._layout import map_notes as map_notes
from ._load import load_score as load_score
from ._midi import midi_bytes as midi_bytes
from ._midi import parse_midi as parse_midi
from ._midi import read_midi as read_midi
from ._notelist import parse_notelist as parse_notelist
from ._rtttl import parse_rtttl as parse_rtttl
from ._score import Note as Note
from ._score import Score as Score
from ._score import ScoreError as ScoreError
from ._score import note_name as note_name
from ._score import parse_pitch as parse_pitch
