"""Round 28 of the reader's people: an approximate apposed strength ("its audience, some 150 strong,")
is an approximate count; a name with its group in apposition ("Kayleigh, one of the lifeguards,") is
one person; a fronted whole with no person noun ("Of the nine sat in X, ...") and its part said as a
pair ("..., a pair get up") are a whole and its subset; a named person's wheelchair or buggy takes them
along; a person held "arm in arm" or "by the hand" is still taken along; a name with the place they
work ("Jo from reception") is one person; a counted object of a verb of carrying whose noun is no
person word ("takes a handful of used mirrors") is things carried, no group; little ones carried
("mums with babies in slings") are no group of their own."""

import pytest


@pytest.mark.parametrize("world,prompt,low,high", [
    ("mall", "The crowd, some 150 strong, walk to the fountain.", 120, 180),
    ("mall", "The shoppers, about forty strong, drift to the food court.", 32, 48),
    ("stadium", "The away end, roughly 300 strong, files out through gate C.", 240, 360),
    ("cinema", "The audience, some sixty strong, leave screen 1.", 48, 72),
    ("museum", "The school party, around thirty strong, wanders into the main hall.", 24, 36),
])
def test_an_approximate_strength_is_an_approximate_count(read, world, prompt, low, high):
    (group,) = read(world, prompt).groups
    assert group.count.kind == "approximate" and (group.count.low, group.count.high) == (low, high)


@pytest.mark.parametrize("world,prompt,who", [
    ("mall", "Kayleigh, one of the cleaners, walks to the fountain.", "Kayleigh"),
    ("museum", "Dr Shah, one of our curators, walks from the entrance to the main hall.", "Dr Shah"),
    ("swimming_baths", "Callum, one of the lifeguards, leaves the crew room for the lifeguard chair.", "Callum"),
    ("hospital", "Priya, one of the nurses, waits at the nurse station.", "Priya"),
    ("library", "Mrs Okafor, one of the librarians, walks to the front desk.", "Mrs Okafor"),
])
def test_a_name_with_its_group_in_apposition_is_one_person(read, world, prompt, who):
    (group,) = read(world, prompt).groups
    assert group.who == who and group.count.value == 1


@pytest.mark.parametrize("world,prompt,whole,part", [
    ("dental_clinic", "Of the nine sat in the waiting room, a pair get up and pay at reception.", 9, 2),
    ("mall", "Of the ten in the food court, three walk to the fountain.", 10, 3),
    ("mall", "Out of the twenty queuing at the coffee counter, a couple give up and walk to the fountain.", 20, 2),
    ("youth_hostel", "Of the twelve hikers in the common room, a pair sneak off to the hobs.", 12, 2),
    ("hospital", "Of the eight waiting in the lobby, a couple walk to the cafeteria.", 8, 2),
])
def test_a_fronted_whole_and_its_part_said_as_a_pair(read, world, prompt, whole, part):
    groups = read(world, prompt).groups
    assert [g.count.value for g in groups] == [whole, part]
    assert groups[1].relation == "subset_of:0"


@pytest.mark.parametrize("world,prompt", [
    ("care_home", "After tea a carer pushes Alastair's wheelchair from the dining room to the lounge."),
    ("office", "A colleague pushes Priya's wheelchair from the kitchen to the meeting room."),
    ("museum", "A volunteer pushes Margaret's wheelchair from the entrance to the main hall."),
    ("mall", "A dad pushes Oliver's buggy from the food court to the fountain."),
])
def test_a_named_persons_wheelchair_takes_them_along(read, world, prompt):
    groups = read(world, prompt).groups
    assert [g.count.value for g in groups] == [1, 1]
    assert groups[1].intent == "follow" and groups[1].follows == groups[0].who


@pytest.mark.parametrize("world,prompt,taken", [
    ("care_home", "A visiting son takes Doris Baxter arm in arm out of the lounge into the garden.", "Doris"),
    ("mall", "A guard walks Edith arm in arm from the food court to the fountain.", "Edith"),
    ("mall", "A guard takes Edith by the hand from the food court to the fountain.", "Edith"),
    ("hospital", "A nurse leads Arthur by the hand from the ward to the cafeteria.", "Arthur"),
])
def test_a_person_held_arm_in_arm_is_still_taken_along(read, world, prompt, taken):
    groups = read(world, prompt).groups
    assert len(groups) == 2 and groups[1].who.startswith(taken) and groups[1].intent == "follow"
    assert groups[0].destination and groups[0].start


