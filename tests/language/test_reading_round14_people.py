"""Round 14 of the reader's people: roles said short ("the GP", "a PCSO", "the vet"), family members
said by their order ("our youngest", "the eldest", "the little one"), counted compounds of several
nouns ("a pair of revenue protection officers"), a school class with a count in apposition, "class"
naming the kind of a person ("spin class regulars"), and a titled name wheeled or pushed by a carer,
with "her room" the room the world names after her."""

import pytest


@pytest.mark.parametrize("world,prompt,label", [
    ("hospital", "The HCA walks from the ward to the pharmacy.", "hca"),
    ("care_home", "The GP heads from reception to the lounge.", "gp"),
    ("primary_school", "The TA walks from the hall to the school office.", "ta"),
    ("station", "A PCSO waits by the ticket office.", "pcso"),
    ("hospital", "The vet heads to the cafeteria.", "vet"),
])
def test_a_role_said_short_is_one_person(read, world, prompt, label):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert (groups[0].label, groups[0].count.kind, groups[0].count.value) == (label, "exact", 1)


@pytest.mark.parametrize("world,prompt", [
    ("museum", "Our youngest is scared of the robot and backs away."),
    ("residential", "The eldest walks to the kitchen."),
    ("mall", "Their little one toddles to the food court."),
    ("care_home", "Her middle one walks to the lounge."),
])
def test_a_family_member_said_by_order_is_one_person(read, world, prompt):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert (groups[0].count.kind, groups[0].count.value) == ("exact", 1)


@pytest.mark.parametrize("world,prompt,n,label", [
    ("station", "Two revenue protection officers walk to the ticket office.", 2, "officer"),
    ("mall", "A couple of car park attendants walk to the food court.", 2, "attendant"),
    ("bus_station", "A pair of ticket office staff walk to the cafe.", 2, "staff"),
])
def test_a_counted_compound_role_keeps_its_count(read, world, prompt, n, label):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert (groups[0].label, groups[0].count.value, groups[0].count.kind) == (label, n, "exact")


@pytest.mark.parametrize("world,prompt,n,start", [
    ("primary_school", "Year 3, 26 children, walk from their classroom to the hall.", 26, "year_3_classroom"),
    ("primary_school", "Year 6, twenty pupils, troop from their classroom to the playground.", 20, "year_6_classroom"),
    ("primary_school", "Year 1, 22 pupils, file out of their classroom to the library.", 22, "year_1_classroom"),
])
def test_a_school_class_with_a_count_is_one_group_from_its_room(read, world, prompt, n, start):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    g = groups[0]
    assert (g.count.value, g.count.kind, g.start, g.intent) == (n, "exact", start, "walk")


@pytest.mark.parametrize("world,prompt,n", [
    ("sports_centre", "Six spin class regulars walk from the cafe to the changing rooms.", 6),
    ("library", "Five craft class regulars head to the cafe.", 5),
])
def test_class_naming_a_kind_of_person_is_no_school_class(read, world, prompt, n):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert (groups[0].label, groups[0].count.value, groups[0].count.kind) == ("regular", n, "exact")


@pytest.mark.parametrize("prompt,room,place", [
    ("A carer pushes Mr Kowalski from his room to the lounge.", "room_2", "lounge"),
    ("A nurse wheels Mrs Baxter from her room to the dining room.", "room_1", "dining_room"),
])
def test_a_titled_resident_pushed_is_a_group_from_their_named_room(read, prompt, room, place):
    carer, resident = read("care_home", prompt).groups
    assert resident.count.value == 1 and resident.intent == "follow"
    assert carer.start == resident.start == room
    assert carer.destination == resident.destination == place


def test_her_room_of_a_staff_member_stays_theirs(read):
    g, = read("care_home", "A carer walks from her room to the lounge.").groups
    assert g.start != "room_3"


