"""The NOTEs of the XM430-W350's e-Manual as data: what a write, a mode or an instruction
does besides storing a value. The simulated servo (``armkit.sim.xm430``) applies them;
each entry names its section of the ROBOTIS e-Manual ("XM430-W350" or "DYNAMIXEL
Protocol 2.0").
"""

from __future__ import annotations

from collections.abc import Mapping

from ._xm430 import (
    MODE_CURRENT,
    MODE_CURRENT_POSITION,
    MODE_EXTENDED_POSITION,
    MODE_POSITION,
    MODE_PWM,
    MODE_VELOCITY,
)

# "Operating Mode (11)", NOTE: switching the mode resets the profile (Profile Velocity,
# Profile Acceleration to 0), Goal PWM and Goal Current to PWM Limit and Current Limit,
# and the gains to the mode's own (here: the table's defaults). A str value names the
# register whose value is taken; None: the register's factory default.
MODE_CHANGE_RESETS: Mapping[str, int | str | None] = {
    "Profile Velocity": 0,
    "Profile Acceleration": 0,
    "Goal PWM": "PWM Limit",
    "Goal Current": "Current Limit",
    "Velocity I Gain": None,
    "Velocity P Gain": None,
    "Position D Gain": None,
    "Position I Gain": None,
    "Position P Gain": None,
    "Feedforward 2nd Gain": None,
    "Feedforward 1st Gain": None,
}

# "Present Position (132)", NOTE: Present Position is a 4-byte continuous count, but it
# is reset to an absolute position within one turn (0 ~ 4,095, plus Homing Offset) when
# the mode changes to Position Control Mode, when torque turns on in that mode, and at
# power on or REBOOT.
ONE_TURN_MODE = MODE_POSITION

# "Homing Offset (20)", NOTE: in Position Control Mode an offset outside -1,024 ~ 1,024
# is ignored (the value is kept but not applied).
POSITION_MODE_HOMING_LIMIT = 1_024

# The goal register each Operating Mode follows ("Operating Mode (11)"); Drive Mode (10)
# bit 3, Torque On by Goal Update: writing it with torque off turns torque on first.
MODE_GOAL: Mapping[int, str] = {
    MODE_CURRENT: "Goal Current",
    MODE_VELOCITY: "Goal Velocity",
    MODE_POSITION: "Goal Position",
    MODE_EXTENDED_POSITION: "Goal Position",
    MODE_CURRENT_POSITION: "Goal Position",
    MODE_PWM: "Goal PWM",
}
POSITION_MODES = (MODE_POSITION, MODE_EXTENDED_POSITION, MODE_CURRENT_POSITION)
SPIN_MODES = (MODE_VELOCITY, MODE_PWM)  # the shaft turns at a commanded velocity

# "Bus Watchdog (98)": 1 ~ 127 arms it (unit 20 ms) while torque is on; no instruction
# packet for that long stops the servo (profile applied as 0) and sets it to -1; then
# the goal registers are read-only (Data Range Error) until 0 is written.
WATCHDOG_UNIT_S = 0.020
WATCHDOG_TRIPPED = -1
WATCHDOG_LOCKS = ("Goal PWM", "Goal Current", "Goal Velocity", "Goal Position")

# "Secondary(Shadow) ID (12)": 253 ~ 255 switch it off; packets for it are executed
# without a status packet, and the EEPROM area cannot be changed through it.
SECONDARY_ID_OFF = 253

# "Goal PWM (100)" in PWM Control Mode drives the motor at that duty; unloaded at the
# recommended 12 V, full duty (885) turns it at the no-load speed, 46 rev/min
# ("Specifications", No Load Speed).
NO_LOAD_RPM = 46.0
FULL_PWM = 885

# "DYNAMIXEL Protocol 2.0", Factory Reset (0x06): option -> registers kept. From
# firmware 42, a broadcast Factory Reset with option 0xFF is not executed.
RESET_ALL, RESET_KEEP_ID, RESET_KEEP_ID_BAUD = 0xFF, 0x01, 0x02
FACTORY_RESET_KEEPS: Mapping[int, tuple[str, ...]] = {
    RESET_ALL: (),
    RESET_KEEP_ID: ("ID",),
    RESET_KEEP_ID_BAUD: ("ID", "Baud Rate"),
}

# "DYNAMIXEL Protocol 2.0", Clear (0x10): option 1 with these fixed bytes folds Present
# Position into one turn (Result Fail while moving).
CLEAR_MULTI_TURN, CLEAR_KEY = 0x01, b"\x44\x58\x4c\x22"

# "DYNAMIXEL Protocol 2.0", Control Table Backup (0x20): option 1 stores, 2 restores
# (then the servo reboots), each followed by these fixed bytes; torque must be off
# (Result Fail). What is kept: the EEPROM area and these RAM registers.
BACKUP_STORE, BACKUP_RESTORE, BACKUP_KEY = 0x01, 0x02, b"\x43\x54\x52\x4c"
BACKUP_RAM = (
    "Velocity I Gain",
    "Velocity P Gain",
    "Position D Gain",
    "Position I Gain",
    "Position P Gain",
    "Feedforward 2nd Gain",
    "Feedforward 1st Gain",
    "Profile Acceleration",
    "Profile Velocity",
)  # fmt: skip  (and every Indirect Address)

# "Startup Configuration (60)": bit 0 torque on at power on / REBOOT; bit 1 the RAM area
# restored from the backup (when Backup Ready (147) is 1).
STARTUP_TORQUE_ON, STARTUP_RAM_RESTORE = 0x01, 0x02

# From which firmware version each feature exists (the e-Manual's notes); a servo
# reporting an older Firmware Version (6) does not have it.
FROM_FIRMWARE: Mapping[str, int] = {
    "Drive Mode": 38,
    "Bus Watchdog": 38,
    "time-based profile": 42,
    "Clear": 42,
    "broadcast Factory Reset 0xFF ignored": 42,
    "Torque On by Goal Update": 45,
    "Startup Configuration": 45,
    "Control Table Backup": 45,
    "Fast Sync Read": 45,
    "Fast Bulk Read": 45,
}
