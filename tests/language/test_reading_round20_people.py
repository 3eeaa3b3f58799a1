"""Round 20 of the reader's people and counts: one person after a possessive or named by a first name
ending in "s" is one, not a crowd; a count with no noun, said of people at a place, counts people."""

import pytest


@pytest.mark.parametrize("world,prompt,destination", [
    ("hospital", "the porter's pal strolls over to the pharmacy", "pharmacy"),
    ("care_home", "the gardener's pal mooches over to the dining room", "dining_room"),
    ("care_home", "the cook's buddy ambles into the lounge", "lounge"),
    ("hospital", "Gladys pops out of the ward and along to the cafe", "cafeteria"),
    ("hospital", "Charles strolls over to the pharmacy", "pharmacy"),
    ("mall", "Agnes wanders over to the fountain", "fountain"),
])
def test_one_person_with_an_unlisted_verb_is_one(read, world, prompt, destination):
    (g,) = read(world, prompt).groups
    assert g.count.kind == "exact" and g.count.value == 1
    assert g.destination == destination


@pytest.mark.parametrize("world,prompt,value,destination", [
    ("care_home", "all 9 in the lounge head to the dining room", 9, "dining_room"),
    ("mall", "all 7 at the fountain walk to the east entrance", 7, "east_entrance"),
    ("hospital", "all 12 in the cafe go over to the pharmacy", 12, "pharmacy"),
    ("museum", "the fifteen in the gift shop head for the main entrance", 15, "main_entrance"),
])
def test_a_count_with_no_noun_at_a_place_counts_people(read, world, prompt, value, destination):
    (g,) = read(world, prompt).groups
    assert g.count.value == value and g.destination == destination
    assert g.label == "person"


@pytest.mark.parametrize("world,prompt,first,more", [
    ("care_home", "the twenty in the lounge and four more go to the dining room", 20, 4),
    ("mall", "the 30 at the fountain and six more head to the food court", 30, 6),
])
def test_a_count_with_no_noun_and_more_keeps_both(read, world, prompt, first, more):
    counts = sorted(g.count.value for g in read(world, prompt).groups)
    assert counts == sorted([first, more])


@pytest.mark.parametrize("world,prompt,more", [
    ("hospital", "a few visitors queue at reception and another 3 join them", 3),
    ("mall", "8 shoppers queue at the cafe counter and a few more arrive to queue later", None),
    ("gp_surgery", "six patients line up at the reception desk; later, 3 more join them", 3),
    ("airport", "five passengers queue at the security checkpoint, then another two join them", 2),
])
def test_people_who_join_a_queue_queue_with_it(read, world, prompt, more):
    first, second = read(world, prompt).groups
    assert first.intent == "queue" and second.intent == "queue"
    assert second.relation == "more_of:0"
    assert more is None or second.count.value == more


@pytest.mark.parametrize("world,prompt,count,destination", [
    ("office", "the 8 developers spend twenty minutes arguing, then troop back in to the meeting room", 8, "boardroom"),
    ("office", "the 6 interns chat for ten minutes and then troop back into the kitchen", 6, "kitchen"),
    ("courthouse", "The 12 jurors spend an hour deliberating, then troop back in to courtroom 2", 12, "courtroom_2"),
    ("courthouse", "the 5 barristers talk for a while and troop off to the robing room", 5, "robing_room"),
])
def test_a_group_verb_after_then_is_the_groups_verb(read, world, prompt, count, destination):
    (g,) = read(world, prompt).groups
    assert g.count.value == count and g.destination == destination
