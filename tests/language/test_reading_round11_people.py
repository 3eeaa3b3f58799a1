"""Round 11 of people reading: people no list names (a word the world uses only to say whose a place
is, "two postgrads", "four gents"; a noun an adjective only people take makes a person's, "a nervous
postgrad", "its worried owner"). Sentences written for these tests, over shipped and
understanding-set worlds."""

import pytest


@pytest.mark.parametrize("world, prompt, label, count", [
    ("university", "Two postgrads walk from the common room to the seminar room.", "postgrad", 2),
    ("university", "A nervous postgrad leaves the robotics lab.", "postgrad", 1),
    ("sports_centre", "Four gents walk from the reception to the gym.", "gent", 4),
    ("hotel", "Its worried owner waits at the front desk.", "owner", 1),
    ("university", "Its worried owner waits at the porters lodge.", "owner", 1),
    ("library", "Her anxious owner waits at the help desk.", "owner", 1),
])
def test_people_no_list_names(read, world, prompt, label, count):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert groups[0].label == label
    assert groups[0].count.kind == "exact" and groups[0].count.value == count


@pytest.mark.parametrize("world, prompt, label", [
    ("university", "The examiners leave the exam hall.", "examiner"),
    ("university", "The congregants leave the lecture theatre.", "congregant"),
    ("university", "The witnesses leave the common room.", "witness"),
    ("library", "The parishioners leave the reading room.", "parishioner"),
    ("hotel", "The jurors leave the bar.", "juror"),
])
def test_roles_of_courts_churches_and_schools_are_people(read, world, prompt, label):
    assert [g.label for g in read(world, prompt).groups] == [label]


@pytest.mark.parametrize("world, prompt, label, count", [
    ("hotel", "A family with a pushchair hurries to the exit.", "family", 4),
    ("hotel", "A couple with a buggy hurries to the lifts.", "couple", 2),
    ("library", "A mum with a pram hurries to the cafe.", "mum", 1),
    ("sports_centre", "A dad with a buggy hurries to the cafe.", "dad", 1),
    ("office", "A man with a trolley hurries to the lifts.", "man", 1),
])
def test_what_people_push_along_is_not_a_person(read, world, prompt, label, count):
    groups = read(world, prompt).groups
    assert [g.label for g in groups] == [label] and groups[0].count.value == count


@pytest.mark.parametrize("world, prompt, label, count, location", [
    ("office", "The robot delivers coffee from the kitchen to the boardroom, where five managers are in a meeting.",
     "manager", 5, "boardroom"),
    ("office", "A cleaner goes to the kitchen, where two interns are chatting.", "intern", 2, "kitchen"),
    ("hotel", "The robot delivers towels from the laundry to the spa, where four guests are waiting.", "guest", 4, "spa"),
    ("hotel", "The robot takes a tray from the kitchen to the bar, where three guests are having drinks.",
     "guest", 3, "bar"),
    ("library", "The robot carries books from the returns desk to the reading room, where six students are studying.",
     "student", 6, "reading_room"),
])
def test_people_in_a_where_clause_after_a_place_are_there(read, world, prompt, label, count, location):
    reading = read(world, prompt)
    group = reading.groups[-1]
    assert (group.label, group.count.value, group.location) == (label, count, location)
    if reading.robot is not None:
        assert reading.robot.destination == location


@pytest.mark.parametrize("world, prompt, label, count", [
    ("hotel", "At 7 sharp a dozen waiters stream in through the staff entrance and head for the kitchen, "
              "while two cleaners finish up in the bar.", "waiter", 12),
    ("hotel", "By 6.30 three porters wait in the lobby.", "porter", 3),
    ("library", "At 9 sharp a dozen students walk in through the main entrance.", "student", 12),
    ("sports_centre", "Around 7.15 four lifeguards walk to the pool.", "lifeguard", 4),
    ("university", "At 10 exactly two porters wait at the main entrance.", "porter", 2),
])
def test_a_subject_after_a_clock_time_with_no_comma(read, world, prompt, label, count):
    group = read(world, prompt).groups[0]
    assert (group.label, group.count.kind, group.count.value) == (label, "exact", count)


@pytest.mark.parametrize("world, prompt, whole, part", [
    ("hotel", "Of the 30 guests leaving the ballroom, a handful stop at the bar.", 30, "bar"),
    ("hotel", "Of the 30 guests in the ballroom, four stop at the bar.", 30, "bar"),
    ("library", "Of the 20 students in the reading room, three stop at the issue desk.", 20, "issue_desk"),
    ("sports_centre", "Of the 12 swimmers leaving the pool, a few stop at the cafe.", 12, "cafe"),
    ("university", "Of the 50 students leaving the lecture theatre, six stop at the coffee bar.", 50, "coffee_bar"),
])
def test_a_part_of_a_fronted_whole_that_stops_somewhere(read, world, prompt, whole, part):
    groups = read(world, prompt).groups
    assert len(groups) == 2 and groups[0].count.value == whole
    assert groups[1].relation == "subset_of:0" and groups[1].location == part and groups[1].intent == "wait"


