"""Clause and place classes of round 14, each with sentences of its own over at least two worlds (none
from the understanding sets): chat spelling (a dropped "g", "frm", "thru", "b4", "bc", "w/", "@", "2"
for "to" before a place but a number before people or as a place's number); a hazard said by what is
noticed or by an alarm going off makes leaving an evacuation; a thing named as a hazard's cause is no
place to refuse, a room kind the world lacks still is; everyday verbs of leaving."""

from __future__ import annotations

import pytest

# ---- A. chat spelling: dropped g, short words, "2" for "to" ------------------------------------------


@pytest.mark.parametrize("world,prompt,intent,start,destination", [
    ("bus_station", "3 cleaners walkin frm the cafe 2 the ticket office", "walk", "cafe", "ticket_office"),
    ("bus_station", "a driver headin frm bay 1 2 the staff office", "walk", "bay_1", "staff_office"),
    ("bus_station", "2 cleaners walk frm bay 2 2 the cafe", "walk", "bay_2", "cafe"),
    ("care_home", "3 carers headin frm the lounge 2 the dining room", "walk", "lounge", "dining_room"),
    ("hospital", "2 nurses walkin frm the pharmacy 2 radiology", "walk", "pharmacy", "radiology"),
    ("hotel", "2 guests headin frm the lobby 2 the restaurant", "walk", "lobby", "restaurant"),
])
def test_chat_spelling_of_a_walk_keeps_its_places(read, world, prompt, intent, start, destination):
    reading = read(world, prompt)
    group = reading.groups[0]
    assert (group.intent, group.start, group.destination) == (intent, start, destination)
    assert reading.unknown_places == ()


@pytest.mark.parametrize("world,prompt,intent,location", [
    ("bus_station", "4 ppl queuin @ the ticket office frm 9", "queue", "ticket_office"),
    ("bus_station", "2 drivers chattin in the staff office bc they r early", "converse", "staff_office"),
    ("care_home", "2 visitors chattin in the lounge", "converse", "lounge"),
    ("care_home", "a carer strollin round the garden", "wander", "garden"),
])
def test_a_dropped_g_is_the_verb(read, world, prompt, intent, location):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.location) == (intent, location)


@pytest.mark.parametrize("world,prompt,count,destination", [
    ("bus_station", "a driver goin 2 bay 2 b4 the bus leaves", 1, "bay_2"),  # "bay 2": the place's number
    ("bus_station", "2 drivers walkin frm the cafe 2 bay 3", 2, "bay_3"),  # "2 drivers": a count
    ("care_home", "2 carers walkin frm the lounge 2 kitchen", 2, "kitchen"),
])
def test_two_is_a_number_before_people_and_after_a_numbered_place(read, world, prompt, count, destination):
    group = read(world, prompt).groups[0]
    assert (group.count.value, group.destination) == (count, destination)


# ---- B. a hazard said by what is noticed or by an alarm: leaving is an evacuation --------------------


@pytest.mark.parametrize("world,prompt,start", [
    ("care_home", "A smell of burning in the lounge: the residents there get out", "lounge"),
    ("care_home", "the alarms are sounding: the residents in the dining room get out", "dining_room"),
    ("bus_station", "a smell of gas in the cafe: the passengers in the concourse get out", "concourse"),
    ("hospital", "Sparks fly from a socket, so the visitors in the cafeteria get out", "cafeteria"),
])
def test_a_hazard_narrative_makes_leaving_an_evacuation(read, world, prompt, start):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.start) == ("evacuate", start)


# ---- C. a thing named as a hazard's cause is no place to refuse ---------------------------------------


@pytest.mark.parametrize("world,prompt,start", [
    ("care_home", "Smell of burning from the hairdryer: the residents in the lounge get out through the fire exit",
     "lounge"),
    ("bus_station", "Smell of burning from the microwave, so the drivers in the staff office get out", "staff_office"),
    ("hospital", "Smoke pours from a laptop charger: the patients in the cafeteria get out now", "cafeteria"),
    ("care_home", "There is smoke coming from the laundry basket, the carers in the lounge leg it", "lounge"),
    ("bus_station", "flames from a bus engine at bay 2, passengers in the concourse leg it", "concourse"),
    ("care_home", "the gas leak in the boiler cupboard means the visitors in the dining room get out", "dining_room"),
])
def test_a_cause_thing_is_not_refused(read, world, prompt, start):
    reading = read(world, prompt)
    group = reading.groups[0]
    assert (group.intent, group.start) == ("evacuate", start)
    assert reading.unknown_places == ()


@pytest.mark.parametrize("world,prompt,refused", [
    ("care_home", "A smell of burning from the boiler room: the residents in the lounge get out", "boiler room"),
    ("bus_station", "Sparks from the cash machine: 4 passengers run to the arcade", "arcade"),
])
def test_a_room_the_world_lacks_is_still_refused_beside_a_hazard(read, world, prompt, refused):
    reading = read(world, prompt)
    assert refused in reading.unknown_places
    assert reading.groups[0].intent == "evacuate"


# ---- D. everyday verbs of leaving -------------------------------------------------------------------


@pytest.mark.parametrize("world,prompt,start", [
    ("care_home", "three residents leg it out of the lounge", "lounge"),
    ("care_home", "two carers bail from the lounge", "lounge"),
    ("bus_station", "four passengers scarper from the waiting room", "waiting_room"),
    ("hospital", "two visitors leg it out of the cafeteria", "cafeteria"),
])
def test_a_verb_of_leaving_is_a_walk_from_where_they_are(read, world, prompt, start):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.start) == ("walk", start)


@pytest.mark.parametrize("world,prompt,start", [
    ("care_home", "Sparks from the kettle: the carers in the lounge leg it", "lounge"),
    ("bus_station", "A burst pipe in the toilets, so the passengers in the waiting room scarper", "waiting_room"),
])
def test_a_verb_of_leaving_with_a_hazard_is_an_evacuation(read, world, prompt, start):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.start) == ("evacuate", start)


# ---- E. a thing's verb after a word of time gives the people no intent ------------------------------


@pytest.mark.parametrize("world,prompt,intent", [
    ("bus_station", "5 people queuing for tickets before the bus leaves", "queue"),
    ("care_home", "3 residents queuing at the dining room before the lunch trolley leaves", "queue"),
])
def test_a_things_verb_after_a_word_of_time_is_no_intent(read, world, prompt, intent):
    assert read(world, prompt).groups[0].intent == intent

