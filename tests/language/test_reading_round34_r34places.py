"""Place classes of round 34, each with sentences of its own over at least two worlds (none from the
understanding sets): a thing said with its state ("a jammed pinsetter") is the thing worked on; "for"
and a place right after a place moved off, out of or from is where they go (refused when the world
lacks it); a bare adverb of place then "in" a room of it ("backstage in the green room") is the room."""

from __future__ import annotations

import pytest


# ---- 1. a thing said with its state: the thing worked on is where they are -----------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("bowling_alley", "A mechanic repairs a jammed pinsetter.", "pinsetters"),
    ("bowling_alley", "Two mechanics free a jammed pinsetter.", "pinsetters"),
    ("hospital", "An engineer repairs the jammed lift.", "elevator_hall"),
    ("office", "A cleaner unblocks a blocked sink.", "kitchen_counter"),
    ("office", "A plumber repairs the cracked sink.", "kitchen_counter"),
])
def test_a_thing_said_with_its_state_is_where_they_work(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.location == location


@pytest.mark.parametrize("world,prompt,location", [
    ("bowling_alley", "A mechanic repairs the pinsetter.", "pinsetters"),
    ("office", "A plumber fixes the sink.", "kitchen_counter"),
    ("hospital", "An engineer mends the lift.", "elevator_hall"),
])
def test_a_thing_worked_on_without_a_state_keeps_its_reading(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.location == location


@pytest.mark.parametrize("world,prompt,destination", [
    ("bowling_alley", "A mechanic walks to the jammed pinsetter.", "pinsetters"),
    ("office", "A plumber walks to the leaking sink.", "kitchen_counter"),
])
def test_a_thing_with_its_state_as_a_destination_keeps_its_reading(read, world, prompt, destination):
    (g,) = read(world, prompt).groups
    assert g.destination == destination


# ---- 2. "for" right after a place moved off, out of or from: where they go ------------------------------

@pytest.mark.parametrize("world,prompt,start,unknown", [
    ("station", "A guard heads off platform 2 for the signal box.", "platform_2", "signal box"),
    ("station", "A guard in hi-vis strides off the second platform for the signal box.", "platform_2", "signal box"),
    ("hospital", "A porter walks out of the cafeteria for the boiler house.", "cafeteria", "boiler house"),
    ("hospital", "Two porters hurry from the cafeteria for the boiler house.", "cafeteria", "boiler house"),
    ("mall", "Three teenagers wander out of the food court for the skate park.", "food_court", "skate park"),
])
def test_a_place_the_world_lacks_after_a_place_moved_off_is_refused(read, world, prompt, start, unknown):
    r = read(world, prompt)
    (g,) = r.groups
    assert g.start == start
    assert unknown in r.unknown_places


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "A porter walks out of the cafeteria for the pharmacy.", "cafeteria", "pharmacy"),
    ("station", "A guard heads off the second platform for the ticket office.", "platform_2", "ticket_office"),
])
def test_a_place_the_world_has_after_a_place_moved_off_keeps_its_reading(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.start, g.destination) == (start, destination)


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "A porter walks out of the cafeteria for a smoke."),
    ("hospital", "Two nurses walk out of the cafeteria for the night."),
])
def test_what_they_go_for_after_a_place_moved_off_is_not_refused(read, world, prompt):
    assert read(world, prompt).unknown_places == ()


# ---- 3. a bare adverb of place then the room in it: the room --------------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("concert_venue", "A singer waits backstage in the green room.", "green_room"),
    ("concert_venue", "A singer waits backstage in the artists' lounge.", "green_room"),
    ("concert_venue", "Two cellists relax backstage in the green room.", "green_room"),
    ("ice_rink", "A coach stands rinkside at the cafe.", "cafe"),
])
def test_a_bare_adverb_of_place_then_a_room_in_it_is_the_room(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.location == location


@pytest.mark.parametrize("world,prompt,location", [
    ("concert_venue", "A singer waits backstage.", "backstage"),
    ("concert_venue", "A singer waits backstage in silence.", "backstage"),
    ("swimming_baths", "A mum sits poolside.", "pool_hall"),
    ("swimming_baths", "A mum sits poolside in the cafe.", "cafe"),
])
def test_a_bare_adverb_of_place_alone_keeps_its_reading(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.location == location


# ---- 4. a person's own thing: the one of the person named, never a kind to refuse -----------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("care_home", "Mr Kowalski shuffles back to his own bed.", "room_2_bed"),
    ("care_home", "Mrs Okafor walks back to her own bed.", "room_3_bed"),
    ("care_home", "Mr Kowalski shuffles back to his bed.", "room_2_bed"),
])
def test_a_persons_own_thing_is_the_one_of_the_person_named(read, world, prompt, destination):
    r = read(world, prompt)
    (g,) = r.groups
    assert g.destination == destination
    assert r.unknown_places == ()


@pytest.mark.parametrize("world,prompt", [
    ("hall_of_residence", "A student heads back to her own bed."),
    ("care_home", "An old man shuffles back to his own bed."),
    ("hall_of_residence", "Two students stumble back to their own beds."),
])
def test_an_own_thing_of_someone_unnamed_is_no_kind_to_refuse(read, world, prompt):
    r = read(world, prompt)
    (g,) = r.groups
    assert g.destination is not None and r.unknown_places == ()


@pytest.mark.parametrize("world,prompt,destination", [
    ("hall_of_residence", "Tom heads back to his own bed.", "g02_bed"),
    ("care_home", "Mr Kowalski heads back to his own room.", "room_2"),
    ("care_home", "Mrs Baxter walks back to her room.", "room_1"),
    ("hospital", "A nurse walks back to her own station.", "nurse_station"),
])
def test_a_persons_own_room_keeps_its_reading(read, world, prompt, destination):
    (g,) = read(world, prompt).groups
    assert g.destination == destination
