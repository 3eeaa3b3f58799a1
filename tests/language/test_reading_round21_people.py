"""Round 21 of the reader's people, counts and groups: a passive of taking someone whose taker is said
right after the verb, with the route after the taker ("a pensioner who has wandered in is taken by a
PCSO from the desk to the room": the taken first, following; the taker walks the route); a name with
its role after it ("Pete the butcher strolls ...") before a second clause joined by "as" or "while"."""

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("police_station", "A lost child who has wandered off is taken by a nurse from the canteen to the front desk.",
     "canteen", "front_counter"),
    ("police_station", "Two drunk lads who came in shouting are led by a sergeant out of the front counter into "
     "the custody suite.", "front_counter", "custody_suite"),
    ("hospital", "An elderly man who has got lost is walked by a porter from the cafe to the pharmacy.",
     "cafeteria", "pharmacy"),
    ("hospital", "A toddler who wandered off is brought by a security guard back to the main entrance.",
     None, "main_entrance"),
])
def test_taken_by_someone_said_before_the_route(read, world, prompt, start, destination):
    r = read(world, prompt)
    taken, taker = r.groups
    assert taken.intent == "follow" and taker.intent == "walk"
    assert taker.start == start and taker.destination == destination
    assert not r.unknown_places


@pytest.mark.parametrize("world,prompt,first,second", [
    ("market_hall", "Pete the butcher strolls from the bakery stall to the noodle stall while a couple of cleaners "
     "carry bins from the toilets to the loading bay.", ("bakery_stall", "noodle_stall"), ("toilets", "loading_bay")),
    ("market_hall", "Dave the baker wanders over from the bakery stall to the noodle stall, as two porters wheel "
     "boxes from the loading bay into the cold store.", ("bakery_stall", "noodle_stall"), ("loading_bay", "cold_store")),
    ("hospital", "Ahmed the cleaner mops from the pharmacy to the cafeteria while three visitors wait in the main "
     "waiting room.", ("pharmacy", "cafeteria"), None),
    ("hospital", "Linda the receptionist hurries from the entrance lobby to the pharmacy while two patients queue at "
     "the pharmacy counter.", ("entrance_lobby", "pharmacy"), None),
    ("office", "Mr Jones the manager walks from reception to the kitchen, as three cleaners push trolleys from the "
     "kitchen into the boardroom.", ("reception", "kitchen"), ("kitchen", "boardroom")),
])
def test_a_name_with_its_role_then_a_second_clause(read, world, prompt, first, second):
    named, others = read(world, prompt).groups
    assert named.count.value == 1 and (named.start, named.destination) == first
    assert others.count.value > 1
    if second is not None:
        assert (others.start, others.destination) == second


@pytest.mark.parametrize("world,prompt,placed,route", [
    ("hospital", "Drop 2 security guards at reception, and have a porter wheel a bed out of radiology up to the "
     "pharmacy.", "reception_desk", ("radiology", "pharmacy")),
    ("hospital", "Drop three nurses in the cafeteria and have a cleaner push a trolley from the pharmacy to "
     "radiology.", "cafeteria", ("pharmacy", "radiology")),
    ("office", "Drop two couriers at reception, and have an intern carry boxes out of the kitchen into the "
     "boardroom.", "reception", ("kitchen", "boardroom")),
    ("office", "Drop a guard by the main entrance and have two cleaners push trolleys from the kitchen to the "
     "boardroom.", "main_entrance", ("kitchen", "boardroom")),
])
def test_drop_people_somewhere_and_have_others_go(read, world, prompt, placed, route):
    dropped, had = read(world, prompt).groups
    assert dropped.location == placed and dropped.start is None
    assert (had.start, had.destination) == route and had.intent == "walk"
