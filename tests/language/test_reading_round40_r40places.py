"""Place classes of round 40, each with sentences of its own over at least two worlds (none from the
understanding sets): a checkpoint "cleared" on the way ("clears customs and heads to ...", "having cleared
security, ...") is passed through, not a place left; a part of a place said with a count or "either"
("at one end of the counter", "on either side of the tables", "at the head of the table") is the place."""

from __future__ import annotations

import pytest


# ---- 1. a checkpoint cleared on the way is passed through --------------------------------------------

@pytest.mark.parametrize("world,prompt,via,destination", [
    ("airport", "Two businessmen clear security and stroll over to gate A2.", "security_checkpoint", "gate_a2"),
    ("airport", "Having cleared security, a young couple heads for the duty free.", "security_checkpoint",
     "duty_free"),
    ("station", "A student clears the ticket barriers, then jogs down to platform 2.", "gateline", "platform_2"),
    ("ferry_terminal", "Three lorry drivers clear passport control and wander to the waiting lounge.",
     "security_check", "departure_lounge"),
    ("aquarium", "After clearing the turnstiles, a school party heads into the shark tunnel.", "turnstiles",
     "shark_tunnel"),
])
def test_a_cleared_checkpoint_is_passed_on_the_way(read, world, prompt, via, destination):
    (group,) = read(world, prompt).groups
    assert via in group.via
    assert group.destination == destination
    assert group.start != via


# ---- guards: clearing a place with nothing after it, and passing through, keep their reading ----------

@pytest.mark.parametrize("world,prompt,start", [
    ("airport", "Two guards clear the security checkpoint.", "security_checkpoint"),
    ("station", "Staff clear the concourse.", "concourse"),
])
def test_clearing_a_place_alone_keeps_its_reading(read, world, prompt, start):
    (group,) = read(world, prompt).groups
    assert group.start == start or group.location == start
    assert start not in group.via


@pytest.mark.parametrize("world,prompt,via,destination", [
    ("airport", "A pilot passes through security and heads to gate A1.", "security_checkpoint", "gate_a1"),
    ("station", "A commuter goes through the ticket barriers and heads to platform 2.", "gateline", "platform_2"),
])
def test_passing_through_a_checkpoint_keeps_its_reading(read, world, prompt, via, destination):
    (group,) = read(world, prompt).groups
    assert via in group.via and group.destination == destination


# ---- 2. a counted part of a fixture or room is the place ---------------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("office", "Four interns perch at one end of the table in meeting room 2.", "meeting_table_2"),
    ("office", "Two managers sit on either side of the table in huddle room two.", "meeting_table_2"),
    ("ferry_terminal", "A pair of truckers lean on one end of the café counter.", "cafe_counter"),
    ("aquarium", "Six pensioners sit along one side of the café tables.", "cafe_tables"),
    ("mall", "Three teenagers loiter at both ends of the food court tables.", "dining_tables"),
    ("office", "The CEO sits at the head of the table in meeting room 2.", "meeting_table_2"),
])
def test_a_counted_part_of_a_place_is_the_place(read, world, prompt, location):
    (group,) = read(world, prompt).groups
    assert group.location == location


# ---- guards: the parts the reader knew, and a head who is a person, keep their reading ---------------

@pytest.mark.parametrize("world,prompt,location", [
    ("ferry_terminal", "Two backpackers wait at the far end of the café counter.", "cafe_counter"),
    ("office", "Three engineers sit at the table in meeting room 2.", "meeting_table_2"),
])
def test_known_parts_keep_their_place(read, world, prompt, location):
    (group,) = read(world, prompt).groups
    assert group.location == location


def test_the_head_of_a_department_is_no_table(read):
    reading = read("hospital", "The head of security waits in the entrance lobby.")
    assert [g.location for g in reading.groups] == ["entrance_lobby"]


# ---- 3. people said by a hyphened word led by a function word keep their place ----------------------

@pytest.mark.parametrize("world,prompt,count,location", [
    ("hospital", "Two worried in-laws in the cafeteria.", 2, "cafeteria"),
    ("mall", "Three no-shows at the information desk.", 3, "information_desk"),
    ("airport", "Four on-lookers by the departure board.", 4, "departure_board"),
    ("aquarium", "Two by-standers at the ocean window.", 2, "ocean_window"),
    ("ferry_terminal", "Five in-patients by the info desk.", 5, "information_desk"),
    ("station", "Two has-beens on platform 2.", 2, "platform_2"),
])
def test_a_hyphened_person_word_led_by_a_function_word_is_people_placed(read, world, prompt, count, location):
    (group,) = read(world, prompt).groups
    assert group.count.value == count
    assert group.location == location
    assert group.intent != "walk"


@pytest.mark.parametrize("world,prompt,destination", [
    ("mall", "Two in-laws stroll over to the food court.", "food_court"),
    ("hospital", "Three no-shows wander off to the cafeteria.", "cafeteria"),
])
def test_guard_a_hyphened_person_word_that_walks_goes_where_said(read, world, prompt, destination):
    (group,) = read(world, prompt).groups
    assert group.destination == destination and group.count.value in (2, 3)


# ---- guards: relatives by marriage after a kin word, and hyphened words the reader knew ---------------

@pytest.mark.parametrize("world,prompt,location", [
    ("hospital", "Two sisters-in-law wait in the cafeteria.", "cafeteria"),
    ("hospital", "Two co-workers in the cafeteria.", "cafeteria"),
    ("mall", "Four walk-ins at the information desk.", "information_desk"),
])
def test_hyphened_people_the_reader_knew_keep_their_place(read, world, prompt, location):
    (group,) = read(world, prompt).groups
    assert group.location == location
