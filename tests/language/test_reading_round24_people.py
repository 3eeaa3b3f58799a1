"""Round 24 of the reader's people, counts and groups: a part said after its whole ("Of the ten
visitors waiting in the cafeteria, four troop over to ward A") by a collective's word that is its
verb, or by a verb the parser took for a noun before "and" and a verb ("three rise and stroll
through"), and with "the second half" of a game as a time, not the rest of the group; a list of
single people whose nouns the world uses for rooms ("a keeper and a vet hurry from ..."); one person
told by a feeling of the robot, whatever noun names them ("a nervous temp at ... is frightened of the
robot"); a role then a name between commas before a verb the parser took for a plural
noun ("our grandad, Bert, shuffles after the robot"); "q" typed in chat is a queue."""

import pytest


@pytest.mark.parametrize("world,prompt,whole,part,location,destination", [
    ("hospital", "Of the ten visitors waiting in the cafeteria, four troop over to ward A.", 10, 4, "cafeteria",
     "ward_a"),
    ("museum", "Of the fifteen pupils sketching in the main hall, six troop into the gift shop.", 15, 6,
     "great_hall", "gift_shop"),
    ("office", "Of the nine developers sat in the kitchen, three rise and stroll through to the boardroom.", 9, 3,
     "kitchen", "boardroom"),
    ("care_home", "Of the eight residents dozing in the lounge, two wake and shuffle off to the garden.", 8, 2,
     "lounge", "garden"),
    ("stadium", "Of the 16 fans drinking at the concourse bar, 5 go back up to the south stand when the second "
     "half kicks off.", 16, 5, "concourse_bar", "south_stand"),
    ("sports_centre", "Of the ten swimmers chatting in the cafe, three head off to the gym when the second half "
     "begins.", 10, 3, "cafe", "gym"),
])
def test_a_part_said_after_its_whole_is_one_subset(read, world, prompt, whole, part, location, destination):
    groups = read(world, prompt).groups
    assert len(groups) == 2
    stay, go = groups
    assert stay.count.value == whole and stay.location == location
    assert go.count.value == part and go.relation == "subset_of:0" and go.destination == destination


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("zoo", "A keeper and a vet hurry from the gift shop to the cafe.", "gift_shop", "cafe"),
    ("zoo", "A vet and a keeper rush from the vet room to the cafe.", "vet_room", "cafe"),
    ("zoo", "A keeper and a cleaner wander over to the lion viewing area.", None, "lion_viewing"),
    ("parcel_depot", "A loader and a driver hurry from the canteen to the loading bay.", "canteen", "van_bay_a"),
    ("parcel_depot", "A driver and a loader wander over to the canteen.", None, "canteen"),
])
def test_a_list_of_single_people_is_a_group_each(read, world, prompt, start, destination):
    groups = read(world, prompt).groups
    assert [g.count.value for g in groups] == [1, 1]
    assert all((g.start, g.destination) == (start, destination) for g in groups)


@pytest.mark.parametrize("world,prompt", [
    ("museum", "A cafe and a shop wait in the main hall."),
    ("zoo", "A gift shop and a cafe stand by the entrance plaza."),
])
def test_a_list_of_places_is_no_one(read, world, prompt):
    assert all(g.count.kind == "vague" for g in read(world, prompt).groups)


@pytest.mark.parametrize("world,prompt", [
    ("parcel_depot", "A new agency loader in the canteen is scared of the robot and cowers whenever it trundles by."),
    ("warehouse", "A nervous temp at the packing bench is frightened of the robot and flinches whenever it rolls past."),
    ("hospital", "A wobbly new locum on ward A is afraid of the robot and shrinks back when it comes near."),
    ("zoo", "The new vet by the cafe is wary of the robot and edges away whenever it comes close."),
])
def test_one_who_feels_something_of_the_robot_is_one_person(read, world, prompt):
    (group,) = read(world, prompt).groups
    assert group.count.kind == "exact" and group.count.value == 1
    assert group.robot_reaction == "Scared"


@pytest.mark.parametrize("world,prompt", [
    ("museum", "The lift in the main hall is out of order."),
    ("office", "A printer in the kitchen is jammed."),
])
def test_a_thing_in_a_state_is_no_one(read, world, prompt):
    assert all(g.count.kind == "vague" for g in read(world, prompt).groups)


@pytest.mark.parametrize("world,prompt", [
    ("care_home", "Our grandad, Bert, shuffles after the robot."),
    ("residential", "My little brother, Leo, scampers after the robot."),
    ("mall", "Our nan, Joan, potters after the robot."),
    ("zoo", "My niece, Isla, waddles after the robot."),
])
def test_a_role_then_a_name_between_commas_is_one_person(read, world, prompt):
    (group,) = read(world, prompt).groups
    assert group.count.kind == "exact" and group.count.value == 1
    assert group.robot_interaction == "follow"


@pytest.mark.parametrize("world,prompt,kind,value", [
    ("supermarket", "6 ppl in q @ till 3", "exact", 6),
    ("supermarket", "about 10 ppl in the q at till 1", "approximate", 10),
    ("station", "12 ppl in q for the ticket office", "exact", 12),
    ("airport", "like 30 pax in q @ security", "approximate", 30),
])
def test_q_typed_in_chat_is_a_queue(read, world, prompt, kind, value):
    (group,) = read(world, prompt).groups
    assert group.intent == "queue" and (group.count.kind, group.count.value) == (kind, value)
