"""Group-count classes of round 37, each with sentences of its own over at least two worlds (none from
the understanding sets): the part of a whole said first that moves off by a verb of going the parser
takes for a noun the number counts ("Of the ten members at the table, 3 duck into the phone booths")."""

from __future__ import annotations

import pytest


# ---- 1. a part moving off by a verb the parser takes for a counted noun ---------------------------------

@pytest.mark.parametrize("world,prompt,whole,part,start,destination", [
    ("coworking_space", "Of the 10 members at the communal table, 3 duck into the phone booths.", 10, 3,
     "communal_table", "phone_pods"),
    ("station", "Of the 40 commuters on platform 2, 6 dart into the waiting room.", 40, 6, "platform_2",
     "waiting_room"),
    ("mall", "Of the twenty shoppers in the food court, five hop over to the cinema.", 20, 5, "food_court",
     "cinema_lobby"),
    ("hospital", "Of the nine visitors in the cafeteria, four crowd into the lift lobby.", 9, 4, "cafeteria",
     "elevator_hall"),
    ("office", "Of the eight engineers in the open office, two duck out to the kitchen.", 8, 2,
     "open_plan_office", "kitchen"),
])
def test_a_part_moving_off_by_a_noun_like_verb_is_a_group(read, world, prompt, whole, part, start, destination):
    stay, go = read(world, prompt).groups
    assert (stay.count.value, go.count.value) == (whole, part)
    assert stay.location == start and stay.destination is None
    assert (go.intent, go.start, go.destination) == ("walk", start, destination)


# ---- guards: readings that must stay as they were --------------------------------------------------------

@pytest.mark.parametrize("world,prompt,n", [
    ("office", "Of the ten engineers in the open office, three walk into meeting room 2.", 2),
    ("mall", "Three shoppers duck into the cinema.", 1),
    ("aquarium", "Ten fish swim in the shark tunnel while two visitors watch.", 1),
    ("hospital", "A nurse wheels a patient from room 4 into the lift lobby.", 2),
])
def test_group_numbers_stay(read, world, prompt, n):
    assert len(read(world, prompt).groups) == n
