"""Strike planning: contacts land on the beat on the emulated servos, infeasible
notes are listed with the time they have and need, loudness and latency act."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from music_doubles import Xylophone, omx_layout
from music_servos import played

from armkit.model import ArmModel, load_model
from armkit.music import (
    LatencyTable,
    PerformanceError,
    RangeError,
    StrikeParams,
    check_performance,
    group_move_predictor,
    parse_notelist,
    plan_performance,
    time_based_predictor,
    trapezoid_predictor,
)
from armkit.music._strike import contact

STICK = 0.13  # tool length with 001's stick gripper and the mallet [m]


@pytest.fixture(scope="module")
def arm() -> ArmModel:
    return load_model("openmanipulator_x").with_tool_length(STICK)


def test_contacts_land_on_the_beat_on_the_emulated_servos(arm: ArmModel) -> None:
    score = parse_notelist("tempo 40 mf C5 q E5 q G5 q C6 q snare q ff C5 q p C5 q", "t.txt")
    perf = plan_performance(score, omx_layout(), arm, time_based_predictor(arm))
    check_performance(perf)
    assert [s.time - perf.offset for s in perf.strikes] == pytest.approx(
        [n.onset for n in score.notes]
    )
    for strike, hit in zip(perf.strikes, played(perf, arm.home), strict=True):
        assert hit is not None, strike.target.note
        assert abs(hit.time - strike.time) < 0.2e-3  # tick and millisecond rounding included
        assert hit.below < 0.04  # the rebound lifts the stick off within 40 ms


def test_moves_are_in_time_order_and_start_at_zero(arm: ArmModel) -> None:
    perf = plan_performance(
        parse_notelist("tempo 40 C5 q D5 q", "t.txt"), omx_layout(), arm, time_based_predictor(arm)
    )
    times = [m.t for m in perf.moves]
    assert times == sorted(times) and times[0] == pytest.approx(0.0)
    assert [m.kind for m in perf.moves] == [
        "travel",
        "down",
        "rebound",
        "travel",
        "down",
        "rebound",
    ]
    assert perf.offset > 0.5  # the lead-in from home to the first hover


def test_too_fast_a_piece_lists_every_late_note_with_its_times(arm: ArmModel) -> None:
    score = parse_notelist("tempo 240 C5 e B6 e C5 e B6 e", "fast.txt")
    perf = plan_performance(score, omx_layout(), arm, time_based_predictor(arm))
    assert [p.reason for p in perf.problems] == ["too soon"] * 3
    for p in perf.problems:
        assert p.available == pytest.approx(0.125) and p.needed is not None and p.needed > 0.125
    with pytest.raises(PerformanceError) as err:
        check_performance(perf)
    assert "B6 at 0.125 s: 0.125 s after the previous note, needs" in str(err.value)
    assert str(err.value).count("after the previous note") == 3 and "--tempo" in str(err.value)
    needed = max(p.needed for p in perf.problems if p.needed)
    slower = plan_performance(
        score, omx_layout(), arm, time_based_predictor(arm), tempo=0.125 / needed * 0.99
    )
    check_performance(slower)


def test_a_lower_hover_buys_time(arm: ArmModel) -> None:
    score = parse_notelist("tempo 180 ff C5 q C5 q", "t.txt")
    perf = plan_performance(score, omx_layout(), arm, time_based_predictor(arm))
    check_performance(perf)
    first, second = perf.strikes
    assert second.hover < first.hover  # the second note had less time


def test_unreachable_notes_are_listed(arm: ArmModel) -> None:
    far = Xylophone("far", (0.40, -0.05, 0.02), (0.40, 0.05, 0.02), 60, 12)
    perf = plan_performance(
        parse_notelist("C4 q D4 q", "t.txt"), [far], arm, time_based_predictor(arm)
    )
    assert [p.reason for p in perf.problems] == ["unreachable", "unreachable"]
    assert not perf.strikes and "cannot reach" in str(perf.problems[0])


def test_notes_outside_the_range_are_refused_with_a_transposition(arm: ArmModel) -> None:
    with pytest.raises(RangeError, match=r"2 notes .*C4 at 0\.00 s.*--transpose 12"):
        plan_performance(
            parse_notelist("C4 q D4 q C5 q", "t.txt"), omx_layout(), arm, time_based_predictor(arm)
        )


def test_louder_notes_strike_faster(arm: ArmModel) -> None:
    score = parse_notelist("tempo 30 ppp C5 q mf C5 q fff C5 q", "t.txt")
    speeds = [
        s.speed
        for s in plan_performance(score, omx_layout(), arm, time_based_predictor(arm)).strikes
    ]
    assert speeds[0] < speeds[1] < speeds[2]


def test_latency_starts_the_stroke_earlier(arm: ArmModel) -> None:
    score = parse_notelist("tempo 40 C5 q E5 q", "t.txt")
    plain = plan_performance(score, omx_layout(), arm, time_based_predictor(arm))
    late = LatencyTable(((("xylophone", 76), 0.03),))
    shifted = plan_performance(score, omx_layout(), arm, time_based_predictor(arm), latency=late)
    down = [m for m in plain.moves if m.kind == "down"]
    down_late = [m for m in shifted.moves if m.kind == "down"]
    assert down_late[1].t - shifted.offset == pytest.approx(down[1].t - plain.offset - 0.03)
    assert down_late[0].t - shifted.offset == pytest.approx(down[0].t - plain.offset)


@pytest.mark.parametrize("make", [trapezoid_predictor, group_move_predictor])
def test_every_predictor_lands_its_own_profiles_on_the_beat(arm: ArmModel, make) -> None:  # type: ignore[no-untyped-def]
    predictor = make(arm)
    perf = plan_performance(
        parse_notelist("tempo 40 C5 q G5 q snare q", "t.txt"), omx_layout(), arm, predictor
    )
    downs = [m for m in perf.moves if m.kind == "down"]
    for strike, move in zip(perf.strikes, downs, strict=True):
        hit = contact(arm, move.profile, float(strike.target.point[2]))
        assert hit is not None and move.t + hit[0] == pytest.approx(strike.time, abs=1e-6)


def test_the_base_may_stand_elsewhere_in_the_scene(arm: ArmModel) -> None:
    T = np.eye(4)
    T[:3, 3] = [0.5, 0.2, 0.0]
    c, s = math.cos(0.3), math.sin(0.3)
    T[:2, :2] = [[c, -s], [s, c]]
    xylo, _ = omx_layout()
    moved = [
        replace(
            xylo,
            first_bar=tuple(T[:3, :3] @ xylo.first_bar + T[:3, 3]),
            last_bar=tuple(T[:3, :3] @ xylo.last_bar + T[:3, 3]),
        )
    ]
    score = parse_notelist("tempo 40 C5 q G5 q", "t.txt")
    here = plan_performance(score, [xylo], arm, time_based_predictor(arm))
    there = plan_performance(score, moved, arm, time_based_predictor(arm), T_world_base=T)
    assert [m.t for m in there.moves] == pytest.approx([m.t for m in here.moves])


def test_strike_params_are_checked() -> None:
    with pytest.raises(ValueError, match="hover"):
        StrikeParams(hover=0.005, min_hover=0.01)
    with pytest.raises(ValueError, match="soft"):
        StrikeParams(soft=0.0)


def test_a_timed_rebound_is_long_enough_from_anywhere_on_its_stroke(arm: ArmModel) -> None:
    """The driver checks a rebound's duration from its own estimate of where the joints
    are (somewhere on the stroke): the timed profile must be legal from every such pose."""
    from armkit.model import move_time
    from armkit.music import timed_predictor

    rebound, rng = timed_predictor(arm), np.random.default_rng(7)
    for _ in range(50):
        hover, through = (rng.uniform(-0.5, 0.5, arm.dof) for _ in range(2))
        share = rng.uniform(0.0, 1.0)
        q_now = hover + share * (through - hover)
        profile = rebound(q_now, hover, 1.0, np.vstack([hover, through]))
        for s in np.linspace(0.0, 1.0, 11):  # every pose the driver may think it is at
            asked = hover + s * (through - hover)
            move_time(arm, asked, hover, speed=1.0, duration=profile.duration)  # no InputError
        q, _, _ = profile.sample(np.array([0.0, profile.duration]))
        assert np.allclose(q[0], q_now) and np.allclose(q[1], hover, atol=2 * math.pi / 4096)