@pytest.mark.parametrize("world,prompt,label", [
    ("care_home", "Mrs Adeyemi's son walks from reception to the lounge.", "son"),
    ("hospital", "Dr Khan's registrar walks to the pharmacy.", "registrar"),
    ("care_home", "Mr Kowalski's elderly sister waits in the lounge.", "sister"),
    ("museum", "The guide's elderly mother waits in the cafe.", "mother"),
])
def test_a_person_owned_by_a_person_is_the_group_not_the_owner(read, world, prompt, label):
    groups = read(world, prompt).groups
    assert [(g.label, g.count.value) for g in groups] == [(label, 1)]


@pytest.mark.parametrize("world,prompt,label", [
    ("bus_station", "The driver's eldest waits by the cafe.", "eldest"),
    ("hotel", "The groom's youngest runs to the lobby.", "youngest"),
])
def test_a_family_member_of_someone_is_one_person(read, world, prompt, label):
    groups = read(world, prompt).groups
    assert [(g.label, g.count.value) for g in groups] == [(label, 1)]


@pytest.mark.parametrize("world,prompt,label,n", [
    ("primary_school", "Two TAs walk from the hall to the staff room.", "ta", 2),
    ("care_home", "Father O'Neill walks from reception to the lounge.", "priest", 1),
    ("hospital", "A trio of junior doctors walk to the cafeteria.", "doctor", 3),
])
def test_short_plural_roles_companions_and_apostrophe_names(read, world, prompt, label, n):
    groups = read(world, prompt).groups
    assert [(g.label, g.count.value) for g in groups] == [(label, n)]


def test_a_companion_by_a_short_role_is_a_group_of_its_own(read):
    groups = read("office", "The CEO and her PA walk to the boardroom.").groups
    assert [(g.label, g.count.value, g.destination) for g in groups] == [("ceo", 1, "boardroom"), ("pa", 1, "boardroom")]


@pytest.mark.parametrize("world,prompt,n", [
    ("bus_station", "The older two run ahead to the cafe.", 2),
    ("museum", "The youngest three wait by the gift shop.", 3),
    ("care_home", "The Reverend walks from reception to the lounge.", 1),
    ("bus_station", "Our eldest tugs at his mum's coat and points at the robot.", 1),
])
def test_children_said_by_their_order_and_a_number(read, world, prompt, n):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert (groups[0].count.kind, groups[0].count.value) == ("exact", n)


@pytest.mark.parametrize("world,prompt,n,place", [
    ("primary_school", "Year 4, 27 children, and their teacher walk to the hall.", 27, "school_hall"),
    ("museum", "The school party, 30 pupils, and three teachers walk to the cafe.", 30, "cafe"),
])
def test_a_group_with_its_count_in_apposition_shares_the_verb_after_and(read, world, prompt, n, place):
    first, second = read(world, prompt).groups
    assert first.count.value == n
    assert first.intent == second.intent == "walk" and first.destination == second.destination == place


@pytest.mark.parametrize("world,prompt,place", [
    ("care_home", "A carer walks Mr Kowalski and Mrs Okafor to the lounge.", "lounge"),
    ("museum", "A guide leads three tourists and a child to the gift shop.", "gift_shop"),
])
def test_people_taken_along_joined_by_and_all_follow(read, world, prompt, place):
    leader, *led = read(world, prompt).groups
    assert len(led) == 2 and leader.destination == place and leader.intent == "walk"
    assert all(g.intent == "follow" and g.destination == place for g in led)


@pytest.mark.parametrize("world,prompt,label", [
    ("warehouse", "The AGV drives to the loading bay while two pickers walk to the canteen.", "picker"),
    ("warehouse", "An HGV reverses into bay 2 and a driver walks to the office.", "driver"),
    ("station", "The PA announces a delay and ten commuters walk to the exit.", "commuter"),
])
def test_a_capital_word_that_drives_or_announces_is_a_machine(read, world, prompt, label):
    groups = read(world, prompt).groups
    assert [g.label for g in groups] == [label]