@pytest.mark.parametrize("world, prompt, location", [
    ("hotel", "Two receptionists hand out boarding passes at the front desk.", "reception_desk"),
    ("sports_centre", "Two staff check swimming passes at reception.", "reception_desk"),
    ("university", "Two porters check parking permits at the main entrance.", "main_entrance"),
    ("office", "Two guards check visitor passes at the reception desk.", "reception_desk"),
    ("airport", "Two agents check boarding passes at gate A1.", "gate_a1"),
    ("airport", "When boarding is called, twenty passengers leave the lounge for gate A1 and two agents check "
                "boarding passes at gate A1.", "gate_a1"),
])
def test_a_job_at_a_post_whose_object_sounds_like_going(read, world, prompt, location):
    group = read(world, prompt).groups[-1]
    assert (group.intent, group.location) == ("wait", location)


@pytest.mark.parametrize("world, prompt, leader", [
    ("hotel", "Fire alarm: everyone in the bar evacuates, staff guide guests out.", "evacuate"),
    ("library", "The fire alarm goes off and two librarians usher the readers out.", "evacuate"),
    ("sports_centre", "Fire drill: the lifeguards lead the swimmers out.", "evacuate"),
    ("hotel", "A porter leads the children outside.", "walk"),
    ("university", "Two porters guide the students out.", "walk"),
])
def test_people_who_take_others_out_go_and_the_others_follow(read, world, prompt, leader):
    *_, leaders, led = read(world, prompt).groups
    assert (leaders.intent, led.intent) == (leader, "follow")


@pytest.mark.parametrize("world, prompt, zones", [
    ("hotel", "Everyone in the bar and the restaurant evacuates.", ["bar", "restaurant"]),
    ("hotel", "Fire alarm: everyone in the bar and the restaurant evacuates, staff guide guests out.",
     ["bar", "restaurant"]),
    ("library", "Everyone in the reading room and the cafe leaves.", ["reading_room", "cafe"]),
    ("sports_centre", "The fire alarm sounds and everyone in the gym and the cafe evacuates.", ["gym", "cafe"]),
    ("university", "Everyone in the library and the common room evacuates.", None),
])
def test_everyone_in_two_rooms_is_everyone_in_each(read, world, prompt, zones):
    groups = [g for g in read(world, prompt).groups if g.count.kind == "whole_zone"]
    assert len(groups) == 2 and groups[0].start != groups[1].start
    if zones is not None:
        assert [g.start for g in groups] == zones


@pytest.mark.parametrize("world, prompt, location", [
    ("library", "Overnight the robot does its rounds of the reading room.", "reading_room"),
    ("hotel", "At night the robot goes on its rounds of the lobby.", "lobby"),
    ("hotel", "The robot is doing its rounds in the bar.", "bar"),
    ("library", "The robot makes its rounds of the cafe while two students wait at the help desk.", "cafe"),
    ("sports_centre", "Late at night the robot patrols the gym.", "gym"),
])
def test_rounds_are_a_patrol_and_a_fronted_time_keeps_the_robot(read, world, prompt, location):
    robot = read(world, prompt).robot
    assert robot is not None and (robot.task, robot.location) == ("patrol", location)


@pytest.mark.parametrize("world, prompt, label", [
    ("library", "The only other person in the building is a guard at the help desk.", "guard"),
    ("hotel", "The robot patrols the bar; the only other person in the hotel is a porter at the front desk.", "porter"),
    ("sports_centre", "The only other person in the centre is a lifeguard by the pool.", "lifeguard"),
    ("university", "The only other people in the library are two students.", "student"),
    ("office", "The only other person in the office is a cleaner in the kitchen.", "cleaner"),
])
def test_the_only_other_person_is_the_one_named_after(read, world, prompt, label):
    # "the only other person" is one more person, not a statement about everyone (decided 2026-11-29)
    groups = read(world, prompt).groups
    assert [g.label for g in groups] == [label] and groups[0].count.kind == "exact"


@pytest.mark.parametrize("world, prompt, led", [
    ("hotel", "Two guards escort a handcuffed smuggler from the lobby to the exit.", "smuggler"),
    ("library", "A librarian escorts a tearful truant to the help desk.", "truant"),
    ("hotel", "Two officers escort a handcuffed poacher from the lobby to the exit.", "poacher"),
    ("sports_centre", "Two stewards escort a drunken streaker from the sports hall to reception.", "streaker"),
    ("university", "Two porters escort a dishevelled gatecrasher from the bar to the main entrance.", "gatecrasher"),
])
def test_someone_escorted_with_an_adjective_is_a_group(read, world, prompt, led):
    groups = read(world, prompt).groups
    assert len(groups) == 2 and groups[1].label == led and groups[1].intent == "follow"
