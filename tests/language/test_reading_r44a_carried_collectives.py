"""A collective of things carried ("brings a bunch of keys", "carries a bunch of balloons"): its noun
after "of" names no person, so it is the things carried and no group led along (a bunch of kids is
people). Language/carried_things.py."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "A porter brings a bunch of keys from the pharmacy to ward B."),
    ("mall", "A dad carries a bunch of balloons from the toy shop to the food court."),
    ("hall_of_residence", "Priya's dad brings a bunch of flowers from the common room to the kitchen."),
])
def test_a_bunch_of_things_carried_is_nobody(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.intent == "walk" and g.destination is not None


def test_a_bunch_of_people_brought_follow(read):
    porter, kids = read("hospital", "A porter brings a bunch of kids from the pharmacy to ward B.").groups
    assert (kids.label, kids.intent, kids.follows) == ("kid", "follow", porter.who)
