"""How near and how long, for the claims a scenario makes about people and the robot: the one place the
generation stages that plan a reaction (so it happens within reach) and the outcome checks that measure
it (analysis/outcomes.py) read the same figures. Here, in the scenario contract below both, so neither
imports the other."""

from __future__ import annotations

LOOK_RANGE = 10.0  # metres: the robot is in sight for "look" within this
LOOK_SHARE = 0.6  # "stare at", "watch": facing it for most of the time it is within LOOK_RANGE
PASS_AT = 4.0  # metres: a robot within this of a place's point is passing it ("as the robot passes the desk")
PASS_BY = 5.0  # metres: a robot within this of someone is passing them ("as it goes by")
GLANCE_SECONDS = 1.0  # "glance at", "look at": facing it at least once this long while within LOOK_RANGE
