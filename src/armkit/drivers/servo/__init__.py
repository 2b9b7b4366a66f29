"""Hobby-servo arms (Lynx6, AL5D) on an SSC-32 or a Pololu Maestro, through pulse tables.

``open_ssc32(model, port)`` / ``open_maestro(model, port)`` return a driver that
turns joint angles into pulses through each servo's ``ServoCalibration`` table;
``calibrate_servos`` measures a unit's tables. pyserial is imported only when a
port is opened.
"""

from ._arm import ServoArmDriver as ServoArmDriver
from ._bus import ServoBus as ServoBus
from ._calibrate import calibrate_servos as calibrate_servos
from ._config import load_setup as load_setup
from ._forecast import JAWS_SPEED as JAWS_SPEED
from ._forecast import ServoForecaster as ServoForecaster
from ._forecast import servo_forecaster as servo_forecaster
from ._open import maestro_pulses as maestro_pulses
from ._open import open_maestro as open_maestro
from ._open import open_ssc32 as open_ssc32
from ._open import ssc32_pulses as ssc32_pulses
from ._table import ServoCalibration as ServoCalibration
