"""The robot taking people out with no place said: "the robot guides the visitors in the cafeteria out",
"leads everyone outside", "takes the children out". It goes to the building's exit nearest where it
takes them from (the place its clause names, else where it was); they follow it (language/reactions.py)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

from grove_tui.language.leading_out import leads_out

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence


def out_exit(s: Sentence, first: int, near: Sequence[str | None]) -> str | None:
    """The exit the robot's clause from `first` takes people out to, when it leads them out: the one
    nearest the first place of `near` the world has (any exit when none)."""
    if not leads_out(s, first):
        return None
    exits = s.index.exits()
    if not exits:
        return None
    world = s.index.world
    centre = None
    for name in near:
        entry = s.index.entry(name) if name else None
        if entry is not None:
            centre = world.zone(entry.zone).centroid
            break
    if centre is None:
        return min(exits, key=lambda e: ("main" not in e, "entrance" not in e, e))  # the main entrance first
    cx, cy = centre[0], centre[1]

    def distance(name: str) -> float:
        x, y = getattr(world.find(name), "position", (cx, cy))
        return math.hypot(x - cx, y - cy)

    return min(exits, key=lambda e: (distance(e), e))
