"""A place said by what is done there, with a verb whose "after" is a particle ("to where staff look after
children who got separated from their parents"): the clause runs on past "after", so its meaning finds
the room; and the people it is done for, said in general ("children", "witnesses"), are nobody present,
so no group. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, destination", [
    ("theme_park", "A frantic mother runs from the food court to where staff look after children who got separated "
                   "from their parents.", "lost_children_point"),
    ("community_centre", "A dad hurries from the cafe to where the volunteers look after the toddlers in the mornings.",
     "playgroup_room"),
    ("courthouse", "A nervous teenager walks from the main hall to where volunteers look after witnesses before they "
                   "give evidence.", "witness_service"),
])
def test_the_room_where_people_are_looked_after(read, world, prompt, destination):
    assert read(world, prompt).groups[0].destination == destination


@pytest.mark.parametrize("world, prompt", [
    ("theme_park", "A frantic mother runs from the food court to where staff look after children who got separated "
                   "from their parents."),
    ("courthouse", "A nervous teenager walks from the main hall to where volunteers look after witnesses before they "
                   "give evidence."),
])
def test_people_said_in_general_in_the_clause_are_no_group(read, world, prompt):
    assert len(read(world, prompt).groups) == 1


def test_people_said_as_present_in_the_clause_stay(read):
    reading = read("theme_park", "A mum runs from the food court to where her two kids are queuing for the log flume.")
    assert len(reading.groups) == 2
