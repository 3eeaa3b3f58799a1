"""A held thing fronted before the subject ("Mug in hand, a guard walks ...", "Flask under one arm, two
porters ...") is what the subject carries, never a person of its own."""

import pytest


@pytest.mark.parametrize("world,prompt,value,label", [
    ("station", "Mug in hand, a guard walks to platform 1.", 1, "guard"),
    ("office", "Mug of tea in hand, an intern walks to the kitchen.", 1, "intern"),
    ("hospital", "Flask under one arm, two porters stroll to ward 2.", 2, "porter"),
    ("airport", "Passport in her hand, a pilot strides to gate B2.", 1, "pilot"),
])
def test_a_fronted_held_thing_is_no_person(read, world, prompt, value, label):
    (group,) = read(world, prompt).groups
    assert (group.count.value, group.label) == (value, label)


def test_a_named_person_before_a_held_thing_stays(read):
    groups = read("museum", "Brolly in hand, Mrs Patel walks to the main hall.").groups
    assert len(groups) == 1 and groups[0].count.value == 1
