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
