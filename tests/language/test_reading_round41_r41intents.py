"""Intent classes of round 41, each with sentences of its own over at least two worlds (none from the
understanding sets): an alarm that calls somebody, is on a watched thing, is false or stops is no
evacuation ("paged by a temperature alarm", "once the alarm clears"); the people's own verbs say what
they do; a person who leaves a place and locks or shuts themselves in a room goes into it ("storms out of
X and locks himself in the toilets"): it is where they go, not where they wait."""

from __future__ import annotations

import pytest


# ---- 1. an alarm that is no hazard leaves walking as walking ---------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("data_centre", "Called out by a humidity alarm, a technician walks from the NOC to data hall 1.", "data_hall_1"),
    ("data_centre", "After the alarm stops, two engineers walk back to the NOC.", "noc"),
    ("data_centre", "Responding to a door alarm, a guard walks to the loading bay.", "loading_bay"),
    ("hospital", "Alerted by a pump alarm, a nurse hurries to ward 2.", "ward_b"),
    ("hospital", "Woken by the bed alarm, a nurse hurries to ward 2.", "ward_b"),
    ("hospital", "After a false alarm, visitors drift back to the cafe.", "cafeteria"),
    ("hospital", "The alarm falls silent and visitors walk back to the cafe.", "cafeteria"),
    ("office", "When the alarm is silenced, staff wander back to their desks.", "open_plan_office"),
    ("mall", "Once the alarm clears, shoppers walk back into the food court.", "food_court"),
    ("mall", "A guard checks the alarm and strolls to the food court.", "food_court"),
    ("mall", "Once the alarm has been reset, shoppers stroll back into the food court.", "food_court"),
    ("office", "A freezer alarm goes off and a cleaner hurries to the kitchen.", "kitchen"),
])
def test_an_alarm_that_is_no_hazard_is_no_evacuation(read, world, prompt, destination):
    (group,) = read(world, prompt).groups
    assert group.intent != "evacuate"
    assert group.destination == destination


# ---- guards: an alarm that goes off, a fire alarm, an alarm heard keep the evacuation ---------------

@pytest.mark.parametrize("world,prompt", [
    ("mall", "The alarm goes off and shoppers walk to the exits."),
    ("mall", "Shoppers hear the alarm and head for the exits."),
    ("hospital", "The fire alarm goes off and a nurse walks to the exit."),
    ("office", "When the fire alarm sounds, staff walk to the assembly point."),
])
def test_an_alarm_that_warns_keeps_the_evacuation(read, world, prompt):
    (group,) = read(world, prompt).groups
    assert group.intent == "evacuate"


# ---- 2. locking or shutting oneself in a room is going into it ---------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("office", "An intern walks out of the boardroom and shuts herself in the ladies.", "boardroom", "restroom_women"),
    ("hospital", "A nurse walks out of the ward and locks herself in the staff room.", "ward_a", "staff_room"),
    ("mall", "A teenager runs out of the food court and locks himself in the toilets.", "food_court", "restrooms"),
    ("residential", "A teenager stomps upstairs and locks herself in the bathroom.", None, "bathroom"),
    ("diy_store", "A cashier storms off the tills and shuts himself in the staff room.", "tills", "staff_room"),
    ("hospital", "A junior doctor leaves the ward, then shuts herself in the staff room to cry.", "ward_a", "staff_room"),
    ("museum", "A guard slips away from the gift shop and locks himself in the staff room.", "gift_shop", "staff_room"),
])
def test_shutting_oneself_in_a_room_is_going_there(read, world, prompt, start, destination):
    (group,) = read(world, prompt).groups
    assert group.intent == "walk"
    assert group.destination == destination
    if start is not None:
        assert group.start == start


# ---- guards: shutting oneself in with no going before, shutting a thing in, waiting keep their reading --

@pytest.mark.parametrize("world,prompt,location", [
    ("office", "Two interns barricade themselves in the kitchen.", "kitchen"),
    ("residential", "After the row, the teenager locks himself in his bedroom.", "child_bedroom"),
    ("museum", "Fed up, a guard locks himself away in the staff room.", "staff_room"),
    ("hospital", "A porter shuts the door to the ward and waits in the staff room.", "staff_room"),
    ("office", "A manager sits in the kitchen.", "kitchen"),
])
def test_shutting_a_thing_or_waiting_keeps_its_reading(read, world, prompt, location):
    (group,) = read(world, prompt).groups
    assert group.intent == "wait" and group.location == location
