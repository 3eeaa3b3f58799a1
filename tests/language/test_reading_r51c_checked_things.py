"""A thing of the world people check, inspect or examine is where they are ("as a croupier inspects the
craps table, ...", "a guard examines the cash machine"), in a "while" clause or not; the robot checked is
still the robot's approach, no place. Real spaCy, understanding worlds, no model."""

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
    ("casino", "While a croupier inspects the craps table, two guests queue at the cloakroom counter.",
     "croupier", "craps_table"),
    ("casino", "A security guard examines the cash machine.", "guard", "cash_machine"),
    ("dialysis_unit", "While a staff nurse checks the drugs trolley, the robot takes a box of needles from the "
     "clean utility to chair 11.", "nurse", "drugs_trolley"),
]


@pytest.mark.parametrize(("world", "sentence", "label", "location"), CASES)
def test_checked_thing_is_where_they_are(world: str, sentence: str, label: str, location: str) -> None:
    reading = read_prompt(sentence, _world(world))
    group = next(g for g in reading.groups if g.label == label)
    assert group.location == location


def test_checking_the_robot_is_no_place() -> None:
    reading = read_prompt("Two croupiers inspect the robot.", _world("casino"))
    assert reading.groups[0].location is None
    assert reading.groups[0].robot_interaction == "approach"
