"""A named owner in a partitive is one group, the owner's own people (language/owner_partitives.py):
"both of Mrs Patel's granddaughters" is two people, as "both of her granddaughters" is."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, n, intent", [
    ("museum", "Both of Mr Shah's sons wander from the cafe to the dinosaur gallery.", 2, "walk"),
    ("office", "All three of Dr Ahmed's students wait in the kitchen.", 3, "wait"),
    ("hospital", "Both of Tom's daughters walk to the pharmacy.", 2, "walk"),
    ("golf_club", "Both of Mr Evans's grandsons leave the bar and run up to the robot.", 2, "robot"),
])
def test_a_named_owners_people_are_one_group(read, world, prompt, n, intent):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value, group.intent) == ("exact", n, intent)


def test_a_part_of_a_group_said_before_stays_a_part(read):
    groups = read("hospital", "Ten nurses wait at the pharmacy and two of Mr Shah's sons walk to the exit.").groups
    assert [g.count.value for g in groups] == [10, 2]
