"""People awaited in an "until"/"before" clause of arriving (language/awaited_comers.py): "until the night
team turns up", "before the doctors arrive", "Just before the surgeon comes in, ..." are no group of the
scene; the people who wait keep their place."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,intent,place", [
    ("hospital", "Two porters hover by the lifts until the night team turns up.", "wait", "elevator_hall"),
    ("hospital", "A visitor waits in reception until the consultant comes down.", "wait", "reception_desk"),
    ("hospital", "A porter loiters in the corridor before the doctors arrive.", "wait", "main_corridor"),
    ("office", "Three interns hang about in the kitchen till the boss finally shows up.", "wait", "kitchen"),
    ("station", "A guard waits on platform 2 until the relief crew has come back.", "wait", "platform_2"),
])
def test_people_awaited_in_an_until_clause_are_no_group(read, world, prompt, intent, place):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert groups[0].intent == intent and groups[0].location == place


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "Just before the surgeon comes in at nine, two nurses walk from the ward to the pharmacy.",
     "ward_a", "pharmacy"),
    ("museum", "Shortly before the curator turns up, a guide leads four visitors from the cafe to the entrance hall.",
     "cafe", "entrance_hall"),
])
def test_a_fronted_awaited_arrival_is_no_group(read, world, prompt, start, destination):
    groups = read(world, prompt).groups
    movers = [g for g in groups if g.intent == "walk"]
    assert movers and all((g.start, g.destination) == (start, destination) for g in movers)
    assert not any(g.who and ("surgeon" in g.who or "curator" in g.who) for g in groups)


def test_someone_who_leaves_with_the_people_is_still_there(read):
    groups = read("hospital", "A nurse waits in the cafeteria until the doctors come, then both go to ward B.").groups
    assert groups[0].location == "cafeteria"
