"""An order to have someone go somewhere or take something there ("..., and have a porter wheel linen out
of the stores up to ward 3", "Have a porter wheel linen to ward 3"): the person is a group of their own,
counted as said, and nobody said before them shares their verb ("Station a guard at the main entrance
and have two volunteers carry the chairs ...": the guard stays). Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, first, second", [
    ("hospital", "Put 2 security officers at reception, and have a porter wheel linen out of the stores up to ward 3.",
     (2, "wait", None, "reception_desk"), (1, "walk", "ward_c", None)),
    ("museum", "Station a guard at the main entrance and have two volunteers carry the chairs to the auditorium.",
     (1, "wait", None, "main_entrance"), (2, "walk", "auditorium", None)),
])
def test_an_ordered_group_is_its_own(read, world, prompt, first, second):
    groups = read(world, prompt).groups
    assert len(groups) == 2
    for g, (count, intent, destination, location) in zip(groups, (first, second)):
        assert (g.count.value, g.intent, g.destination, g.location) == (count, intent, destination, location)


@pytest.mark.parametrize("world, prompt, label, destination", [
    ("hospital", "Have a porter wheel linen to ward 3.", "porter", "ward_c"),
    ("supermarket", "Have a shelf stacker push a cage from the stockroom to the bakery.", "stacker", "bakery"),
])
def test_one_ordered_person_is_one_person(read, world, prompt, label, destination):
    (group,) = read(world, prompt).groups
    assert (group.count.value, group.label, group.destination) == (1, label, destination)


def test_have_a_look_is_no_order(read):
    (group,) = read("hospital", "Have a look around the lobby.").groups
    assert group.label != "look"
