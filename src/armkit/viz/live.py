"""The live channel's face for the factory: ``armkit.connect`` attaches a
``LivePublisher`` to every kept simulated arm with ``publish_live`` (the rest of the
channel, ``LiveSource`` and ``publisher_of``, is on ``armkit.viz``)."""

from ._live import publish_live as publish_live
