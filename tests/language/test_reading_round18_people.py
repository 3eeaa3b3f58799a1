"""Round 18 of the reader's people: the groups of a passive in the order the sentence says them;
someone who only perceives or reports is no group; kin listed together are one family; asides
about a group are no group; approximate ranges ("a dozen or two"); people named by their wheelchair
or pram; a time clause about an activity ("once the tour is over") names nobody."""

import pytest


@pytest.mark.parametrize("world,prompt,taken,taker,start,destination", [
    ("hospital", "A patient is wheeled to radiology by a porter", "patient", "porter", None, "radiology"),
    ("hospital", "Two elderly men are taken from the pharmacy to the cafeteria by a nurse", "man", "nurse",
     "pharmacy", "cafeteria"),
    ("care_home", "Mrs Okafor is led to the lounge by two carers", None, "carer",
     None, "lounge"),
    ("museum", "A lost child is walked to the security office by a guard", "child", "guard", None,
     "security_office"),
])
def test_a_passive_s_groups_follow_the_order_said(read, world, prompt, taken, taker, start, destination):
    first, second = read(world, prompt).groups
    assert first.intent == "follow" and second.intent == "walk"
    assert taken is None or first.label == taken
    assert second.label == taker and (second.start, second.destination) == (start, destination)


def test_an_active_escort_keeps_the_taker_first(read):
    first, second = read("hospital", "A porter wheels a patient to radiology").groups
    assert (first.label, first.intent, second.intent) == ("porter", "walk", "follow")


@pytest.mark.parametrize("world,prompt,count,start", [
    ("university",
     "Someone smells burning in the chemistry lab and all fifteen researchers leave", 15, "chemistry_lab"),
    ("university",
     "A technician spots a leak in the robotics lab, so the 8 students evacuate", 8, "robotics_lab"),
    ("hospital", "A nurse notices a fire in the cafeteria and 20 visitors evacuate", 20, "cafeteria"),
    ("museum", "A guard hears an alarm in the gift shop and twelve tourists leave", 12, "gift_shop"),
])
def test_who_only_perceives_is_no_group(read, world, prompt, count, start):
    (g,) = read(world, prompt).groups
    assert g.count.value == count and g.intent == "evacuate" and g.start == start


def test_a_perceiver_who_also_moves_is_a_group(read):
    (g,) = read("hospital", "A guard notices smoke and walks to the cafeteria").groups
    assert g.label == "guard" and g.destination == "cafeteria"


@pytest.mark.parametrize("world,prompt,count", [
    ("mall", "Mum, Dad and the three kids walk to the food court", 5),
    ("mall", "Grandma, Grandpa and two grandchildren wait at the bookshop", 4),
    ("residential", "Mum, Dad, Gran and the baby go to the living room", 4),
    ("museum", "mum, dad and the 2 kids head to the cafe", 4),
])
def test_kin_listed_together_are_one_family(read, world, prompt, count):
    (g,) = read(world, prompt).groups
    assert (g.count.kind, g.count.value) == ("exact", count) and g.together


@pytest.mark.parametrize("world,prompt,low,high", [
    ("mall", "a dozen or two teens walk to the food court", 12, 24),
    ("museum", "One or two dozen pupils wait in the great hall", 12, 24),
    ("station", "two or three hundred fans wait on the concourse", 200, 300),
    ("hospital", "a handful or so of porters wait in the entrance lobby", 3, 5),
])
def test_approximate_ranges(read, world, prompt, low, high):
    (g,) = read(world, prompt).groups
    assert (g.count.low, g.count.high) == (low, high) and low <= g.count.value <= high


@pytest.mark.parametrize("world,prompt,label", [
    ("museum", "Once the tour is over, Mr Evans walks to the cafe", "man"),
    ("museum", "When the tour ends the guide walks to the staff room", "guide"),
    ("mall", "As soon as the party is over, the guests walk to the food court", "guest"),
    ("primary_school", "When the class is over, the teacher goes to the staff room", "teacher"),
])
def test_a_time_clause_about_an_activity_names_nobody(read, world, prompt, label):
    (g,) = read(world, prompt).groups
    assert g.label == label


def test_a_tour_group_that_arrives_is_people(read):
    groups = read("museum", "When the tour group arrives, the guide walks to the staff room").groups
    assert [g.label for g in groups] == ["tour", "guide"]


@pytest.mark.parametrize("world,prompt,count", [
    ("station", "Three commuters (all men) wait at the gateline", 3),
    ("station", "two guards (both women) walk to the cafe", 2),
    ("hospital", "Six nurses (all women) chat in the staff room", 6),
    ("museum", "Five tourists, all Germans, wait in the great hall", 5),
])
def test_an_aside_about_a_group_is_no_group(read, world, prompt, count):
    (g,) = read(world, prompt).groups
    assert g.count.value == count


@pytest.mark.parametrize("world,prompt,label,count", [
    ("hospital", "two wheelchairs roll from the entrance lobby to radiology", "wheelchair user", 2),
    ("hospital", "A pushchair goes to the pharmacy", "parent", 1),
    ("primary_school", "A wheelchair rolls to the school hall", "wheelchair user", 1),
    ("hospital", "A stroller heads to the cafeteria", "parent", 1),
])
def test_people_named_by_their_wheelchair_or_pram(read, world, prompt, label, count):
    (g,) = read(world, prompt).groups
    assert (g.label, g.count.value) == (label, count)


def test_a_pram_with_its_pusher_is_no_second_person(read):
    (g,) = read("hospital", "A mum with a pram walks to the pharmacy").groups
    assert g.label == "mum" and g.count.value == 1
