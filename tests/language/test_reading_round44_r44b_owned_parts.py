"""Round 44 (r44b): a part of someone's own people, with no count of the whole ("six of their parents",
"three of her doctoral students", "two of his mates"): only the part is there, one group of as many as
said; the whole ("their parents") is no group of the scene (language/collective_parts.py, partitives.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,counts", [
    ("mall", "Ten kids play by the fountain and four of their mums sit in the food court.", [10, 4]),
    ("university", "The professor and two of her research students walk from the library to the lecture theatre.", [1, 2]),
    ("hotel", "The groom waits in the lobby while three of his mates drink at the bar.", [1, 3]),
])
def test_a_part_of_someones_own_people_is_one_group(read, world, prompt, counts):
    reading = read(world, prompt)
    assert [g.count.value for g in reading.groups] == counts
    assert all(g.relation is None for g in reading.groups)


def test_a_part_of_a_group_said_before_stays_its_subset(read):
    a, b = read("hospital", "Ten nurses wait in the lobby; two of the nurses walk to the pharmacy.").groups
    assert (a.count.value, b.count.value, b.relation) == (10, 2, "subset_of:0")
