"""The XM430-W350's operating modes and the NOTEs of its control table, through the
official SDK's packet handler (ROBOTIS e-Manual, "XM430-W350"; section per test)."""

from __future__ import annotations

import pytest
from dxl_bench import GOAL, OK, PRESENT, TORQUE, Bench

MODE, DRIVE, HOMING, WATCHDOG, GOAL_PWM, GOAL_CURRENT, GOAL_VELOCITY = 11, 10, 20, 98, 100, 102, 104
PROFILE_ACCEL, PROFILE_VELOCITY, PRESENT_VELOCITY, MOVING = 108, 112, 128, 122
TICKS_PER_S_PER_UNIT = 0.229 * 4096 / 60  # Goal/Present Velocity unit [tick/s]


@pytest.fixture
def b() -> Bench:
    return Bench()


def test_velocity_control_mode_turns(b: Bench) -> None:
    """ "Operating Mode (11)" 1, Velocity Control Mode; "Goal Velocity (104)": the shaft
    turns at Goal Velocity x 0.229 rev/min, endlessly; Present Velocity reads it."""
    assert b.w(11, MODE, 1, 1) == (OK, 0)
    b.w(11, TORQUE, 1, 1)
    start = b.r(11, PRESENT, 4)
    assert b.w(11, GOAL_VELOCITY, 4, 100) == (OK, 0)
    b.world.advance(2.0)
    assert b.r(11, PRESENT, 4) - start == pytest.approx(2.0 * 100 * TICKS_PER_S_PER_UNIT, abs=2)
    assert b.r(11, PRESENT_VELOCITY, 4) == 100 and b.r(11, MOVING, 1) == 1
    b.world.advance(20.0)  # past a whole turn: the count goes on
    assert b.r(11, PRESENT, 4) > 4096 + start
    assert b.w(11, GOAL_VELOCITY, 4, -200) == (OK, 0)
    b.world.advance(1.0)
    assert b.r(11, PRESENT_VELOCITY, 4) == -200


def test_velocity_mode_accelerates_with_profile_acceleration(b: Bench) -> None:
    """ "Profile Velocity (112)", NOTE: Velocity Control Mode uses only Profile
    Acceleration; t1 = 64 x Goal Velocity / Profile Acceleration [ms]."""
    b.w(11, MODE, 1, 1), b.w(11, TORQUE, 1, 1)
    b.w(11, PROFILE_ACCEL, 4, 64)  # 100 units in 64 x 100 / 64 = 100 ms
    b.w(11, GOAL_VELOCITY, 4, 100)
    b.world.advance(0.05)
    assert b.r(11, PRESENT_VELOCITY, 4) == pytest.approx(50, abs=2)
    b.world.advance(0.06)
    assert b.r(11, PRESENT_VELOCITY, 4) == 100


