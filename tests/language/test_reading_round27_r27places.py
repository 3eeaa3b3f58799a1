"""Round 27 of the reader's places: a verb of work and its particle acts on the thing ("wipes down the
fountain"), no way down it; the room said after the thing worked on is where they are ("polishes the
tables in the restaurant"); a fixture said as it is written, against its room said in the plural ("at
the till": the till counter, not the tills); a place referred back by "it" ("the waiting room floods,
and the people sitting in it ..."); the verb after what people are on ("two students on placement water
the orchids"), no part of that noun phrase."""

import pytest


@pytest.mark.parametrize("world,prompt,location", [
    ("mall", "A cleaner wipes down the fountain.", "fountain"),
    ("station", "A porter wipes down the benches.", "concourse_benches"),
    ("fire_station", "Two firefighters hose down the scrap cars.", "scrap_cars"),
    ("hospital", "A nurse wipes down the reception desk.", "reception_desk"),
    ("hotel", "A cleaner polishes up the banquet tables.", "banquet_tables"),
    ("museum", "A cleaner wipes down the benches.", "great_hall_benches"),
])
def test_a_verb_of_work_and_its_particle_acts_on_the_thing(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.location == location and not g.via and g.start is None


@pytest.mark.parametrize("world,prompt,location", [
    ("station", "A barista wipes the tables in the cafe.", "cafe"),
    ("station", "A cleaner polishes the sinks in the toilets.", "toilets"),
    ("station", "A shop assistant tidies the magazines in the newsagent.", "newsagent"),
    ("hotel", "A waiter polishes the tables in the restaurant.", "restaurant"),
    ("fire_station", "Two cadets hang tunics in the kit room.", "kit_room"),
])
def test_the_room_said_after_the_thing_worked_on_is_where_they_are(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.location == location


@pytest.mark.parametrize("world,prompt,location", [
    ("garden_centre", "Three shoppers queue at the till.", "till_counter"),
    ("garden_centre", "A pensioner with a trolley waits at the till.", "till_counter"),
    ("supermarket", "A woman rummages in the freezer.", "chest_freezers"),
    ("station", "A backpacker waits by the locker.", "luggage_lockers"),
    ("police_station", "An officer waits by the locker.", "officer_lockers"),
])
def test_a_fixture_said_as_written_against_its_room_in_the_plural(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.location == location


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("station", "The waiting room floods, and the twelve people sitting in it move out to the concourse.",
     "waiting_room", "concourse"),
    ("hospital", "A pipe bursts in the cafeteria and the six nurses eating in it hurry to the main corridor.",
     "cafeteria", "main_corridor"),
    ("museum", "A leak floods the cafe, and the twenty tourists sitting in it head to the great hall.",
     "cafe", "great_hall"),
    ("mall", "Water pours into the food court, and the forty shoppers eating in it drift out to the fountain.",
     "food_court", "fountain"),
    ("office", "The kitchen floods and the three engineers chatting in it run out to the lobby.",
     "kitchen", "reception"),
])
def test_a_place_referred_back_by_it(read, world, prompt, start, destination):
    g = read(world, prompt).groups[-1]
    assert g.start == start and g.destination == destination


@pytest.mark.parametrize("world,prompt,location", [
    ("hotel", "Two waiters on the late shift polish the banquet tables.", "banquet_tables"),
    ("fire_station", "A firefighter on duty hoses down the scrap cars.", "scrap_cars"),
    ("garden_centre", "Two students on placement water the orchids.", "orchid_table"),
    ("supermarket", "Three staff on the night shift stack shelves in the frozen foods aisle.", "frozen_foods"),
])
def test_the_verb_after_what_people_are_on(read, world, prompt, location):
    r = read(world, prompt)
    (g,) = r.groups
    assert g.location == location and not r.unknown_places


# ---- guards: readings that must not change ---------------------------------------------------------

@pytest.mark.parametrize("world,prompt,role,place", [
    ("station", "Two guards walk down the platform.", "via", ("platform_1",)),
    ("hospital", "A porter walks down the corridor to the pharmacy.", "via", ("main_corridor",)),
    ("hospital", "Two nurses on duty walk to the pharmacy.", "destination", "pharmacy"),
    ("hospital", "A nurse on her break sits in the cafeteria.", "location", "cafeteria"),
    ("station", "A cleaner wipes the tables.", "location", "cafe_tables"),
    ("garden_centre", "Three lads on work experience stack the growbags.", "location", "compost_pallets"),
])
def test_guard_ways_down_and_what_people_are_on(read, world, prompt, role, place):
    (g,) = read(world, prompt).groups
    assert getattr(g, role) == place


@pytest.mark.parametrize("world,prompt,location", [
    ("supermarket", "A man waits at the till.", "checkouts"),
    ("fire_station", "A firefighter stands in the shower.", "shower_cubicles"),
    ("mall", "A man walks to the fountain and sits on the edge of it.", "fountain"),
    ("station", "A cleaner walks to the cafe and waits in it.", "cafe"),
])
def test_guard_places_already_read(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.location == location
