"""Group-count classes of round 37, each with sentences of its own over at least two worlds (none from
the understanding sets): the part of a whole said first that moves off by a verb of going the parser
takes for a noun the number counts ("Of the ten members at the table, 3 duck into the phone booths"); a list
item whose verb the parser takes for a noun after its plural subject or "a couple" ("..., and a couple
bowl on lane 3", "a pair of guests paddle in the indoor pool")."""

from __future__ import annotations

import pytest


# ---- 1. a part moving off by a verb the parser takes for a counted noun ---------------------------------

@pytest.mark.parametrize("world,prompt,whole,part,start,destination", [
    # "the phone booths" is the phone booth area's own name (its pods are only "a phone booth"): round 44
    ("coworking_space", "Of the 10 members at the communal table, 3 duck into the phone booths.", 10, 3,
     "communal_table", "phone_booths"),
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


# ---- 2. a list item's verb taken for a noun after its plural or "a couple" -----------------------------

@pytest.mark.parametrize("world,prompt,n,index,location", [
    ("bowling_alley", "Two staff mop the concourse, and a couple bowl on lane 3.", 2, 1, "bumper_lanes"),
    ("hotel", "A porter waits in the lobby, a pair of guests paddle in the indoor pool, and a cleaner hoovers the "
     "corridor.", 3, 1, "swimming_pool"),
    ("mall", "A guard stands at the main entrance, and a couple dance by the cinema.", 2, 1, "cinema_lobby"),
    ("mall", "Two cleaners mop the food court and a couple picnic by the fountain.", 2, 1, "fountain"),
    ("hotel", "The receptionist yawns behind the desk and a couple smoke outside the main entrance.", 2, 1,
     "main_entrance"),
])
def test_a_list_items_noun_like_verb_keeps_its_people(read, world, prompt, n, index, location):
    groups = read(world, prompt).groups
    assert len(groups) == n
    assert (groups[index].count.value, groups[index].location) == (2, location)


# ---- 3. people who arrive only after a fronted "Before ... arrive," are no group ----------------------

@pytest.mark.parametrize("world,prompt,count,start,destination", [
    ("hospital", "Before the first patient arrives, a nurse walks from reception to ward B.", 1, "reception_desk",
     "ward_b"),
    ("office", "Before the boss gets in, Dave nips from the kitchen to meeting room 2.", 1, "kitchen",
     "meeting_room_2"),
    ("museum", "Before the school party turns up, a curator walks from the cafe to the ancient Egypt gallery.", 1,
     "cafe", "egyptian_gallery"),
    ("mall", "Before the shoppers arrive, two cleaners walk from the food court to the main entrance.", 2,
     "food_court", "main_entrance"),
])
def test_people_yet_to_arrive_are_no_group(read, world, prompt, count, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.count.value, g.start, g.destination) == (count, start, destination)


# ---- guards: readings that must stay as they were --------------------------------------------------------

@pytest.mark.parametrize("world,prompt,n", [
    ("office", "Of the ten engineers in the open office, three walk into meeting room 2.", 2),
    ("mall", "Three shoppers duck into the cinema.", 1),
    ("aquarium", "Ten fish swim in the shark tunnel while two visitors watch.", 1),
    ("hospital", "A nurse wheels a patient from room 4 into the lift lobby.", 2),
    ("swimming_baths", "A lifeguard sits by the poolside, a pair of toddlers paddle in the learner pool, and two "
     "mums chat in the café.", 3),
    ("hospital", "A nurse waits at reception, a couple of visitors queue in the cafeteria, and a porter walks to "
     "ward B.", 3),
    ("mall", "Two guards stand by the main entrance and a couple bicker outside the cinema.", 2),
    ("dental_clinic", "Until the dentist arrives, two patients wait in reception.", 1),
    ("mall", "After the shoppers arrive, two cleaners walk to the main entrance.", 2),
])
def test_group_numbers_stay(read, world, prompt, n):
    assert len(read(world, prompt).groups) == n
