"""A zone people are named by ("the poker room's dealer", "a bookie's clerk") is where they start only
when no place is said after "from": the whole name said after "from" is where they set off. With no
"from", the possessor's zone is still where they are. Real spaCy, understanding worlds, no model."""

from __future__ import annotations

from functools import cache

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world.loader import load_world
from grove_tui.world.model import World


@cache
def _world(name: str) -> World:
    return load_world(f"eval/understanding/worlds/{name}.yaml")


CASES = [
    ("casino", "The poker room's dealer walks from the sports bar back to the cashier cage.", "sports_bar",
     "cashier_cage"),
    ("hospice", "The laundry's porter walks from the chapel to the kitchen.", "chapel", "kitchen"),
    ("racecourse", "A bookie's clerk walks from the champagne bar back to the betting ring.", "champagne_bar",
     "betting_hall"),
    ("casino", "The poker room's dealer walks to the cashier cage.", "poker_room", "cashier_cage"),
]


@pytest.mark.parametrize(("world", "sentence", "start", "destination"), CASES)
def test_said_from_beats_the_possessor(world: str, sentence: str, start: str, destination: str) -> None:
    reading = read_prompt(sentence, _world(world))
    assert len(reading.groups) == 1, reading.groups
    group = reading.groups[0]
    assert (group.start, group.destination) == (start, destination)
