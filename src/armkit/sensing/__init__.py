"""Sensing: a Sharp GP2D120 infrared distance sensor on the hand (seed 002), its
datasheet curve, its narrow beam against a scene, and the reading side: the SSC-32's
``VA``..``VD`` or a serial ADC board that prints its readings (with an emulator on a
pty). The simulated sensor lives in the simulator (``SimArm.install_sensor``); sensing
imports no ``sim``."""

from ._adc import AdcBoard as AdcBoard
from ._adc import AdcEmulator as AdcEmulator
from ._beam import SensorMount as SensorMount
from ._beam import nearest as nearest
from ._gp2d120 import NOISE_V as NOISE_V
from ._gp2d120 import RANGE as RANGE
from ._gp2d120 import distance as distance
from ._gp2d120 import volts as volts
from ._sensor import DistanceSensor as DistanceSensor
from ._sensor import open_sensor as open_sensor
