"""The clause passes of round 32 over the reading: a purpose with its place, said after going off
(leisure_places.py), an errand with a thing carried from one place to another (carried_errands.py) and surprise at seeing the robot somewhere, said after a comma (surprised_at.py)."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language.carried_errands import carried_errands
from grove_tui.language.leisure_places import leisure_places
from grove_tui.language.model import PromptReading
from grove_tui.language.places import PlaceIndex
from grove_tui.language.surprised_at import occasions, surprised_at


def round32_clauses(prompt: str, index: PlaceIndex, reading: PromptReading) -> PromptReading:
    """The reading with round 32's clause readings applied."""
    groups = surprised_at(prompt, carried_errands(index, leisure_places(index, reading.groups)))
    events = occasions(prompt)
    unknown = tuple(u for u in reading.unknown_places if not set(u.lower().split()[-1:]) & events)
    return replace(reading, groups=groups, unknown_places=unknown)
