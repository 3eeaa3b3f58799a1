"""A second verbless chat item of one person after an "-ing" item ("... and a cleaner dawdling by the
freezers"): the person is a group of their own at their place, and the first item keeps its verb
(a queue stays a queue). Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, first, second", [
    ("supermarket", "five shoppers queuing at tills and a cleaner dawdling by the freezers",
     (5, "queue", "checkouts"), (1, "frozen_foods")),
    ("mall", "3 teens lounging at the food court and a cleaner loitering near the fountain",
     (3, "wait", "food_court"), (1, "fountain")),
])
def test_the_joined_person_is_read_and_the_first_item_keeps_its_verb(read, world, prompt, first, second):
    groups = read(world, prompt).groups
    assert len(groups) == 2
    a, b = groups
    assert (a.count.value, a.intent, a.location) == first
    assert (b.count.value, b.location) == second
