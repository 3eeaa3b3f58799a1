"""A uniformed youth unit named by "pack" ("a Brownie pack of twelve", "a pack of about twenty") is
people, as many as said; "a pack of crisps" and "pack up" stay a thing and a verb."""

import pytest


@pytest.mark.parametrize("world,prompt,kind,value", [
    ("mall", "A pack of about twenty is waiting at the fountain.", "approximate", 20),
    ("mall", "A Brownie pack of twelve is waiting at the fountain.", "exact", 12),
    ("museum", "A Scout pack of around forty walks from the entrance to the main hall.", "approximate", 40),
])
def test_a_youth_unit_counts_its_people(read, world, prompt, kind, value):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == (kind, value)


@pytest.mark.parametrize("world,prompt,value", [
    ("mall", "A shopper carries a pack of crisps to the fountain.", 1),
    ("mall", "Two guards pack up and leave through the main entrance.", 2),
])
def test_a_pack_of_things_or_packing_up_is_no_people(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert group.count.value == value
