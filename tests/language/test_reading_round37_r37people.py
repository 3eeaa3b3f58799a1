"""Who-and-how-many classes of round 37, each with sentences of its own over at least two worlds (none
from the understanding sets): a queue said as a line with its length ("the line at the pharmacy is
twenty strong") is that many people queueing there; a passive of taking whose "by" phrase the parser
hangs on the route ("Mrs Okoro is wheeled up to ward B by a porter") keeps its taker; "a pair of
orderlies wheel Mr Ahmed ..." keeps the pair who take him."""

from __future__ import annotations

import pytest


# ---- 1. a queue said as a line with its length -------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,kind,value,location", [
    ("hospital", "The line at the pharmacy is twenty strong and reaches back to the lifts.", "exact", 20, "pharmacy"),
    ("hospital", "At lunchtime the queue at the cafeteria is about thirty people long.", "approximate", 30,
     "cafeteria"),
    ("station", "By eight the queue for the ticket office is some thirty people long.", "approximate", 30,
     "ticket_office"),
    ("railway_museum", "The queue at the admissions desk is 25 deep and winds round past the lockers.", "exact", 25,
     "ticket_desk"),
    ("mall", "On Saturday the line at the food court is fifteen strong.", "exact", 15, "food_court"),
])
def test_a_line_with_its_length_is_that_many_queueing(read, world, prompt, kind, value, location):
    (g,) = read(world, prompt).groups
    assert (g.count.kind, g.count.value) == (kind, value)
    assert (g.intent, g.location, g.destination) == ("queue", location, None)


# ---- 2. a passive of taking with the "by" phrase after a route the parser misreads ---------------------

@pytest.mark.parametrize("world,prompt,taker,value,destination", [
    ("hospital", "Mrs Okoro is wheeled up to ward B by a porter.", "porter", 1, "ward_b"),
    ("hospital", "Mr Grant, still groggy, is taken up to ward B by two nurses.", "nurses", 2, "ward_b"),
    ("airport", "Mr Hale is wheeled up to gate B2 by an attendant.", "attendant", 1, "gate_b2"),
    ("airport", "Mrs Lee is taken up to gate B2 by her son.", "son", 1, "gate_b2"),
    ("hospital", "Mrs Okoro is wheeled up to ward B by Nurse Jo.", "Jo", 1, "ward_b"),
])
def test_a_passive_taker_after_the_route_is_kept(read, world, prompt, taker, value, destination):
    groups = read(world, prompt).groups
    assert len(groups) == 2
    (mover,) = [g for g in groups if taker in g.who]
    (moved,) = [g for g in groups if g is not mover]
    assert mover.count.value == value and mover.destination == destination
    assert moved.intent == "follow" and moved.follows == mover.who and moved.destination == destination


# ---- 3. "a pair of" takers whose verb the parser reads as a noun ----------------------------------------

@pytest.mark.parametrize("world,prompt,value,start,destination", [
    ("hospital", "A pair of orderlies wheel Mr Ahmed in his bed from ward B to radiology.", 2, "ward_b", "radiology"),
    ("hospital", "A pair of nurses wheel Mrs Lee from the cafeteria to ward B.", 2, "cafeteria", "ward_b"),
    ("hospital", "A couple of orderlies wheel Mrs Lee from the cafeteria to ward B.", 2, "cafeteria", "ward_b"),
    ("museum", "A pair of attendants wheel Mr Hale from the entrance hall to the cafe.", 2, "entrance_hall", "cafe"),
])
def test_counted_takers_keep_the_person_taken(read, world, prompt, value, start, destination):
    mover, moved = read(world, prompt).groups
    assert mover.count.value == value and (mover.start, mover.destination) == (start, destination)
    assert moved.count.value == 1 and moved.intent == "follow" and moved.follows == mover.who
    assert (moved.start, moved.destination) == (start, destination)


# ---- guards: readings that must stay as they were --------------------------------------------------------

@pytest.mark.parametrize("world,prompt,value,intent", [
    ("mall", "A queue of twenty people waits at the food court.", 20, "queue"),
    ("hospital", "Twenty people queue at the pharmacy.", 20, "queue"),
    ("station", "Two guards walk along the line to platform 2.", 2, "walk"),
])
def test_queues_said_otherwise_keep_their_reading(read, world, prompt, value, intent):
    g = read(world, prompt).groups[0]
    assert (g.count.value, g.intent) == (value, intent)


@pytest.mark.parametrize("world,prompt,count", [
    ("hospital", "Mrs Okoro is wheeled to ward B by the lifts.", 1),
    ("museum", "A pupil is taken to the cafe by the teacher.", 2),
    ("hospital", "A pair of nurses walk to the cafeteria.", 1),
    ("station", "The twins are taken down to platform 2 by their dad.", 2),
    ("care_home", "Mrs Dunn is wheeled up to the lounge by a carer.", 2),
    ("care_home", "A couple of carers wheel Mrs Dunn from the dining room to the lounge.", 2),
    ("museum", "A pair of guards escort a shoplifter from the gift shop to the entrance hall.", 2),
    ("mall", "Two orderlies wheel Mr Ahmed from the food court to the main entrance.", 2),
])
def test_takers_said_otherwise_keep_their_groups(read, world, prompt, count):
    assert len(read(world, prompt).groups) == count
