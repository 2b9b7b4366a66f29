"""One simulated XM430-W350: its control-table memory and its motor.

The control table is data (``armkit.devices._xm430``: address, size, sign, access,
factory default and the Range column as one rule per register), and so are the
e-Manual's NOTEs (``devices._xm430_notes``); a WRITE is checked as the firmware
does (``_xm430_checks``: access 7, length 5, range 4, limit 6) and nothing is
written unless all of it may be. The motor (``_xm430_motor``) follows the mode's
goal: a position profile in position modes, a spin in velocity and PWM modes.

Present Position = the shaft's position + the turns folded away + Homing Offset
(ignored in Position Control Mode beyond +-1,024). On an arm (``feedback`` set)
the shaft is the arm's; alone (``armkit emulate``) it follows the motion exactly.
Not modelled: Current Control Mode moves nothing (no load), Drive Mode bit 0
(reverse) is stored but does not turn the arm the other way, Protocol Type 1 makes
the servo deaf to Protocol 2.0 (Protocol 1.0 is not emulated), Shutdown conditions
other than an injected overload.
"""

from __future__ import annotations

from collections.abc import Callable

from ..devices import dxl_packet as pkt
from ..devices import xm430 as xm
from ..devices import xm430_notes as notes
from ._xm430_checks import Written, check_write
from ._xm430_drive import Drive
from ._xm430_memory import read_through, runs
from ._xm430_motor import Motor
from ._xm430_profile import Motion, Profile, velocity_profile_times

__all__ = ["XM430", "Profile", "velocity_profile_times"]

_TORQUE_ENABLE = xm.register("Torque Enable").address
# name -> (first byte, past the last, signed): the table looked up once, not per access
_SLOTS = {r.name: (r.address, r.address + r.size, r.signed) for r in xm.XM430_W350.values()}
_REGISTERS = sorted(xm.XM430_W350.values(), key=lambda r: r.address)
_RAM = [r for r in _REGISTERS if not r.eeprom and r.writable and not r.name.startswith("Indirect")]
_KEPT_BY_BACKUP = [
    r
    for r in _REGISTERS
    if r.writable and (r.eeprom or r.name in notes.BACKUP_RAM or r.name.startswith("Indirect A"))
]


