"""Devices: bytes on the wire (USB control transfers, SSC-32 text, Maestro and Dynamixel packets).

Each module imports its client library (pyusb, pyserial, dynamixel-sdk) only
when a device is opened, so ``import armkit`` never needs them.
"""