def test_pwm_control_mode_turns_at_the_unloaded_speed(b: Bench) -> None:
    """ "Operating Mode (11)" 16, PWM Control Mode; "Goal PWM (100)": full duty (885) runs
    the unloaded motor at its no-load speed (46 rev/min at 12 V, Specifications); half
    duty at half of it."""
    b.w(11, MODE, 1, 16), b.w(11, TORQUE, 1, 1)
    start = b.r(11, PRESENT, 4)
    assert b.w(11, GOAL_PWM, 2, 885 // 2) == (OK, 0)
    b.world.advance(1.0)
    turned = b.r(11, PRESENT, 4) - start
    assert turned == pytest.approx(46 / 60 * 4096 * 442 / 885, abs=2)
    assert b.r(11, 124, 2) == 442  # Present PWM


def test_extended_position_mode_counts_turns(b: Bench) -> None:
    """ "Operating Mode (11)" 4, Extended Position Control Mode: goals beyond one turn,
    -1,048,575 ~ 1,048,575."""
    b.w(11, MODE, 1, 4), b.w(11, TORQUE, 1, 1)
    assert b.w(11, GOAL, 4, 3 * 4096 + 7) == (OK, 0)
    b.world.advance(30.0)
    assert b.r(11, PRESENT, 4) == 3 * 4096 + 7


def test_current_based_position_mode_moves_to_its_goal(b: Bench) -> None:
    """ "Operating Mode (11)" 5, Current-based Position Control Mode: position control
    (the gripper's mode), goals over many turns."""
    b.w(15, MODE, 1, 5), b.w(15, TORQUE, 1, 1)
    assert b.w(15, GOAL, 4, -5000) == (OK, 0)
    b.world.advance(30.0)
    assert b.r(15, PRESENT, 4) == -5000


def test_a_mode_change_resets_the_profile_and_the_goals(b: Bench) -> None:
    """ "Operating Mode (11)", NOTE: switching resets Profile Velocity and Profile
    Acceleration to 0, Goal PWM and Goal Current to PWM Limit and Current Limit."""
    b.w(11, 36, 2, 800), b.w(11, 38, 2, 1000)  # PWM Limit, Current Limit
    b.w(11, PROFILE_ACCEL, 4, 30), b.w(11, PROFILE_VELOCITY, 4, 300)
    b.w(11, GOAL_PWM, 2, 100), b.w(11, GOAL_CURRENT, 2, 50)
    assert b.w(11, MODE, 1, 4) == (OK, 0)
    assert [b.r(11, a, 4) for a in (PROFILE_ACCEL, PROFILE_VELOCITY)] == [0, 0]
    assert (b.r(11, GOAL_PWM, 2), b.r(11, GOAL_CURRENT, 2)) == (800, 1000)
    b.w(11, PROFILE_VELOCITY, 4, 300)
    assert b.w(11, MODE, 1, 4) == (OK, 0) and b.r(11, PROFILE_VELOCITY, 4) == 300  # no change


def test_present_position_folds_into_one_turn(b: Bench) -> None:
    """ "Present Position (132)", NOTE: a continuous count, reset within one turn when the
    mode changes to Position Control Mode, when torque turns on in it, and at REBOOT
    (Homing Offset still added)."""
    b.w(11, MODE, 1, 4), b.w(11, TORQUE, 1, 1), b.w(11, GOAL, 4, 2 * 4096 + 100)
    b.world.advance(30.0)
    b.w(11, TORQUE, 1, 0)
    assert b.r(11, PRESENT, 4) == 2 * 4096 + 100  # torque off: still the count
    assert b.w(11, MODE, 1, 3) == (OK, 0)
    assert b.r(11, PRESENT, 4) == 100
    b.w(11, MODE, 1, 4), b.w(11, TORQUE, 1, 1), b.w(11, GOAL, 4, -4096 + 5)
    b.world.advance(30.0)
    assert b.ph.reboot(b.port, 11) == (OK, 0)
    assert b.r(11, PRESENT, 4) == 5
    b.w(11, HOMING, 4, 1000)
    assert b.r(11, PRESENT, 4) == 1005  # extended mode: the offset applies


def test_homing_offset_beyond_1024_is_ignored_in_position_mode(b: Bench) -> None:
    """ "Homing Offset (20)", NOTE: in Position Control Mode an invalid Homing Offset is
    ignored (valid range -1,024 ~ 1,024); in the extended mode it applies."""
    assert b.w(11, HOMING, 4, 1024) == (OK, 0)
    assert b.r(11, PRESENT, 4) == 2048 + 1024
    assert b.w(11, HOMING, 4, 2000) == (OK, 0)  # taken, kept...
    assert b.r(11, HOMING, 4) == 2000 and b.r(11, PRESENT, 4) == 2048  # ...not applied
    b.w(11, MODE, 1, 4)
    assert b.r(11, PRESENT, 4) == 2048 + 2000


def test_bus_watchdog_stops_the_servo_and_locks_the_goals(b: Bench) -> None:
    """ "Bus Watchdog (98)" example: velocity mode, Goal Velocity 50, Bus Watchdog 100
    (2,000 ms); no packet for 2 s stops the servo and sets -1; a goal then answers Data
    Range Error; writing 0 clears it and the goal is taken again."""
    b.w(11, MODE, 1, 1), b.w(11, TORQUE, 1, 1), b.w(11, GOAL_VELOCITY, 4, 50)
    assert b.w(11, WATCHDOG, 1, 100) == (OK, 0)
    b.world.advance(1.9)
    assert b.r(11, WATCHDOG, 1) == 100 and b.r(11, PRESENT_VELOCITY, 4) == 50  # a packet: alive
    b.world.advance(2.1)  # silence for 2.1 s
    assert b.r(11, WATCHDOG, 1) == 255  # -1: tripped
    assert b.r(11, PRESENT_VELOCITY, 4) == 0
    stopped = b.r(11, PRESENT, 4)
    b.world.advance(1.0)
    assert b.r(11, PRESENT, 4) == stopped
    assert b.w(11, GOAL_VELOCITY, 4, 150) == (OK, 4)
    assert b.w(11, WATCHDOG, 1, 0) == (OK, 0)
    assert b.w(11, GOAL_VELOCITY, 4, 150) == (OK, 0)
    b.world.advance(0.5)
    assert b.r(11, PRESENT_VELOCITY, 4) == 150


def test_bus_watchdog_is_quiet_while_torque_is_off(b: Bench) -> None:
    """ "Bus Watchdog (98)": it monitors the communication when Torque Enable is 1."""
    b.w(11, WATCHDOG, 1, 1)
    b.world.advance(1.0)
    assert b.r(11, WATCHDOG, 1) == 1


@pytest.mark.parametrize(("firmware", "moves"), [(46, True), (44, False)])
def test_torque_on_by_goal_update(firmware: int, moves: bool) -> None:
    """ "Drive Mode (10)" bit 3, Torque On by Goal Update (from firmware 45): a goal
    written with torque off turns torque on and is carried out; without the bit (or on
    older firmware) the goal is only stored."""
    b = Bench(firmware=firmware)
    assert b.w(11, DRIVE, 1, 0x08) == (OK, 0)
    assert b.w(11, GOAL, 4, 3000) == (OK, 0)
    b.world.advance(5.0)
    assert b.r(11, TORQUE, 1) == int(moves)
    assert b.r(11, PRESENT, 4) == (3000 if moves else 2048)
    assert b.w(12, GOAL, 4, 3000) == (OK, 0)  # bit 3 clear
    b.world.advance(5.0)
    assert b.r(12, TORQUE, 1) == 0 and b.r(12, PRESENT, 4) == 2048


def test_startup_configuration_torque_on_after_reboot(b: Bench) -> None:
    """ "Startup Configuration (60)" bit 0: after power on (REBOOT) torque is on."""
    assert b.w(11, 60, 1, 1) == (OK, 0)
    b.ph.reboot(b.port, 11)
    assert b.r(11, TORQUE, 1) == 1
    b.ph.reboot(b.port, 12)
    assert b.r(12, TORQUE, 1) == 0
