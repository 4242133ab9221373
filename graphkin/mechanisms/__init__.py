"""The mechanism file: parse, validate, and the plain model it describes."""

from graphkin.mechanisms.model import (
    FRAME,
    Drive,
    Link,
    Mechanism,
    Pin,
    Rates,
    Rolling,
    Slider,
    Slot,
)
from graphkin.mechanisms.parse import from_dict, load, loads

__all__ = ["FRAME", "Drive", "Link", "Mechanism", "Pin", "Rates", "Rolling", "Slider", "Slot",
           "load", "loads", "from_dict"]
