"""Round 44 (r44b): a thing that fails, said as a clause's subject ("the power fails", "the water cuts
out", "the router crashes"): its "-er" ending made it an agent's noun, a person, and a group of one.
A noun in no list of people, the subject of a verb of failing, is a thing (language/failing_things.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count", [
    ("mall", "The power cuts out and everyone in the food court leaves by the north exit.", None),
    ("office", "The router crashes and three developers wander over to the kitchen.", 3),
    ("hospital", "The water fails on ward B, so two nurses walk to the pharmacy.", 2),
    ("hotel", "The power goes off and four guests wait in the lobby.", 4),
])
def test_a_thing_that_fails_is_no_person(read, world, prompt, count):
    (group,) = read(world, prompt).groups
    assert count is None or group.count.value == count
    assert "power" not in group.who and "water" not in group.who and "router" not in group.who


def test_a_person_who_fails_to_come_is_still_a_person(read):
    reading = read("office", "The plumber fails to turn up, so a caretaker waits at reception.")
    assert any(g.who == "a caretaker" for g in reading.groups)
