"""The clause passes of round 31 over the reading: a purpose that names where people go
(purposed_places.py), going to where a problem is (problem_places.py) and a place the world lacks,
searched for by its kind (searched_unknown.py), and a place said by what is done there read as the room,
not a thing in it (activity_place_zones.py). Going away from the robot by any verb is read with the
robot's interactions (robot_shrinking.py)."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language.activity_place_zones import activity_place_zones
from grove_tui.language.model import PromptReading
from grove_tui.language.places import PlaceIndex
from grove_tui.language.problem_places import problem_places
from grove_tui.language.purposed_places import purposed_places
from grove_tui.language.searched_unknown import searched_unknown


def round31_clauses(prompt: str, index: PlaceIndex, reading: PromptReading) -> PromptReading:
    """The reading with round 31's clause readings applied."""
    groups = activity_place_zones(index, problem_places(prompt, index, purposed_places(index, reading.groups)))
    unknown = tuple(dict.fromkeys((*reading.unknown_places, *searched_unknown(prompt, index))))
    return replace(reading, groups=groups, unknown_places=unknown)
