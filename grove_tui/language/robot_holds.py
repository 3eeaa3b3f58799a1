"""Reactions to the robot said by idioms of holding ground or holding on (round 27).

- Holding one's ground where the robot would go ("stands his ground as the robot tries to get by",
  "holds her ground in the doorway", "refuses to budge an inch", "plants his feet") is blocking it.
- Keeping hold of the robot ("keeps a hand on the robot as it guides her", "holds on to the robot",
  "clings to its arm", "takes the robot's arm") is being led by it: following.

Read as the idioms of robot_idioms.py are: only in a clause that names the robot or that the robot's
clause times ("... as the robot tries to get by").
"""

from __future__ import annotations

HOLDING_IDIOMS: dict[tuple[str, ...], str] = {
    ("stand", "*", "ground"): "block", ("hold", "*", "ground"): "block", ("stand", "firm"): "block",
    ("stand", "fast"): "block", ("plant", "*", "feet"): "block", ("dig", "*", "heels", "in"): "block",
    ("dig", "in", "*", "heels"): "block",
    ("keep", "*", "hand", "on"): "follow", ("keep", "*", "hands", "on"): "follow", ("rest", "*", "hand", "on"): "follow",
    ("keep", "hold", "of"): "follow", ("keep", "a", "hold", "of"): "follow", ("hold", "on", "to"): "follow",
    ("hold", "onto"): "follow", ("hang", "on", "to"): "follow", ("hang", "onto"): "follow", ("cling", "to"): "follow",
    ("cling", "on", "to"): "follow", ("clutch", "on", "to"): "follow", ("keep", "a", "grip", "on"): "follow",
    ("keep", "*", "grip", "on"): "follow", ("take", "*", "arm"): "follow",
}