@pytest.mark.parametrize("world,prompt,who", [
    ("dental_clinic", "Jo from reception dashes into the practice office.", "Jo"),
    ("mall", "Sam from security walks to the fountain.", "Sam"),
    ("office", "Kim from security walks to the kitchen.", "Kim"),
    ("hotel", "Mo from security walks to the lobby.", "Mo"),
    ("mall", "Jo walks to the fountain.", "Jo"),
])
def test_a_name_with_its_workplace_is_one_person(read, world, prompt, who):
    (group,) = read(world, prompt).groups
    assert group.who == who and group.count.kind == "exact" and group.count.value == 1 and group.destination


@pytest.mark.parametrize("world,prompt", [
    ("dental_clinic", "A trainee takes a handful of used mirrors to the staff room."),
    ("mall", "A guard takes a handful of leaflets to the fountain."),
    ("hospital", "A porter takes a few clean sheets to the ward."),
    ("mall", "A cleaner takes a few used cups to the food court."),
    ("museum", "A guide takes a few spare maps to the main hall."),
])
def test_counted_things_carried_are_no_group(read, world, prompt):
    (group,) = read(world, prompt).groups
    assert group.count.value == 1 and group.destination


@pytest.mark.parametrize("world,prompt,value", [
    ("mall", "Ten mums with babies in slings wait by the fountain.", 10),
    ("hospital", "A woman with a baby in a sling waits in the lobby.", 1),
    ("airport", "Two dads with toddlers on their shoulders walk to gate A2.", 2),
    ("mall", "Five dads with toddlers in pushchairs queue at the coffee counter.", 5),
    ("museum", "A young mum with a newborn in her arms walks from the entrance to the main hall.", 1),
])
def test_little_ones_carried_are_no_group_of_their_own(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert group.count.value == value


@pytest.mark.parametrize("world,prompt,counts", [
    ("mall", "The crowd, 150 strong, walk to the fountain.", [(150, "exact")]),
    ("mall", "Meanwhile, one of the guards walks to the fountain.", [(1, "exact")]),
    ("mall", "Of the nine shoppers in the food court, five walk to the fountain.", [(9, "exact"), (5, "exact")]),
    ("mall", "Of the nine shoppers in the food court, a handful walk to the fountain.", [(9, "exact"), (4, "vague")]),
    ("mall", "Two friends walk arm in arm to the fountain.", [(2, "exact")]),
    ("mall", "A guard leads Mr Dobbs arm in arm from the food court to the fountain.", [(1, "exact"), (1, "exact")]),
    ("hospital", "A porter pushes Mrs Khan's wheelchair from the ward to the x-ray room.", [(1, "exact"), (1, "exact")]),
    ("mall", "A guard pushes Boots's trolley from the food court to the fountain.", [(1, "exact")]),
    ("mall", "Tom walks from the food court to the fountain.", [(1, "exact")]),
    ("mall", "A guard takes a handful of children to the fountain.", [(1, "exact"), (3, "vague")]),
    ("mall", "A guard takes two children to the fountain.", [(1, "exact"), (2, "exact")]),
    ("hospital", "A mum with two toddlers walks to the cafeteria.", [(1, "exact"), (2, "exact")]),
])
def test_guards_keep_their_reading(read, world, prompt, counts):
    assert [(g.count.value, g.count.kind) for g in read(world, prompt).groups] == counts


@pytest.mark.parametrize("world,prompt,start", [
    ("mall", "Tom walks from the food court to the fountain.", "food_court"),
    ("mall", "Anna from the cafe walks to the fountain.", "coffee_counter"),
    ("museum", "Lucy from the shop walks to the main hall.", "gift_shop"),
    ("hospital", "Marek from the pharmacy hurries to the nurse station.", "pharmacy"),
])
def test_a_workplace_the_world_has_stays_the_start(read, world, prompt, start):
    (group,) = read(world, prompt).groups
    assert group.count.value == 1 and group.start == start and group.destination
