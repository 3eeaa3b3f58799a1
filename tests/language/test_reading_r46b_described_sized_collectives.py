"""A collective sized with "of", then a word that describes its people, then who they are ("a gang of
ten excited kids", "a squad of twelve junior nurses"): one group of that many people, as without
the describing word, not "ten gang members" and a few more. Language/counted_collectives.py."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,value", [
    ("zoo", "A gang of eight noisy teenagers wander from the penguin pool to the cafe.", 8),
    ("hospital", "A team of twelve junior doctors hurry from the cafeteria to ward B.", 12),
    ("mall", "A troop of six little scouts march from the toy shop to the food court.", 6),
])
def test_a_sized_collective_of_described_people_is_one_group(read, world, prompt, value):
    (g,) = read(world, prompt).groups
    assert g.count.value == value


def test_a_sized_collective_with_a_verb_after_is_its_members(read):
    (g,) = read("zoo", "A troupe of eight walk from the penguin pool to the cafe.").groups
    assert g.count.value == 8
