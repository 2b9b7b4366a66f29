"""Music: scores, instrument mapping, strike planning and listening (pure, SI units).

Scores come from MIDI files (the ``midi`` extra), RTTTL or a plain note list and
become one typed ``Score`` (onsets in seconds, MIDI pitches). Notes map to the
bars and drums of a scene's instruments; ``plan_performance`` schedules every
strike backwards from its note time with the arm's motion model, and lists the
notes it cannot reach in time. Contacts (time, note, speed) become a WAV file
and onset-error statistics. ``play(arm, scene, file, on, tempo, transpose)`` is
the job (``armkit play``, the script's ``play``): planned and checked whole, then
sent at the planned times; in the simulator a ``Listener`` on the arm's World
hears every contact the mallet makes. ``plan_play(model, scene, file, ...)`` plans and
checks the same job on a model alone (``armkit check``). A tempo factor is
``MIN_TEMPO..MAX_TEMPO`` everywhere; a piece too fast is refused with the fastest tempo
the planner plays it at.
"""

from ._chords import CHORDS as CHORDS
from ._chords import ChordWarning as ChordWarning
from ._chords import one_line as one_line
from ._latency import LatencyError as LatencyError
from ._latency import calibrate as calibrate
from ._latency import calibration_score as calibration_score
from ._latency import load_latency as load_latency
from ._latency import save_latency as save_latency
from ._layout import Bars as Bars
from ._layout import DrumLike as DrumLike
from ._layout import RangeError as RangeError
from ._layout import StrikeSpot as StrikeSpot
from ._layout import best_transpose as best_transpose
from ._layout import map_notes as map_notes
from ._listen import Listener as Listener
from ._listen import Surface as Surface
from ._load import load_score as load_score
from ._midi import midi_bytes as midi_bytes
from ._midi import parse_midi as parse_midi
from ._midi import read_midi as read_midi
from ._notelist import parse_notelist as parse_notelist
from ._onsets import Contact as Contact
from ._onsets import LatencyTable as LatencyTable
from ._onsets import NoteError as NoteError
from ._onsets import OnsetStats as OnsetStats
from ._onsets import match as match
from ._onsets import onset_stats as onset_stats
from ._performance import Move as Move
from ._performance import Performance as Performance
from ._performance import PerformanceError as PerformanceError
from ._performance import Problem as Problem
from ._performance import Strike as Strike
from ._performance import check_performance as check_performance
from ._plan import plan_performance as plan_performance
from ._play import Played as Played
from ._play import check_tempo as check_tempo
from ._play import check_transpose as check_transpose
from ._play import instruments as instruments
from ._play import perform as perform
from ._play import performance_plan as performance_plan
from ._play import plan_play as plan_play
from ._play import play as play
from ._play import prepare as prepare
from ._play import score_on as score_on
from ._plot import PLOT_SUFFIXES as PLOT_SUFFIXES
from ._plot import plot_onsets as plot_onsets
from ._predict import JointProfile as JointProfile
from ._predict import LinearMove as LinearMove
from ._predict import Predictor as Predictor
from ._predict import Rebound as Rebound
from ._predict import group_move_predictor as group_move_predictor
from ._predict import time_based_predictor as time_based_predictor
from ._predict import timed_predictor as timed_predictor
from ._predict import trapezoid_predictor as trapezoid_predictor
from ._rtttl import parse_rtttl as parse_rtttl
from ._score import MAX_TEMPO as MAX_TEMPO
from ._score import MIN_TEMPO as MIN_TEMPO
from ._score import Note as Note
from ._score import Score as Score
from ._score import ScoreError as ScoreError
from ._score import note_name as note_name
from ._score import parse_pitch as parse_pitch
from ._score import tempo_range as tempo_range
from ._servos import servo_kind as servo_kind
from ._strike import StrikeParams as StrikeParams
from ._strike import StrikePoses as StrikePoses
from ._synth import frequency as frequency
from ._synth import render as render
from ._synth import write_wav as write_wav
