"""Place classes of round 37, each with sentences of its own over at least two worlds (none from the
understanding sets): a place said before and referred back to by "it" after "on" or a verb of queueing
("the cast of 14 on it escape", "the riders queuing for it walk out"); people said by the queue they
stand in who then move ("ten people lined up for the Viper walk to the food court"); the people of a
place said back with "its" ("the cafe floods and its 12 customers leave")."""

from __future__ import annotations

import pytest


# ---- 1. "on it", "queuing for it": the place said before ------------------------------------------------

@pytest.mark.parametrize("world,prompt,start", [
    ("playhouse", "A spotlight starts smoking above the stage, so the cast of 14 on it escape.", "stage"),
    ("ice_rink", "A light fitting sparks above the rink, so the 40 skaters on it leave.", "rink"),
    ("playhouse", "A lamp sparks above the stage and everyone on it escapes.", "stage"),
    ("climbing_centre", "A hold snaps above the bouldering wall, so the 10 climbers on it walk out.", "bouldering_hall"),
    ("theme_park", "The Viper breaks down, and the 20 riders queuing for it walk out.", "viper_queue"),
    ("theme_park", "Splash Falls closes and the 12 people lined up for it head to the food court.", "flume_queue"),
])
def test_a_place_said_before_and_referred_back_by_it_is_where_people_start(read, world, prompt, start):
    r = read(world, prompt)
    assert r.groups[-1].start == start
    assert r.groups[-1].intent in ("walk", "evacuate")


# ---- 2. a queue said on the people who then move -------------------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("theme_park", "Ten people queuing for the Viper leave.", "viper_queue", None),
    ("theme_park", "Twenty riders lined up for the Viper walk to the food court.", "viper_queue", "food_court"),
    ("theme_park", "The 35 riders queuing for Splash Falls hurry out via the east emergency gate.", "flume_queue",
     "east_emergency_gate"),
    ("theme_park", "Splash Falls shuts and the 35 riders queuing for it hurry out via the east emergency gate.",
     "flume_queue", "east_emergency_gate"),
])
def test_people_queuing_for_a_place_who_move_start_in_its_queue(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.start, g.destination, g.location) == (start, destination, None)


# ---- 3. "its" people: the people of the place said before ------------------------------------------------

@pytest.mark.parametrize("world,prompt,start", [
    ("mall", "The toy store catches fire and its 20 shoppers escape through the main entrance.", "toy_store"),
    ("office", "The kitchen floods, so its 6 users walk out to the reception.", "kitchen"),
    ("museum", "The cafe floods and its 12 customers leave.", "cafe"),
    ("stadium", "With the away end's roof blown off, its 900 or so fans evacuate via gate C.", "north_stand"),
])
def test_its_people_start_in_the_place_said_before(read, world, prompt, start):
    (g,) = read(world, prompt).groups
    assert g.start == start


# ---- guards: readings that must stay ---------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("theme_park", "Ten people queue for the Viper.", "viper_queue"),
    ("mall", "A man sets his bag on the bench and sits on it.", "atrium_benches"),
])
def test_people_who_stay_keep_their_place(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert (g.location, g.start) == (location, None)


def test_the_robots_own_its_is_no_place(read):
    r = read("hospital", "The robot parks in the lobby and its 2 passengers walk to the pharmacy.")
    assert (r.groups[0].start, r.groups[0].destination) == (None, "pharmacy")


def test_people_said_in_a_place_keep_it(read):
    r = read("mall", "A fire starts in the toy store, so the 20 shoppers in it hurry out through the main entrance.")
    assert (r.groups[0].start, r.groups[0].destination) == ("toy_store", "main_entrance")
