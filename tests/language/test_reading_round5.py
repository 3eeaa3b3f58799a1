"""Classes the fifth fresh set found, each with sentences of its own over at least two worlds (none
from the understanding sets): chat signs ("@ the desk", "~20"), people "in line" with no verb,
"N more at X" doing what the group before does, places a sentence calls by another word or by what
happens there, and phrases after a place preposition that are no place ("your bags", "the agenda")."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.language.text import normalise


def read(worlds, world, prompt):
    reading = read_prompt(prompt, worlds[world])
    assert reading.unknown_places == (), reading.unknown_places
    return reading


@pytest.mark.parametrize("typed,expected", [
    ("5 kids @ the fountain", "5 kids at the fountain"),
    ("~20 people @gate 3", "about 20 people at gate 3"),
    ("approx ~ 12 ppl", "approximately about 12 people"),
    ("mail bob@example.org or ~/notes", "mail bob@example.org or ~/notes"),
])
def test_chat_signs_are_words(typed, expected):
    assert normalise(typed) == expected


@pytest.mark.parametrize("world,prompt,location,value,kind", [
    ("hospital", "~15 ppl in line @ the pharmacy counter", "pharmacy_counter", 15, "approximate"),
    ("mall", "about a dozen shoppers in line at the express till", "express_till", 12, "approximate"),
    ("station", "8 commuters in a queue @ the ticket office", "ticket_office", 8, "exact"),
    ("airport", "twenty travellers in line at check-in counter A", "check_in_counter_a", 20, "exact"),
])
def test_people_in_line_with_no_verb_queue(worlds, world, prompt, location, value, kind):
    g, = read(worlds, world, prompt).groups
    assert (g.intent, g.location, g.count.value, g.count.kind) == ("queue", location, value, kind)


@pytest.mark.parametrize("world,prompt,first,second", [
    ("mall", "A dozen shoppers queue at the express till, 3 more at the coffee counter.", "express_till",
     "coffee_counter"),
    ("station", "Ten commuters queue at the ticket office, two more at the ticket machines.", "ticket_office",
     "ticket_machines"),
    ("hospital", "Six patients wait in the main waiting room and 3 more in the second waiting room.",
     "main_waiting_room", "outpatient_waiting"),
])
def test_more_of_a_group_with_no_verb_do_as_it_does(worlds, world, prompt, first, second):
    a, b = read(worlds, world, prompt).groups
    assert b.relation == "more_of:0" and b.intent == a.intent and (a.location, b.location) == (first, second)


@pytest.mark.parametrize("world,prompt,field,place", [
    ("hospital", "A porter pushes a trolley from the stockroom to the ICU.", "start", "supply_room"),
    ("hospital", "Two nurses gossip at the nurses' post.", "location", "nurse_station"),
    ("hospital", "A cleaner heads to the storeroom.", "destination", "supply_room"),
    ("station", "A porter carries two suitcases from the stockroom to platform 1.", "start", "left_luggage"),
])
def test_a_place_under_another_word_is_read_not_refused(worlds, world, prompt, field, place):
    g, = read(worlds, world, prompt).groups
    assert getattr(g, field) == place


@pytest.mark.parametrize("world,prompt", [
    ("residential", "Two kids play in the bowling alley."),
    ("mall", "Three teenagers wait at the bowling alley."),
    ("hospital", "A nurse walks to the helipad."),
])
def test_a_place_far_from_every_name_is_still_refused(worlds, world, prompt):
    assert read_prompt(prompt, worlds[world]).unknown_places


@pytest.mark.parametrize("world,prompt,start", [
    ("station", "Twelve commuters leave the waiting room and go out to the street.", "waiting_room"),
    ("hospital", "Five visitors walk out of the cafeteria to the car park.", "cafeteria"),
    ("office", "Two engineers leave the kitchen and head out to the street.", "kitchen"),
])
def test_the_street_is_out_through_an_exit(worlds, world, prompt, start):
    g, = read(worlds, world, prompt).groups
    index_exits = {d.name for z in worlds[world].zones for d in z.doors if d.exit}
    assert g.start == start and g.destination in index_exits, (g.start, g.destination)


@pytest.mark.parametrize("world,prompt,location", [
    ("office", "Three analysts talk through the budget in the boardroom.", "boardroom"),
    ("hospital", "Two doctors chat over the test results at the nurses' station.", "nurse_station"),
])
def test_a_topic_is_no_place(worlds, world, prompt, location):
    g, = read(worlds, world, prompt).groups
    assert g.location == location


@pytest.mark.parametrize("world,prompt,field,place", [
    ("station", "Four backpackers wait by the office where you can store your suitcases.", "location", "left_luggage"),
    ("airport", "Two porters walk to the hall where you collect your bags.", "destination", "baggage_claim"),
    ("hospital", "Nine patients queue at the counter where you pick up prescriptions.", "location", "pharmacy_counter"),
    ("residential", "The twins nap in the room where the children sleep.", "location", "child_bedroom"),
    ("office", "Two managers hurry to the room where the board meets.", "destination", "boardroom"),
])
def test_a_place_described_by_what_happens_there(worlds, world, prompt, field, place):
    g, = read(worlds, world, prompt).groups
    assert getattr(g, field) == place


@pytest.mark.parametrize("world,prompt,field,place", [
    ("airport", "A porter wheels a trolley from gate A2 to the baggage carousels.", "destination", "baggage_claim"),
    ("hospital", "Two nurses restock the supply shelves.", "location", "supply_room"),
    ("office", "Five developers type at the desks in silence.", "location", "open_plan_office"),
    ("airport", "Forty travellers queue at the check-in desks.", "location", "check_in_hall"),
])
def test_several_fixtures_alike_in_the_plural_are_their_room(worlds, world, prompt, field, place):
    g, = read(worlds, world, prompt).groups
    assert getattr(g, field) == place


@pytest.mark.parametrize("world,prompt,location", [
    ("mall", "Three teens wait by the toy shop's counter.", "toy_till"),
    ("station", "A barista waits behind the café's counter.", "cafe_counter"),
    ("hospital", "Four visitors queue at the pharmacy's counter.", "pharmacy_counter"),
    ("hospital", "A man waits at the cafeteria's counter.", "food_counter"),
])
def test_a_fixture_named_through_its_room(worlds, world, prompt, location):
    g, = read(worlds, world, prompt).groups
    assert g.location == location


@pytest.mark.parametrize("world,prompt,start,destination,value", [
    ("mall", "Smoke! The shoppers, twenty in total, pour out of the north doors.", None, "north_exit", 20),
    ("hospital", "Fire alarm: the visitors, nine in all, hurry out of the main entrance.", None, "main_entrance", 9),
    ("station", "Evacuation: the commuters, thirty in all, leave through the main doors.", None, "main_entrance", 30),
])
def test_a_count_in_apposition_and_out_of_an_exit(worlds, world, prompt, start, destination, value):
    g, = read(worlds, world, prompt).groups
    assert (g.start, g.destination, g.count.value) == (start, destination, value)


@pytest.mark.parametrize("world,prompt,field,place", [
    ("hospital", "Ward B's patients shuffle to the cafeteria.", "start", "ward_b"),
    ("mall", "Alarm! The food court's diners hurry to the east entrance.", "start", "food_court"),
    ("station", "The waiting room's twelve passengers walk to platform 2.", "start", "waiting_room"),
    ("office", "The kitchen's two baristas chat.", "location", "kitchen"),
])
def test_the_people_of_a_place_are_in_it(worlds, world, prompt, field, place):
    g, = read(worlds, world, prompt).groups
    assert getattr(g, field) == place


@pytest.mark.parametrize("world,prompt,label,value,start", [
    ("office", "Everyone in the kitchen, four interns, walks to the boardroom.", "intern", 4, "kitchen"),
    ("hospital", "Alarm! Everybody in the cafeteria, a dozen or so visitors, leaves by the main entrance.", "visitor",
     12, "cafeteria"),
    ("mall", "Everyone in the cinema lobby, thirty-odd teenagers, walks to the food court.", "teenager", 30,
     "cinema_lobby"),
])
def test_everyone_somewhere_then_who_and_how_many_is_one_group(worlds, world, prompt, label, value, start):
    g, = read(worlds, world, prompt).groups
    assert (g.label, g.count.value, g.start) == (label, value, start)


@pytest.mark.parametrize("world,prompt", [
    ("airport", "Five travellers leave the first-class lounge for gate A1."),
    ("hospital", "A nurse wheels a first-class patient to the lifts."),
])
def test_half_of_a_compound_before_a_noun_is_no_group(worlds, world, prompt):
    assert len(read_prompt(prompt, worlds[world]).groups) == 1


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "When the robot enters the lobby, the kids run to it and their parents shrink back."),
    ("mall", "As the robot passes the fountain, the teens cheer and their parents recoil."),
    ("office", "When the robot arrives, the interns wave at it and their boss steps back."),
])
def test_shrinking_back_once_the_robot_is_named_is_fear_of_it(worlds, world, prompt):
    g = read(worlds, world, prompt).groups[-1]
    assert (g.intent, g.robot_interaction, g.robot_reaction) == ("robot", "avoid", "Scared")


@pytest.mark.parametrize("world,prompt", [
    ("office", "Two interns step back from the printer."),
    ("station", "The robot crosses the concourse; a few commuters go back to the ticket hall."),
])
def test_stepping_back_from_something_else_is_no_reaction(worlds, world, prompt):
    g = read(worlds, world, prompt).groups[-1]
    assert g.robot_interaction is None


@pytest.mark.parametrize("world,prompt,location", [
    ("mall", "Two kids queue at the express till while a guard watches them from the supermarket doors.",
     "supermarket_exit"),
    ("hospital", "A nurse watches the patients from the nurses' station.", "nurse_station"),
    ("office", "The boss watches the interns from the boardroom door.", "boardroom_door"),
])
def test_watching_from_a_place_is_being_there(worlds, world, prompt, location):
    g = read(worlds, world, prompt).groups[-1]
    assert (g.location, g.start) == (location, None)


@pytest.mark.parametrize("world,prompt,label,start", [
    ("station", "The robot waits by the gateline as dozens of commuters stream out of the ticket hall.", "commuter",
     "ticket_hall"),
    ("mall", "The robot stands by the fountain while hundreds of fans flood in from the east entrance.", "fan",
     "east_entrance"),
])
def test_dozens_of_people_after_a_robot_clause_are_their_own_group(worlds, world, prompt, label, start):
    reading = read(worlds, world, prompt)
    g, = reading.groups
    assert (g.label, g.intent, g.start) == (label, "walk", start) and g.count.value >= 12
    assert reading.robot is not None and "as" not in reading.robot.text.split() and "while" not in reading.robot.text.split()


@pytest.mark.parametrize("world,prompt,interaction", [
    ("office", "When the robot rolls in, a porter jumps out of the robot's way.", "avoid"),
    ("mall", "When the robot comes, two teens move out of its path.", "avoid"),
    ("hospital", "A nurse stands in the robot's way.", "block"),
])
def test_out_of_the_robots_way_is_making_way(worlds, world, prompt, interaction):
    g = read(worlds, world, prompt).groups[-1]
    assert g.robot_interaction == interaction


@pytest.mark.parametrize("world,prompt,intent,seconds", [
    ("residential", "Two neighbours natter on the balcony for a whole hour.", "converse", 3600),
    ("office", "Two interns wait in the kitchen for a full minute.", "wait", 60),
    ("hospital", "Three aunties chatter in the lobby for an entire hour.", "converse", 3600),
])
def test_a_whole_hour_and_chattering(worlds, world, prompt, intent, seconds):
    g, = read(worlds, world, prompt).groups
    assert (g.intent, g.wait_seconds) == (intent, seconds)


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "Two nurses roll an old man in his bed from ward C to the ICU.", "ward_c", "intensive_care"),
    ("residential", "Dad carries the baby in her cot from the kids room to the living room.", "child_bedroom",
     "living_room"),
    ("airport", "An agent rolls a passenger in his wheelchair from gate A1 to the baggage claim.", "gate_a1",
     "baggage_claim"),
])
def test_a_person_rolled_or_carried_in_their_bed_is_a_second_group(worlds, world, prompt, start, destination):
    mover, moved = read(worlds, world, prompt).groups
    assert (mover.start, mover.destination, moved.start, moved.destination) == (start, destination, start, destination)
    assert moved.intent == "follow" and moved.count.value == 1


@pytest.mark.parametrize("world,prompt,location", [
    ("residential", "The parents sleep in their room while the kids play in theirs.", "child_bedroom"),
    ("office", "Two interns chat in the kitchen while the manager waits in his.", "manager_office"),
    ("museum", "Two guards drink tea in the café while the director reads in hers.", "director_office"),
])
def test_an_elided_possessive_is_the_persons_own_room(worlds, world, prompt, location):
    g = read(worlds, world, prompt).groups[-1]
    assert g.location == location


@pytest.mark.parametrize("world,prompt", [
    ("office", "Four interns at their desks turn their heads as the robot goes by."),
    ("hospital", "Two nurses turn their heads as the robot passes."),
    ("mall", "Three shoppers crane their necks as the robot glides past."),
])
def test_turning_heads_at_the_robot_is_looking(worlds, world, prompt):
    g = read(worlds, world, prompt).groups[-1]
    assert (g.robot_interaction, g.robot_reaction) == ("look", "Surprised")


@pytest.mark.parametrize("world,prompt,label,location", [
    ("hospital", "Six students with clipboards crowd around the nurses' station.", "student", "nurse_station"),
    ("station", "Ten fans with scarves huddle by the departure board.", "fan", "departure_board"),
    ("museum", "A dozen kids with worksheets cluster round the t-rex.", "kid", "t_rex_skeleton"),
])
def test_a_gathering_verb_after_what_people_carry_is_no_second_group(worlds, world, prompt, label, location):
    g, = read(worlds, world, prompt).groups
    assert (g.label, g.location) == (label, location)
