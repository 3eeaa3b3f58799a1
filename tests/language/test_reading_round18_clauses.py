"""Round 18 of the reader's clauses and places: leaving for the day is a walk, not an evacuation;
a hazard said as an event ("a pipe bursts") makes leaving an evacuation; laps and circuits of a
place are wandering there; running for a train or a
flight goes where it is boarded."""

import pytest


@pytest.mark.parametrize("world,prompt,start", [
    ("mall", "Three teenagers make themselves scarce from the bookshop.", "bookshop"),
    ("mall", "Two staff knock off for the day from the toy store.", "toy_store"),
    ("mall", "The cleaners in the food court call it a day.", "food_court"),
    ("office", "The developers in the open plan office knock off early.", "open_plan_office"),
    ("office", "Two interns make themselves scarce from the kitchen.", "kitchen"),
    ("museum", "The guides in the great hall clock off for the day.", "great_hall"),
])
def test_leaving_for_the_day_is_a_walk_away(read, world, prompt, start):
    (g,) = read(world, prompt).groups
    assert g.intent == "walk" and g.start == start and g.destination is None


@pytest.mark.parametrize("world,prompt,start", [
    ("hospital", "A pipe bursts in the pharmacy and the staff leave.", "pharmacy"),
    ("hospital", "The sprinklers go off in the staff room and everyone leaves.", "staff_room"),
    ("hospital", "A ceiling panel falls in the main waiting room and ten patients hurry out.", "main_waiting_room"),
    ("museum", "The roof starts leaking in the great hall so the tourists leave.", "great_hall"),
    ("museum", "When a water pipe bursts in the cafe, the visitors there leave.", "cafe"),
    ("library", "Water pours through the ceiling of the reading room and the readers in there leave.", "reading_room"),
])
def test_leaving_after_a_hazard_said_as_an_event_is_an_evacuation(read, world, prompt, start):
    (g,) = read(world, prompt).groups
    assert g.intent == "evacuate" and g.start == start


@pytest.mark.parametrize("world,prompt,location", [
    ("mall", "A boy does laps of the main atrium.", "main_atrium"),
    ("mall", "Two joggers run circuits of the west mall.", "west_mall"),
    ("airport", "A man walks circuits of the arrivals hall.", "arrivals_hall"),
    ("airport", "A bored child does a lap of the duty free.", "duty_free"),
    ("library", "An old man walks slow laps of the reading room.", "reading_room"),
])
def test_laps_and_circuits_of_a_place_are_wandering_there(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.intent == "wander" and g.location == location


@pytest.mark.parametrize("world,prompt,destination", [
    ("station", "Two passengers run for the train.", "platform_"),
    ("airport", "A late couple dash from duty free for their flight.", "gate_"),
    ("airport", "Four passengers run for their flight.", "gate_"),
    ("bus_station", "A woman runs for the last coach.", "bay_"),
    ("bus_station", "Two students run for the bus.", "bay_"),
    ("ferry_terminal", "A family rushes for the ferry.", "boarding_area"),
])
def test_running_for_a_conveyance_goes_where_it_is_boarded(read, world, prompt, destination):
    (g,) = read(world, prompt).groups
    assert g.intent == "walk" and g.pace == "fast" and (g.destination or "").startswith(destination)


@pytest.mark.parametrize("world,prompt,destination", [
    ("library", "Two children follow the robot to the cafe.", "cafe"),
    ("mall", "A curious child trails the robot into the food court.", "food_court"),
    ("mall", "Three students follow the robot out into the food court.", "food_court"),
    ("hospital", "A curious child follows the robot into the cafeteria.", "cafeteria"),
])
def test_people_who_follow_the_robot_somewhere_make_it_lead_there(read, world, prompt, destination):
    r = read(world, prompt)
    (g,) = r.groups
    assert g.robot_interaction == "follow" and g.destination == destination
    assert r.robot is not None and (r.robot.task, r.robot.destination) == ("cross", destination)


def test_the_robot_followed_nowhere_said_is_given_no_task(read):
    assert read("hospital", "Two visitors follow the robot.").robot is None


@pytest.mark.parametrize("world,prompt,location", [
    ("hospital", "Two visitors wait outside the pharmacy.", "main_corridor"),
    ("hospital", "A porter stands in front of the staff room.", "central_corridor"),
    ("station", "A man waits outside the newsagent.", "concourse"),
    ("station", "Two teenagers loiter in front of the cafe.", "concourse"),
    ("hospital", "Two visitors wait inside the pharmacy.", "pharmacy"),
])
def test_outside_a_room_is_the_zone_its_door_opens_to(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.location == location
