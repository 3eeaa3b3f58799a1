"""Round 10 of the reader on people, counts and clauses: sentences written for it over shipped and
extra worlds, each a class of phrasing (a second task after the first, ...)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, label, count, destination", [
    ("station", "the robot waits on platform 1, then leads passengers to the exit", "passenger", None, None),
    ("station", "The robot waits on platform 1 and then guides 5 passengers to the main entrance", "passenger", 5,
     "main_entrance"),
    ("station", "The robot patrols the concourse, then escorts an elderly man to platform 2", "man", 1, "platform_2"),
    ("hotel", "The robot waits in the lobby and later takes two guests to the lift lobby", "guest", 2, "lift_lobby"),
])
def test_people_the_robot_takes_along_in_its_second_task(read, world, prompt, label, count, destination):
    r = read(world, prompt)
    assert r.robot is not None
    assert [g.label for g in r.groups] == [label]
    g = r.groups[0]
    assert g.robot_interaction == "follow"
    assert count is None or g.count.value == count
    assert destination is None or g.destination == destination


def test_people_a_person_takes_along_in_a_second_task(read):
    r = read("university", "A porter waits in the entrance foyer, then leads 4 visitors to the canteen")
    assert [(g.label, g.count.value) for g in r.groups] == [("porter", 1), ("visitor", 4)]
    assert r.groups[1].destination == "canteen"


def test_a_leading_verb_after_then_names_nobody(read):
    r = read("library", "The robot waits in the foyer and then guides 3 students to the reading room")
    assert [g.label for g in r.groups] == ["student"]
    assert [g.label for g in read("library", "Two guides wait in the entrance foyer").groups] == ["guide"]


@pytest.mark.parametrize("world, prompt, whole, part", [
    ("library", "50 students study in the reading room, 20% of them go to the cafe", 50, 10),
    ("library", "50 students study in the reading room; 10 percent of them walk to the toilets", 50, 5),
    ("library", "30% of the 50 visitors in the foyer walk to the stacks", 50, 15),
    ("hospital", "There are 40 patients in the main waiting room. 25 per cent of them queue at the pharmacy.", 40, 10),
])
def test_a_percentage_of_a_group_is_its_share(read, world, prompt, whole, part):
    r = read(world, prompt)
    assert [g.count.value for g in r.groups] == [whole, part]
    assert r.groups[0].label == r.groups[1].label
    assert r.groups[1].relation == "subset_of:0"


@pytest.mark.parametrize("world, prompt, whole, part, destination", [
    ("sports_centre", "Of the 40 people in the sports hall, half walk to the cafe", 40, 20, "cafe"),
    ("sports_centre", "Of the 30 swimmers in the pool hall, two thirds leave for the cafe", 30, 20, "cafe"),
    ("sports_centre", "Of the 20 players in the sports hall, 25% go to the cafe", 20, 5, "cafe"),
    ("station", "40 passengers wait on platform 1; half go to the cafe and the rest go to the waiting room", 40, 20,
     "cafe"),
    ("university", "Twenty students arrive in the foyer; a quarter head to the canteen", 20, 5, "canteen"),
])
def test_a_share_said_alone_is_part_of_the_group_before(read, world, prompt, whole, part, destination):
    r = read(world, prompt)
    assert [g.count.value for g in r.groups][:2] == [whole, part]
    assert r.groups[1].label == r.groups[0].label
    assert r.groups[1].relation == "subset_of:0"
    assert r.groups[1].destination == destination


def test_half_an_hour_is_no_share(read):
    r = read("sports_centre", "Half an hour later, ten people walk to the gym")
    assert [(g.count.value, g.destination) for g in r.groups] == [(10, "gym")]


@pytest.mark.parametrize("world, prompt, count, places", [
    ("station", "two guards stand at each exit", 2,
     {"main_entrance", "south_entrance", "platform_1_exit", "platform_2_exit"}),
    ("station", "place one cleaner on each platform", 1, {"platform_1", "platform_2"}),
    ("university", "two students wait in each of the seminar rooms", 2, {"seminar_room_1", "seminar_room_2"}),
    ("university", "one technician in every lab", 1, {"computer_lab", "chemistry_lab", "robotics_lab"}),
    ("airport", "Spawn 5 passengers at each gate", 5, {"gate_a1", "gate_a2", "gate_b1", "gate_b2"}),
])
def test_people_at_each_place_of_a_kind_are_a_group_at_every_one(read, world, prompt, count, places):
    r = read(world, prompt)
    assert len(r.groups) == len(places)
    assert {g.location for g in r.groups} == places
    assert {g.count.value for g in r.groups} == {count}


def test_each_place_keeps_the_other_groups_and_their_relations(read):
    r = read("station", "three passengers wait on every platform, while a guard patrols the concourse")
    assert [(g.label, g.location) for g in r.groups] == [("passenger", "platform_1"), ("passenger", "platform_2"),
                                                         ("guard", "concourse")]


def test_every_table_in_one_room_stays_in_that_room(read):
    r = read("hotel", "a couple sits at every table in the restaurant")
    assert [g.location for g in r.groups] == ["restaurant_tables"]


@pytest.mark.parametrize("world, prompt, via", [
    ("university", "The main corridor is crossed by ten cleaners", "main_corridor"),
    ("hotel", "The lobby is crossed by six guests heading to the lifts", "lobby"),
    ("hotel", "The guest corridor is traversed by two cleaners", "guest_corridor"),
])
def test_a_place_crossed_in_the_passive_is_a_way_through(read, world, prompt, via):
    g = read(world, prompt).groups[0]
    assert g.intent == "walk" and via in g.via and g.destination != via


@pytest.mark.parametrize("world, prompt, location", [
    ("library", "Generate 25 students scattered across the reading room", "reading_room"),
    ("library", "30 students are spread out across the reading room", "reading_room"),
    ("station", "40 commuters spread along platform 1", "platform_1"),
    ("university", "Twelve students dotted around the canteen", "canteen"),
])
def test_people_scattered_across_a_place_stay_in_it(read, world, prompt, location):
    g = read(world, prompt).groups[0]
    assert (g.intent, g.location, g.via) == ("wait", location, ())


@pytest.mark.parametrize("world, prompt, places", [
    ("hospital", "Ten nurses: four on ward A, six on ward B", ["ward_a", "ward_b"]),
    ("hospital", "Place 5 guards, two at the main entrance and three at the pharmacy", ["main_entrance", "pharmacy"]),
    ("library", "Add 3 librarians: one at the issue desk, two in the sorting room", ["issue_desk", "sorting_room"]),
])
def test_a_whole_split_by_counts_that_add_up_keeps_its_people(read, world, prompt, places):
    from grove_tui.language.model import effective_counts

    r = read(world, prompt)
    assert [g.relation for g in r.groups[1:]] == ["subset_of:0"] * len(places)
    assert [g.location for g in r.groups[1:]] == places
    assert sum(effective_counts(r).values()) == r.groups[0].count.value


def test_a_whole_with_its_own_place_is_no_split(read):
    r = read("hospital", "Ten nurses walk to ward A, four walk to ward B and six go to ward C")
    assert [g.relation for g in r.groups] == [None, None, None]


@pytest.mark.parametrize("world, prompt, task, start, destination", [
    ("station", "the robot waits on platform 1, then leads passengers to the exit", "cross", "platform_1", None),
    ("station", "The robot patrols the concourse, then escorts an elderly man to platform 2", "cross", "concourse",
     "platform_2"),
    ("university", "The robot waits in the foyer, then follows two students to the canteen", "follow",
     "entrance_foyer", "canteen"),
    ("hotel", "The robot delivers towels to the spa and then guides three guests to the bar", "cross", "spa", "bar"),
])
def test_the_robots_second_task_with_people_is_its_task(read, world, prompt, task, start, destination):
    robot = read(world, prompt).robot
    assert robot is not None
    assert (robot.task, robot.start) == (task, start)
    assert destination is None or robot.destination == destination


def test_the_robot_following_in_its_second_task_follows_them(read):
    robot = read("university", "The robot goes to the post room, then follows a professor to the canteen").robot
    assert robot is not None and robot.task == "follow" and robot.follows == "a professor"


def test_half_the_n_people_without_of_is_half_of_them(read):
    r = read("university", "Half the 60 students in lecture theatre 1 go to the canteen")
    assert [(g.label, g.count.value, g.relation) for g in r.groups] == [("student", 60, None),
                                                                        ("student", 30, "subset_of:0")]
    assert r.groups[0].location == "lecture_theatre_1" and r.groups[1].destination == "canteen"


def test_most_of_a_counted_group_leaves_the_rest(read):
    r = read("university", "Most of the 20 students in the study area stay, the rest go to the canteen")
    assert [g.count.value for g in r.groups] == [20, 15, 5]
    assert r.groups[1].relation == "subset_of:0" and r.groups[2].destination == "canteen"


@pytest.mark.parametrize("world, prompt, count, start, destination", [
    ("airport", "12 agents: gate A1 -> security", 12, "gate_a1", "security_checkpoint"),
    ("station", "Spawn 10 ppl (ticket hall -> platform 2)", 10, "ticket_hall", "platform_2"),
    ("station", "10 people: platform 1 → main entrance", 10, "platform_1", "main_entrance"),
    ("airport", "12 agents -> security", 12, None, "security_checkpoint"),
])
def test_a_route_written_with_an_arrow(read, world, prompt, count, start, destination):
    g = read(world, prompt).groups[0]
    assert (g.count.value, g.intent, g.start, g.destination) == (count, "walk", start, destination)


@pytest.mark.parametrize("world, prompt, label, count, intent, location", [
    ("airport", "n=20 pedestrians in the concourse, random walk", "person", 20, "wander", "concourse"),
    ("airport", "10 people walk randomly in the concourse", "person", 10, "wander", "concourse"),
    ("hotel", "8 guests moving aimlessly around the lobby", "guest", 8, "wander", "lobby"),
    ("airport", "Inject 6 tourists at the arrivals hall", "tourist", 6, "wait", "arrivals_hall"),
    ("library", "Deploy 4 peds in the lending hall", "person", 4, "wait", "lending_hall"),
])
def test_researchers_shorthand_for_counts_people_and_random_walks(read, world, prompt, label, count, intent, location):
    g = read(world, prompt).groups[0]
    assert (g.label, g.count.value, g.intent, g.location) == (label, count, intent, location)


def test_people_from_each_place_set_off_from_every_one(read):
    r = read("airport", "Spawn 3 passengers at every gate walking to the concourse")
    assert {g.start for g in r.groups} == {"gate_a1", "gate_a2", "gate_b1", "gate_b2"}
    assert {g.destination for g in r.groups} == {"concourse"}


@pytest.mark.parametrize("world, prompt, start", [
    ("station", "Anyone waiting on platform 1 moves to platform 2", "platform_1"),
    ("station", "Those who are waiting in the waiting room walk to platform 1", "waiting_room"),
    ("station", "Whoever is in the cafe leaves", "cafe"),
    ("university", "Each student in the study area walks to the canteen", "study_area"),
])
def test_anyone_whoever_and_those_who_are_everyone_there(read, world, prompt, start):
    g = read(world, prompt).groups[0]
    assert g.count.kind == "whole_zone" and g.start == start


@pytest.mark.parametrize("world, prompt, groups", [
    ("mall", "A mother with her two kids walks to the toy store", [("mother", 1), ("kid", 2)]),
    ("mall", "An old man with his daughter walks slowly to the pharmacy", [("man", 1), ("daughter", 1)]),
    ("mall", "Two dads with their kids queue at the toy store", [("dad", 2), ("kid", None)]),
])
def test_one_persons_companions_are_people_of_their_own_doing_the_same(read, world, prompt, groups):
    r = read(world, prompt)
    assert [(g.label, g.count.value if n is not None else None) for g, (_, n) in zip(r.groups, groups)] == groups
    assert len({(g.intent, g.destination, g.location) for g in r.groups}) == 1


def test_a_familys_own_children_are_no_group_of_their_own(read):
    assert [g.label for g in read("mall", "Families wait at the cinema lobby with their children").groups] == ["family"]


def test_people_touring_a_gallery_wander_it(read):
    g = read("museum", "A school group of 25 pupils tours the dinosaur gallery").groups[0]
    assert (g.intent, g.location) == ("wander", "dinosaur_gallery")


def test_a_whole_said_with_no_number_is_as_many_as_its_parts(read):
    from grove_tui.language.model import effective_counts

    r = read("mall", "Shoppers: 20 in the food court, 10 in the supermarket")
    assert r.groups[0].count.value == 30
    assert [g.relation for g in r.groups[1:]] == ["subset_of:0", "subset_of:0"]
    assert sum(effective_counts(r).values()) == 30


@pytest.mark.parametrize("world, prompt, leaders, taken, destination", [
    ("museum", "Three guides, each with a group of ten visitors, walk to the great hall", ("guide", 3),
     ("visitor", 30), "great_hall"),
    ("museum", "Two teachers, each leading 15 pupils, enter the dinosaur gallery", ("teacher", 2), ("pupil", 30),
     "dinosaur_gallery"),
    ("hospital", "Two porters, each pushing a patient in a wheelchair, go to radiology", ("porter", 2),
     ("patient", 2), "radiology"),
    ("hospital", "Four nurses each escort a patient to ward B", ("nurse", 4), ("patient", 4), "ward_b"),
])
def test_people_each_of_a_group_takes_along(read, world, prompt, leaders, taken, destination):
    r = read(world, prompt)
    assert [(g.label, g.count.value) for g in r.groups] == [leaders, taken]
    assert [g.destination for g in r.groups] == [destination, destination]
    assert r.groups[0].intent == "walk"


@pytest.mark.parametrize("world, prompt, location, destination", [
    ("office", "Four developers chat in the kitchen. Then they go to the boardroom.", "kitchen", "boardroom"),
    ("office", "Four developers chat in the kitchen. Ten minutes later, they go to the boardroom.", "kitchen",
     "boardroom"),
    ("library", "Six students study in the reading room. After that, they walk to the cafe.", "reading_room", "cafe"),
    ("office", "A manager waits in her office. A few minutes later she walks to reception.", "manager_office",
     "reception"),
])
def test_a_next_sentence_about_them_goes_on_with_the_same_people(read, world, prompt, location, destination):
    r = read(world, prompt)
    assert len(r.groups) == 1
    assert location in (r.groups[0].location, r.groups[0].start) and r.groups[0].destination == destination


def test_a_next_sentence_about_new_people_is_theirs(read):
    r = read("office", "Four developers chat in the kitchen. They are tired. Two managers wait in the boardroom.")
    assert [(g.label, g.location, g.destination) for g in r.groups] == [("developer", "kitchen", None),
                                                                        ("manager", "boardroom", None)]


def test_an_imperatives_people_share_the_verb_said_after_them_all(read):
    r = read("airport", "Spawn 8 passengers at gate B1 and 8 at gate B2, all walking to baggage claim")
    assert [(g.count.value, g.intent, g.start, g.destination) for g in r.groups] == [
        (8, "walk", "gate_b1", "baggage_claim"), (8, "walk", "gate_b2", "baggage_claim")]


@pytest.mark.parametrize("prompt, count", [("15+ guests wait in the lobby", 15), ("20+ ppl in the bar", 20)])
def test_a_count_with_a_plus_is_at_least_that_many(read, prompt, count):
    g = read("hotel", prompt).groups[0]
    assert g.count.value >= count and g.label in ("guest", "person")


def test_a_plus_between_two_groups_still_joins_them(read):
    r = read("hotel", "2 porters + 1 manager walk to the lobby")
    assert [(g.label, g.count.value) for g in r.groups] == [("porter", 2), ("manager", 1)]


@pytest.mark.parametrize("world, prompt, places, destination", [
    ("office", "4 people wait in the kitchen and 2 in meeting room 1; then they all walk to reception.",
     ["kitchen", "meeting_room_1"], "reception"),
    ("office", "4 people wait in the kitchen and 2 in meeting room 1. Then they all walk to reception.",
     ["kitchen", "meeting_room_1"], "reception"),
    ("library", "Five students wait in the foyer and three in the cafe; they all then go to the reading room",
     ["entrance_foyer", "cafe"], "reading_room"),
])
def test_they_all_take_every_group_of_the_sentence_along(read, world, prompt, places, destination):
    r = read(world, prompt)
    assert [g.location or g.start for g in r.groups] == places
    assert [g.destination for g in r.groups] == [destination] * len(places)


def test_both_of_them_after_one_group_is_that_group(read):
    r = read("office", "Three developers chat in the kitchen and two interns wait at reception, "
                       "then both of them go to the boardroom")
    assert r.groups[0].destination is None


@pytest.mark.parametrize("world, prompt, places", [
    ("station", "Every platform has three passengers waiting", {"platform_1", "platform_2"}),
    ("university", "Each seminar room has two students in it", {"seminar_room_1", "seminar_room_2"}),
])
def test_every_place_that_has_people_has_them_each(read, world, prompt, places):
    assert {g.location for g in read(world, prompt).groups} == places


def test_a_place_heading_its_clause_is_its_first_groups_only(read):
    r = read("station", "Each platform has a guard and the concourse has 10 passengers")
    assert [g.label for g in r.groups].count("passenger") == 1
