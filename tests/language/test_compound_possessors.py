"""Round 53 (r53a): a person named by their relation to another person whose role is a compound
("the party host's mother", "the team captain's father") is one person; the possessor is no group
(language/mentions.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("residential", "The team captain's father waits in the hall."),
    ("hotel", "The tour guide's sister waits by the bar."),
    ("residential", "The party host's mother walks from the kitchen to the garden."),
])
def test_compound_possessor_is_no_group(read, world, prompt):
    (group,) = read(world, prompt).groups
    assert group.count.value == 1


def test_quoted_case_reads_one_walker(read):
    (group,) = read("soft_play_centre", "The party host's mother carries the candle-lit cake from the café "
                                        "seating into party room two.").groups
    assert (group.count.value, group.start, group.destination) == (1, "cafe_seating", "party_room_2")
