"""Place classes of round 42 (fixtures inside rooms, rooms said by a part of them), each with sentences of
its own over at least two worlds (none from the understanding sets):
1. a thing of a room said with a word of the room ("the dorm bunks", "the desk in reception", "the
   chemist counter") is that thing, though a name of the room carries the thing's word ("bunk room",
   "front desk area", "medicine counter") or "in" is a word of one of the world's names.
2. "the <room> exit" is the one exit of that room, not the room people pass through, and "exit" after a
   room said after "to", "via", "through", "for" is no verb.
3. a room said by its name's first words and the kind of its several things ("the roped walls" of the
   "roped hall") is that room."""

from __future__ import annotations

import pytest


# ---- 1. a thing of a room said with the room's word ----------------------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("museum", "Three kids stare at the mummy in the egypt gallery.", "mummy_case"),
    ("museum", "A school group crowds round the whale in the great hall.", "whale_skeleton"),
    ("office", "A visitor waits at the desk in reception.", "reception_desk"),
    ("office", "Two admins stand by the servers in the server room.", "server_racks"),
    ("blood_donor_centre", "Two donors linger by the snacks in the refreshment area.", "snack_table"),
    ("hospital", "Four patients queue at the chemist counter.", "pharmacy_counter"),
    ("fire_station", "A firefighter dozes on the dorm bunks.", "bunks"),
    ("aquarium", "Six children gather at the tank in the rock pool area.", "touch_tank"),
])
def test_a_thing_said_with_its_rooms_word_is_the_thing(read, world, prompt, location):
    (group,) = read(world, prompt).groups
    assert group.location == location


# ---- 2. the one exit of a room said with the room ------------------------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("museum", "Twenty visitors hurry to the egyptian gallery exit.", "fire_exit"),
    ("aquarium", "Fifteen visitors head for the shark tunnel exit.", "tunnel_fire_exit"),
    ("aquarium", "A family walks through the reef gallery exit.", "reef_fire_exit"),
    ("hospital", "Nine visitors leave via the cafeteria exit.", "cafeteria_terrace_door"),
    ("art_gallery", "Thirty people file out through the sculpture court exit.", "court_fire_exit"),
    ("blood_donor_centre", "Five donors make for the refreshment area exit.", "refreshment_fire_exit"),
    ("mall", "Ten shoppers hurry to the food court exit.", "north_exit"),
])
def test_a_rooms_exit_said_with_the_room_is_that_exit(read, world, prompt, destination):
    (group,) = read(world, prompt).groups
    assert group.destination == destination and not group.via


# ---- 3. a room by its first words and its several things -----------------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("climbing_centre", "Two instructors chat beside the roped walls.", "rope_hall"),
    ("climbing_centre", "Ten climbers queue at the roped walls.", "rope_hall"),
    ("airport", "Two officers stand by the screening scanners.", "security_checkpoint"),
    ("airport", "A cleaner mops near the screening scanners.", "security_checkpoint"),
])
def test_a_room_said_by_its_first_words_and_its_things_is_the_room(read, world, prompt, location):
    (group,) = read(world, prompt).groups
    assert group.location == location


# ---- guards: rooms, things and verbs that keep their reading -------------------------------------------

@pytest.mark.parametrize("world,prompt,start", [
    ("aquarium", "The visitors in the shark tunnel exit quickly.", "shark_tunnel"),
    ("concert_venue", "The fans in the circle exit calmly.", "circle"),
])
def test_people_in_a_room_who_exit_it_start_there(read, world, prompt, start):
    (group,) = read(world, prompt).groups
    assert group.start == start


@pytest.mark.parametrize("world,prompt,field,place", [
    ("mall", "Ten shoppers hurry to the main exit.", "destination", "main_entrance"),
    ("museum", "Two guards stand in the egyptian gallery.", "location", "egyptian_gallery"),
    ("office", "Two devs wait at the kitchen counter.", "location", "kitchen_counter"),
    ("hotel", "Two guests sit at the ballroom tables.", "location", "banquet_tables"),
    ("fire_station", "A firefighter sleeps in the bunk room.", "location", "dormitory"),
    ("hospital", "Five patients wait at the medicine counter.", "location", "pharmacy"),
    ("office", "Five interviewers sit at the table in huddle room two.", "location", "meeting_table_2"),
    ("climbing_centre", "Six climbers chat by the lead wall.", "location", "lead_wall"),
    ("mall", "Two kids sit on the benches in the atrium.", "location", "atrium_benches"),
])
def test_rooms_and_things_said_whole_keep_their_reading(read, world, prompt, field, place):
    (group,) = read(world, prompt).groups
    assert getattr(group, field) == place
