"""Someone who stands at an exit without leaving stands beside its opening, not in it.

"Two security guards wait by the main entrance": their point was 0.6 m inside the door's centre, in
the opening itself, where anyone walking out (and the robot following one of them) pushed them over
the door line, and they stood in the way of everyone leaving. A person sent to an exit door by any
node but the one that walks them out stands just inside, beside the opening (past its jamb), on the
first side with free floor; the claim about being there covers both sides of the opening.
"""

from __future__ import annotations

from collections.abc import Callable

from grove_tui.errors import GenerationError
from grove_tui.world.model import Door

BESIDE = 0.6  # metres past the jamb
INSIDE = 0.9  # metres in from the door line
CLAIM_POINT = 0.6  # the claim's point (the door's inward point, as for any door)


def _point(door: Door, side: float) -> tuple[float, float]:
    along = side * (door.width / 2.0 + BESIDE)
    return (door.position[0] + along * door.along[0] + INSIDE * door.normal[0],
            door.position[1] + along * door.along[1] + INSIDE * door.normal[1])


def off_the_opening(door: Door, snap: Callable[[tuple[float, float]], tuple[float, float]]) -> tuple[float, float]:
    """Where a person sent to an exit door (not to leave through it) stands: beside its opening, just inside."""
    for side in (1.0, -1.0):
        p = _point(door, side)
        try:
            q = snap(p)
        except GenerationError:
            continue
        if abs(q[0] - p[0]) + abs(q[1] - p[1]) < 0.3:
            return q
    return snap(door.inward_point(INSIDE + 0.6))


def claim_radius(door: Door, radius: float) -> float:
    """A claim about being at an exit door reaches past its jambs, where people wait beside the opening."""
    return radius + door.width / 2.0 + BESIDE if door.exit else radius
