"""The clause passes of round 30 over the groups read, in order: a zone cleared in the passive
(cleared_passive.py), steering wide of or hanging back from the robot (steered_clear.py), a feeling set
apart from its clause (feeling_adjectives.py); crowding round a thing after\nmoving (crowding_round.py)."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.cleared_passive import cleared_away
from grove_tui.language.crowding_round import crowding_round
from grove_tui.language.feeling_adjectives import coloured_by_feeling
from grove_tui.language.model import GroupReading
from grove_tui.language.places import PlaceIndex
from grove_tui.language.steered_clear import steering_clear_of_the_robot


def round30_clauses(prompt: str, index: PlaceIndex, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """The groups with round 30's clause readings applied."""
    return coloured_by_feeling(prompt, steering_clear_of_the_robot(cleared_away(crowding_round(index, groups))))
