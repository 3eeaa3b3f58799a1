"""Round 23 of the reader's people, counts and groups: a person moved along by another by a verb no
list of leading verbs has ("trundles", "marches"), said by a bare given name ("guides Doris from
..."), with what they ride in between ("brings Alastair in his wheelchair from ..."), or by a plural
subject whose verb the parser took for a modifier ("two carers wheel Mr Reid out of ..."), is a second
group that follows; the movers keep their own count."""

import pytest


@pytest.mark.parametrize("world,prompt,movers,start,destination", [
    ("hospital", "A nurse trundles a patient on a trolley out of radiology.", 1, "radiology", None),
    ("care_home", "A carer trundles a resident on a stretcher out of the lounge and into the garden.", 1, "lounge",
     "garden"),
    ("police_station", "Two officers march a drunk from the custody suite to the canteen.", 2, "custody_suite",
     "canteen"),
    ("police_station", "A pair of constables march a suspect from custody into interview room 1.", 2,
     "custody_suite", "interview_room_1"),
    ("care_home", "A nurse guides Doris from the lounge to the garden.", 1, "lounge", "garden"),
    ("office", "A receptionist walks Priya out of the kitchen and into the boardroom.", 1, "kitchen", "boardroom"),
    ("care_home", "A care assistant brings Alastair in his wheelchair from the lounge to the dining room.", 1,
     "lounge", "dining_room"),
    ("hospital", "A porter hustles Edna in her wheelchair out of ward A and down to the pharmacy.", 1, "ward_a",
     "pharmacy"),
    ("care_home", "Two carers wheel Mr Reid out of the lounge and into the garden.", 2, "lounge", "garden"),
    ("zoo", "Two keepers wheel Mr Reid from the gift shop to the cafe.", 2, "gift_shop", "cafe"),
])
def test_a_person_taken_along_by_others_is_a_second_group(read, world, prompt, movers, start, destination):
    mover, taken = read(world, prompt).groups
    assert mover.count.value == movers and taken.count.value == 1
    assert mover.intent == "walk" and taken.intent == "follow"
    assert (mover.start, mover.destination) == (start, destination)


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "A nurse sees a patient from ward A."),
    ("office", "A receptionist greets a visitor from reception."),
    ("care_home", "A carer watches Doris in the lounge."),
    ("office", "Two cleaners wheel the trolley out of the kitchen."),
])
def test_no_one_taken_along_without_a_person_and_a_route(read, world, prompt):
    assert all(g.intent != "follow" for g in read(world, prompt).groups)


@pytest.mark.parametrize("world,prompt", [
    ("office", "Two leaf blowers hum in the kitchen."),
    ("hospital", "Fairy lights hang around the cafeteria."),
])
def test_things_named_by_agent_nouns_are_nobody(read, world, prompt):
    assert all(g.count.kind == "vague" for g in read(world, prompt).groups)


@pytest.mark.parametrize("world,prompt,kind,value", [
    ("theme_park", "The moment the park opens, about seventy thrill-seekers sprint for the food court.", "approximate", 70),
    ("zoo", "About thirty sun-seekers laze on penguin beach.", "approximate", 30),
    ("office", "Some 12 autograph hunters hang about in reception.", "approximate", 12),
    ("market_hall", "A dozen bargain hunters rummage through the craft stalls as the robot sweeps up and down the "
     "central aisle.", "exact", 12),
    ("hospital", "Around forty autograph-hunters hang about in the cafeteria.", "approximate", 40),
    ("hospital", "A dozen sun-seekers hang around outside the cafeteria.", "exact", 12),
])
def test_a_count_on_people_named_by_a_split_agent_noun(read, world, prompt, kind, value):
    group = read(world, prompt).groups[0]
    assert group.count.kind == kind and group.count.value == value
