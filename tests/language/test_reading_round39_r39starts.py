"""Start classes of round 39, each with sentences of its own over at least two worlds (none from the
understanding sets): a time said by "mid-" and an event noun that also names a group ("Mid-party, the
kitchen's alarm goes off and ...", "... wander to the café mid-tour") is a time, not one more group, so
the people who leave keep the start the alarm gives them."""

from __future__ import annotations

import pytest


# ---- 1. "mid-party", "mid-tour", "mid-class": a time, not a group -------------------------------------

@pytest.mark.parametrize("world,prompt,start", [
    ("mall", "Mid-party, the food court's fire alarm goes off and sixty shoppers hurry out through the main entrance.",
     "food_court"),
    ("hall_of_residence", "The JCR's smoke detector trips mid-party and a dozen residents pile out through the "
     "bike store door.", "common_room"),
    ("museum", "In mid-tour, the visitors in the great hall wander to the café.", "great_hall"),
    ("museum", "The visitors in the great hall wander to the café mid-tour.", "great_hall"),
    ("university", "Mid-class, the smoke alarm in SR2 goes off and twenty students file out.", "seminar_room_2"),
    ("office", "Mid-party, the kitchen's smoke alarm goes off and a dozen staff file out of the main entrance.",
     "kitchen"),
])
def test_a_mid_event_time_is_not_a_group(read, world, prompt, start):
    (group,) = read(world, prompt).groups
    assert group.start == start
    assert group.intent in ("walk", "evacuate")


# ---- guards: "mid-" adjectives and a real party keep their reading ------------------------------------

@pytest.mark.parametrize("world,prompt,count", [
    ("museum", "A party of six wanders from the great hall to the café.", 6),
    ("mall", "A mid-sized group of 12 shoppers waits in the food court.", 12),
    ("station", "Mid-morning, two guards walk from platform 2 to the ticket office.", 2),
])
def test_mid_adjectives_and_real_parties_keep_their_reading(read, world, prompt, count):
    (group,) = read(world, prompt).groups
    assert group.count.value == count


# ---- 2. a zone that shuts: the people who then leave start in it --------------------------------------

@pytest.mark.parametrize("world,prompt,start", [
    ("mall", "The food court shuts and sixty shoppers hurry out through the main entrance.", "food_court"),
    ("mall", "The food court closes, so sixty shoppers head for the main entrance.", "food_court"),
    ("hospital", "The cafeteria shuts early and a dozen visitors walk to the main entrance.", "cafeteria"),
    ("museum", "The café shuts down and twenty visitors wander to the great hall.", "cafe"),
    ("theme_park", "Without warning the Viper shuts, and forty riders file out via the east emergency gate.",
     "viper_station"),
])
def test_people_leaving_a_zone_that_shuts_start_in_it(read, world, prompt, start):
    (group,) = read(world, prompt).groups
    assert group.start == start


# ---- guards: a door that shuts, a zone shut by someone, a zone that is closed -------------------------

@pytest.mark.parametrize("world,prompt,starts", [
    ("office", "The lift door shuts and two staff walk to the kitchen.", [None]),
    ("mall", "The food court is closed, so a family waits by the fountain.", [None]),
])
def test_a_shut_door_or_a_closed_zone_gives_no_start(read, world, prompt, starts):
    assert [g.start for g in read(world, prompt).groups] == starts
