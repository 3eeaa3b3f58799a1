"""Round 44 (r44b): members said as included in an aside ("a family of seven, grandparents included,
...", "a party of ten, kids and all, ...", "twelve hikers ..., guide included."): who is among the group,
not a second group beside it (language/included_members.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count,destination", [
    ("museum", "A school party of thirty, teachers included, troops from the cloakroom to the cafe.", 30, "cafe"),
    ("airport", "A party of ten, kids and all, walks from check-in to gate A2.", 10, "gate_a2"),
    ("mall", "Twelve ramblers stroll to the food court, guide included.", 12, "food_court"),
    ("hospital", "A family of six, the grandparents included, walks from the lobby to the pharmacy.", 6, "pharmacy"),
])
def test_members_said_as_included_are_no_group_of_their_own(read, world, prompt, count, destination):
    (group,) = read(world, prompt).groups
    assert group.count.value == count and group.destination == destination


def test_a_clause_about_what_is_included_is_left_alone(read):
    reading = read("hotel", "Two guests walk to the spa, breakfast is included, and a porter waits in the lobby.")
    assert len(reading.groups) == 2
