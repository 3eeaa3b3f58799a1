"""Round 9 on people, counts, clauses and the robot, each class with sentences of its own over at least
two worlds (none from the understanding sets): a person no list names, said with "a"/"an", a number or
as a name, is that many people ("an airline rep", "two second-years", "Little Tom"); a number after a
comma with a state and a place borrows the group's noun ("..., 1 asleep on the benches"); couple words
("the newlyweds") are two together; "spend twenty minutes / the afternoon at X" is a stay of that long;
acting so that the robot cannot pass is blocking it; carrying something out of a room is walking; a
cleaner who "wanders" is not a "wanderer"."""

from __future__ import annotations

import pytest


def first(reading):
    assert reading.groups, reading
    return reading.groups[0]


# ---- A. a person no list names -----------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,count", [
    ("airport", "A baggage rep waits at the information desk", 1),
    ("hotel", "An events rep walks to the bar", 1),
    ("university", "A third-year walks to the library", 1),
    ("university", "Three final-years wander around the atrium", 3),
    ("library", "Two second-years sit in the reading room", 2),
    ("hospital", "Little Sam waits in the waiting room", 1),
    ("residential", "Little Ben walks to the kitchen", 1),
])
def test_an_unlisted_person_is_counted(read, world, prompt, count):
    g = first(read(world, prompt))
    assert g.who != "people"
    assert (g.count.kind, g.count.value) == ("exact", count)


# ---- B. a number after a comma borrows the noun ----------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("station", "4 blokes wait by the ticket machines, 2 asleep on the benches", "concourse_benches"),
    ("sports_centre", "seven swimmers in the pool, one asleep on the benches", "poolside_bench"),
])
def test_a_number_with_a_state_after_a_comma(read, world, prompt, place):
    r = read(world, prompt)
    assert len(r.groups) == 2, r.groups
    second = r.groups[1]
    assert second.label == r.groups[0].label and second.count.kind == "exact"
    assert second.location == place


# ---- C. couples and stays -------------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("hotel", "The honeymooners walk to the restaurant"),
    ("mall", "The newlyweds wander around the food court"),
])
def test_couple_words_are_two_together(read, world, prompt):
    g = first(read(world, prompt))
    assert g.count.value == 2 and g.together


@pytest.mark.parametrize("world,prompt,seconds", [
    ("mall", "A shopper spends ten minutes at the food court", 600),
    ("university", "A porter spends five minutes in the atrium", 300),
    ("hotel", "Two guests spend the afternoon in the bar", 3 * 3600),
])
def test_spending_time_is_a_stay(read, world, prompt, seconds):
    g = first(read(world, prompt))
    assert g.intent == "wait" and g.wait_seconds == seconds


# ---- D. so that the robot cannot pass -------------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("office", "Four staff stand shoulder to shoulder so the robot can't get through"),
    ("hotel", "Two porters stand in the corridor so that the robot cannot pass"),
    ("library", "Three students stand in the aisle so the robot can't get past"),
])
def test_keeping_the_robot_from_passing_is_blocking(read, world, prompt):
    g = first(read(world, prompt))
    assert g.robot_interaction == "block" and g.robot_reaction == "Threatening"


# ---- F. carrying out of a room; a verb read as an agent noun --------------------------------------

@pytest.mark.parametrize("world,prompt,start", [
    ("hotel", "A waiter carries plates out of the kitchen", "kitchen"),
    ("hospital", "A porter carries boxes out of the pharmacy", None),
])
def test_carrying_out_of_a_room_is_walking(read, world, prompt, start):
    g = first(read(world, prompt))
    assert g.intent == "walk"
    if start is not None:
        assert g.start == start


@pytest.mark.parametrize("world,prompt", [
    ("office", "A cleaner wanders round the kitchen emptying the bins"),
    ("hospital", "A cleaner wanders round the waiting room wiping the chairs"),
])
def test_a_verb_after_a_person_is_no_agent_noun(read, world, prompt):
    g = first(read(world, prompt))
    assert g.label == "cleaner" and g.intent == "wander"


# ---- E. an event that empties out as a matter of course -------------------------------------------

@pytest.mark.parametrize("world,prompt,start", [
    ("university", "The 11 am seminar, 25 students, empties out of the lecture theatre into the corridor",
     "lecture_theatre_1"),
    ("hotel", "The wedding reception, 80 guests, spills out of the ballroom into the garden", "ballroom"),
    ("mall", "The afternoon screening crowd spills out of the cinema", "cinema_lobby"),
])
def test_an_event_emptying_out_is_walking(read, world, prompt, start):
    g = first(read(world, prompt))
    assert g.intent == "walk" and g.start == start


def test_an_emptying_out_with_a_hazard_stays_an_evacuation(read):
    g = first(read("mall", "Fire! The matinee crowd empties out of the cinema"))
    assert g.intent == "evacuate"


# ---- a name after a child's word; a person word in a place's name ---------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("residential", "Little Ben walks from the kitchen to his bedroom", "child_bedroom"),
    ("residential", "Baby Ava crawls from the living room to her bedroom", "child_bedroom"),
])
def test_a_little_one_by_name_is_a_child(read, world, prompt, destination):
    g = first(read(world, prompt))
    assert g.label == "child" and g.count.value == 1 and g.destination == destination


@pytest.mark.parametrize("world,prompt", [
    ("hotel", "Ten guests queue at the buffet and two waiters chat by the host stand"),
    ("hotel", "Two porters wait by the concierge desk while six guests queue at reception"),
])
def test_a_person_word_in_a_place_name_is_no_group(read, world, prompt):
    assert len(read(world, prompt).groups) == 2


# ---- the other half -------------------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,whole", [
    ("university", "Half of the forty students walk to the library and the other half stay in the atrium", 40),
    ("office", "Half of the ten developers go to the kitchen and the other half stay at their desks", 10),
])
def test_the_other_half_is_the_rest(read, world, prompt, whole):
    r = read(world, prompt)
    halves = [g for g in r.groups if g.count.value == whole // 2]
    assert len(halves) == 2, r.groups
    assert {g.intent for g in halves} == {"walk", "wait"}


# ---- a collective whose members a count names; a time is no count ---------------------------------

@pytest.mark.parametrize("world,prompt,label,count", [
    ("museum", "The school party, 25 children, waits in the foyer", "child", 25),
    ("hotel", "The wedding party, about 40 guests, gathers in the ballroom", "guest", 40),
    ("university", "The 9 am class, 30 pupils, leaves the lecture theatre", "pupil", 30),
])
def test_a_collective_with_its_members_counted_is_one_group(read, world, prompt, label, count):
    r = read(world, prompt)
    assert len(r.groups) == 1, r.groups
    assert r.groups[0].label == label and r.groups[0].count.value == count
