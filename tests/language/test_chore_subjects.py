"""Round 55 (r55a): a noun no list names (or a trade's word the world gives a unit) that does a chore
to something ("restocks the minibar", "scrubs down the pontoon") is a person, so a list of clauses
keeps each clause's group (language/chore_subjects.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,sizes", [
    ("hotel", "A chambermaid restocks the minibar, two porters stack the luggage trolleys, and a few guests "
     "queue at reception.", 3),
    ("marina", "A deckie scrubs down the pontoon, and three sailors wait by the fuel berth.", 2),
    ("market_hall", "A fishmonger restocks the fish counter.", 1),
])
def test_a_chore_doer_is_a_group(read, world, prompt, sizes):
    groups = read(world, prompt).groups
    assert len(groups) == sizes
    assert groups[0].count.value == 1


def test_a_thing_that_empties_is_no_one(read):
    groups = read("hotel", "The fountain empties slowly while two guests wait at reception.").groups
    assert len(groups) == 1 and groups[0].count.value == 2
