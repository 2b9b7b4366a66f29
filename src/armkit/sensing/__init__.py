"""Sensing: a Sharp GP2D120 infrared distance sensor on the hand (seed 002), its
datasheet curve, its narrow beam against a scene, a simulated one installed as a
simulated arm's analog input, and the reading side: the SSC-32's ``VA``..``VD`` or a
serial ADC board that prints its readings (with an emulator on a pty)."""

from ._adc import AdcBoard as AdcBoard
from ._adc import AdcEmulator as AdcEmulator
from ._beam import SensorMount as SensorMount
from ._gp2d120 import RANGE as RANGE
from ._gp2d120 import distance as distance
from ._gp2d120 import volts as volts
from ._sensor import DistanceSensor as DistanceSensor
from ._sensor import open_sensor as open_sensor
from ._simulated import SimulatedSensor as SimulatedSensor
from ._simulated import install_sensor as install_sensor
