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
