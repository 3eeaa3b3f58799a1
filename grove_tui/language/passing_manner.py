"""How the robot's clause passes the people it passes: through them, or past them.

"Eight patients queue at the pharmacy while the robot drives past them to the cafeteria": the reading's
RobotReading.passes names the people its clause goes by (language/robot_crowds.py) with the same word for
"through the queue" and "past them", and planning sent the robot through the queue's gap in both cases; the
report then claimed "passes through the patients" ✓ and "passes beside the people at pharmacy" ✗ for one
passing. This reads which it is from the robot's own words: through (through, among, amid, between, into,
threads, weaves, cuts, pushes) or beside (past, by, beside, alongside, around): `passes_through`.

    passes_through(robot)  # True: through them; False: past / beside them (the default for a bare "passes")
"""

from __future__ import annotations

import re

from grove_tui.language.model import RobotReading

_THROUGH = re.compile(r"\b(?:through|thru|among|amongst|amid|amidst|between|into|threads?|threading|weaves?|weaving"
                      r"|cuts?\s+across|pushes|squeezes\s+through)\b", re.IGNORECASE)


def passes_through(robot: RobotReading | None) -> bool:
    """Whether the robot's clause goes through the people it passes (else it passes beside them)."""
    if robot is None:
        return False
    return _THROUGH.search(robot.text or "") is not None