class XM430:
    """One simulated XM430-W350 (see module doc).

    Args:
        servo_id: its ID.  clock: its time [s].  position: where its shaft starts [tick].
        baudrate: the rate it listens at [bit/s].  firmware: the Firmware Version it
            reports (the features it has, ``notes.FROM_FIRMWARE``).
    """

    def __init__(
        self,
        servo_id: int,
        clock: Callable[[], float],
        position: int = 2048,
        baudrate: int = 57_600,
        firmware: int = xm.FIRMWARE_VERSION,
    ) -> None:
        self.memory = bytearray(xm.CONTROL_TABLE_SIZE)
        self.clock = clock
        self.feedback: Callable[[], tuple[float, float]] | None = None  # the arm's (tick, tick/s)
        self.motor = Motor(self, float(position), clock())
        self.registered: tuple[int, bytes] | None = None  # REG_WRITE waiting for ACTION
        self.backup: bytes | None = None  # Control Table Backup's store
        self.factory_reset(notes.RESET_ALL)
        self.memory[6] = firmware
        self.set("ID", servo_id)
        self.set("Baud Rate", xm.baud_value(baudrate))
        self.set("Goal Position", position)
        self.effects: dict[str, Callable[[int, int], None]] = {
            "Operating Mode": self._mode,
            "Torque Enable": self._torque_enable,
            "Bus Watchdog": lambda old, new: self.motor.heard(self.clock()),
            "Goal Position": lambda old, new: self.motor.goal_position(new),
            "Goal Velocity": lambda old, new: self.motor.goal_spin(),
            "Goal PWM": lambda old, new: self.motor.goal_spin(),
        }

    # -- registers -------------------------------------------------------------
    def get(self, name: str) -> int:
        """Register value, refreshed from the motor first."""
        reg = xm.register(name)
        return reg.decode(self.read(reg.address, reg.size))

    def set(self, name: str, value: int) -> None:
        """Poke a register directly (no checks, no side effects)."""
        reg = xm.register(name)
        self.memory[reg.address : reg.address + reg.size] = reg.encode(value)

    def value(self, name: str) -> int:
        """Register value as stored (no refresh); InputError for an unknown name."""
        slot = _SLOTS.get(name)
        if slot is None:  # not in the table: xm.register raises, naming those that are
            reg = xm.register(name)
            return reg.decode(self.memory[reg.address : reg.address + reg.size])
        start, stop, signed = slot
        if stop - start == 1 and not signed:  # a byte register: the byte itself
            return self.memory[start]
        return int.from_bytes(self.memory[start:stop], "little", signed=signed)

    def has(self, feature: str) -> bool:
        """True when its firmware has ``feature`` (a key of ``notes.FROM_FIRMWARE``)."""
        return self.memory[6] >= notes.FROM_FIRMWARE[feature]

    @property
    def baudrate(self) -> int:
        """The rate it listens at [bit/s], from its Baud Rate register."""
        return xm.BAUD_RATES.get(self.value("Baud Rate"), 0)

    @property
    def plans(self) -> int:
        """How many position moves were started (a re-sent goal adds none)."""
        return self.motor.plans

    @property
    def motion(self) -> Motion:
        """The motor's present motion (``Profile`` or ``Spin``, in shaft ticks)."""
        return self.motor.motion

    def hear(self, now: float) -> None:
        """An instruction packet for it at ``now`` [s]: the Bus Watchdog starts again
        (after tripping if it had already expired)."""
        self.motor.watch(now)
        self.motor.heard(now)

    # -- reading -------------------------------------------------------------------
    def read(self, address: int, size: int) -> bytes:
        """``size`` bytes from ``address`` after updating the present-state registers;
        Indirect Data bytes read the byte their Indirect Address names."""
        self.motor.refresh(self.clock())
        return read_through(self.memory, address, size)

    def drive(self) -> Drive:
        """What the motor is driven to until the next packet (``_xm430_drive``)."""
        return self.motor.drive()

    def setpoint(self, now: float) -> float | None:
        """Where the motor is driven to at ``now`` [tick, shaft]; None: torque off."""
        return self.motor.drive().setpoint(now)

    def busy(self, now: float) -> bool:
        """True while the motor's motion is running."""
        return self.motor.drive().busy(now)

    def hold_at(self, tick: int) -> None:
        """Put the shaft at ``tick`` (its frame unshifted), at rest, goal there (assembly)."""
        self.motor.place(float(tick), self.clock())
        self.set("Goal Position", tick)
        self.set("Present Position", tick)

    # -- writing -------------------------------------------------------------------
    def write(self, address: int, data: bytes, *, secondary: bool = False) -> int:
        """WRITE as the firmware does it (``secondary``: sent to the Secondary ID); returns
        the status error number (0 = ok). Nothing is written unless all of it may be."""
        now = self.clock()
        self.motor.watch(now)
        locked = bool(self.memory[_TORQUE_ENABLE]) or secondary
        tripped = self.value("Bus Watchdog") == notes.WATCHDOG_TRIPPED
        pieces = runs(self.memory, address, data)
        error, written = check_write(
            self.memory, pieces, eeprom_locked=locked, watchdog_tripped=tripped
        )
        if not error:
            self._apply(written)
        return error

    def _apply(self, written: Written) -> None:
        """Store every written value, then run the effects in table order (the mode before
        the torque before the goals), each with the register's value before the write.
        Drive Mode bit 3 (Torque On by Goal Update): the mode's goal, written with torque
        off, turns torque on first."""
        if self._torque_by_goal(written):
            self.motor.torque(True)
        memory = self.memory
        before = {reg: reg.decode(memory[reg.address : reg.address + reg.size]) for reg in written}
        for reg, value in written.items():
            memory[reg.address : reg.address + reg.size] = reg.encode(value)
        for reg in sorted(written, key=lambda r: r.address):
            effect = self.effects.get(reg.name)
            if effect is not None:
                effect(before[reg], written[reg])

    def _torque_enable(self, old: int, new: int) -> None:
        if old != new:
            self.motor.torque(bool(new))

    def _torque_by_goal(self, written: Written) -> bool:
        if self.value("Torque Enable") or not self.has("Torque On by Goal Update"):
            return False
        if not self.value("Drive Mode") & xm.DRIVE_MODE_TORQUE_ON_BY_GOAL:
            return False
        goal = notes.MODE_GOAL.get(self.value("Operating Mode"))
        return any(reg.name == goal for reg in written)

    def _mode(self, old: int, new: int) -> None:
        """Operating Mode NOTE: the resets (``notes.MODE_CHANGE_RESETS``); entering
        Position Control Mode folds Present Position into one turn."""
        if old == new:
            return
        for name, value in notes.MODE_CHANGE_RESETS.items():
            reg = xm.register(name)
            if value is None:
                self.set(name, reg.default)
            else:
                self.set(name, self.value(value) if isinstance(value, str) else value)
        self.motor.mode_changed(new)

    # -- instructions other than READ/WRITE ---------------------------------------
    def overload(self) -> None:
        """Trip the overload error: torque off, the alert bit on until REBOOT."""
        self.set("Torque Enable", 0)
        self.motor.torque(False)
        self.set("Hardware Error Status", 0x20)

    def reboot(self) -> None:
        """REBOOT: as at power on: the RAM area back to its defaults (or the backup,
        Startup Configuration bit 1), Present Position within one turn, torque off (on
        with Startup Configuration bit 0), the hardware error cleared."""
        for reg in _RAM:
            self.set(reg.name, reg.default)
        self.set("Hardware Error Status", 0)
        self.registered = None
        startup = self.value("Startup Configuration") if self.has("Startup Configuration") else 0
        if startup & notes.STARTUP_RAM_RESTORE and self.backup is not None:
            self._restore(ram=True)
        self.motor.power_on(self.clock())
        if startup & notes.STARTUP_TORQUE_ON:
            self.set("Torque Enable", 1)
            self.motor.torque(True)

    def factory_reset(self, option: int) -> None:
        """FACTORY_RESET: every register to its factory value, but those ``option`` keeps
        (``notes.FACTORY_RESET_KEEPS``); the shaft stays where it is."""
        kept = {name: self.value(name) for name in notes.FACTORY_RESET_KEEPS.get(option, ())}
        firmware = self.memory[6]
        for reg in _REGISTERS:
            self.memory[reg.address : reg.address + reg.size] = reg.encode(reg.default)
        self.memory[6] = firmware or xm.FIRMWARE_VERSION
        for name, value in kept.items():
            self.set(name, value)
        self.registered = None
        self.motor.power_on(self.clock())

    def clear_multi_turn(self) -> int:
        """CLEAR (option 1): Present Position back into one turn, the shaft unmoved;
        Result Fail while the servo moves. Returns the error number."""
        now = self.clock()
        if self.busy(now):
            return pkt.RESULT_FAIL
        self.motor.fold(now)
        return 0

    def backup_table(self, option: int) -> int:
        """Control Table Backup: store (1) or restore the EEPROM area and reboot (2);
        Result Fail with torque on, Data Range Error for another option."""
        if self.value("Torque Enable"):
            return pkt.RESULT_FAIL
        if option == notes.BACKUP_STORE:
            self.backup = bytes(self.memory)
            self.set("Backup Ready", 1)
            return 0
        if option != notes.BACKUP_RESTORE or self.backup is None:
            return pkt.DATA_RANGE_ERROR if option != notes.BACKUP_RESTORE else pkt.RESULT_FAIL
        self._restore(ram=False)
        return 0

    def _restore(self, *, ram: bool) -> None:
        """Copy the backup's EEPROM area (``ram``: its kept RAM registers) back."""
        assert self.backup is not None
        for reg in _KEPT_BY_BACKUP:
            if reg.eeprom != ram:
                span = slice(reg.address, reg.address + reg.size)
                self.memory[span] = self.backup[span]

    @property
    def error_bits(self) -> int:
        """The alert bit for every status while a hardware error is latched."""
        return pkt.ALERT_BIT if self.value("Hardware Error Status") else 0
