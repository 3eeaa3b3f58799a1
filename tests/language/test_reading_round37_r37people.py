"""Who-and-how-many classes of round 37, each with sentences of its own over at least two worlds (none
from the understanding sets): a queue said as a line with its length ("the line at the pharmacy is
twenty strong") is that many people queueing there."""

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


# ---- guards: readings that must stay as they were --------------------------------------------------------

@pytest.mark.parametrize("world,prompt,value,intent", [
    ("mall", "A queue of twenty people waits at the food court.", 20, "queue"),
    ("hospital", "Twenty people queue at the pharmacy.", 20, "queue"),
    ("station", "Two guards walk along the line to platform 2.", 2, "walk"),
])
def test_queues_said_otherwise_keep_their_reading(read, world, prompt, value, intent):
    g = read(world, prompt).groups[0]
    assert (g.count.value, g.intent) == (value, intent)
