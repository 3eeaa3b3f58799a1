"""Round 44 (r44b): a body's name with a possessive inside before the person noun ("a busload of Women's
Institute ladies", "two St John's Ambulance volunteers"): the possessive is the name's, and the person
noun after the name heads the phrase; the vehicle's load is those people, one group, not the load and a
second vague few (language/of_names.py, people.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,low,high,destination", [
    ("mall", "A coachload of Women's Institute members files from the north entrance to the food court.", 30, 50,
     "food_court"),
    ("zoo", "A busload of Young Farmers' Club lads wanders over to the penguin pool.", 30, 50, None),
    ("hospital", "Two St John's Ambulance volunteers walk from the lobby to the pharmacy.", 2, 2, "pharmacy"),
])
def test_a_name_with_a_possessive_before_people_is_their_kind(read, world, prompt, low, high, destination):
    (group,) = read(world, prompt).groups
    assert low <= group.count.value <= high
    assert destination is None or group.destination == destination


def test_an_owner_said_with_a_possessive_keeps_its_reading(read):
    (group,) = read("museum", "Mrs Cole's daughter walks to the cafe.").groups
    assert group.count.value == 1 and group.destination == "cafe"
