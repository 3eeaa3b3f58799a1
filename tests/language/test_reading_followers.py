"""People who follow someone said before them ("... and a porter follows her", "a coach follows them"):
they follow that group, by its words, and with no way of their own they go where it goes."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, leader, start, destination", [
    ("hospital", "A nurse walks to the pharmacy and a porter follows her.", "A nurse", None, "pharmacy"),
    ("sports_centre", "Three players walk from the changing rooms to squash court 2, and a coach follows them.",
     "Three players", "changing_room_men", "squash_court_2"),
    ("office", "Two managers walk from reception to the boardroom; an intern follows close behind.",
     "Two managers", "reception", "boardroom"),
    # "her" is one person, though a group was said after her
    ("station", "A guard walks to the ticket hall, four commuters wait on platform 1, and a cleaner follows her.",
     "A guard", None, "ticket_hall"),
])
def test_a_follower_follows_the_group_said_before_and_goes_its_way(read, world, prompt, leader, start,
                                                                     destination):
    reading = read(world, prompt)
    follower = next(g for g in reading.groups if g.intent == "follow")
    assert follower.follows == leader
    assert (follower.start, follower.destination) == (start, destination)


def test_a_follower_with_a_way_of_its_own_keeps_it(read):
    reading = read("hospital", "A nurse walks to the pharmacy and a porter follows her to the lobby.")
    porter = next(g for g in reading.groups if g.label == "porter")
    assert porter.follows == "A nurse" and porter.destination == "entrance_lobby"


@pytest.mark.parametrize("world, prompt", [
    ("residential", "A child follows her mother to the kitchen."),
    ("museum", "A boy follows his teacher to the auditorium."),
])
def test_her_before_a_noun_is_whose_not_whom(read, world, prompt):
    reading = read(world, prompt)
    assert reading.groups[0].intent == "follow" and reading.groups[0].follows.split()[-1] in ("mother", "teacher")


@pytest.mark.parametrize("world, prompt, led", [
    ("mall", "A guard escorts a shoplifter from the bookshop to the food court.", "shoplifter"),
    ("hospital", "A nurse accompanies a bewildered pensioner from the entrance lobby to ward C.", "pensioner"),
    ("library", "A librarian guides a freshman from the foyer to the reading room.", "freshman"),
])
def test_someone_escorted_whom_no_list_names_is_there_and_goes_along(read, world, prompt, led):
    reading = read(world, prompt)
    assert [g.count.value for g in reading.groups] == [1, 1]
    escorted = reading.groups[1]
    assert escorted.label == led and escorted.intent == "follow"
    assert escorted.destination == reading.groups[0].destination


def test_a_thing_wheeled_is_no_one(read):
    reading = read("hospital", "A porter wheels a trolley from ward A to the pharmacy.")
    assert [g.label for g in reading.groups] == ["porter"]


@pytest.mark.parametrize("world, prompt, taken_along", [
    ("museum", "Ten tourists follow their guide from the entrance hall to the Egyptian gallery, and a child runs "
               "up to the robot.", "guide"),
    ("hospital", "Two nurses help a patient to ward C and a child runs up to the robot.", "patient"),
    ("mall", "A guard escorts two shoplifters to the food court, and a toddler waves at the robot.", "shoplifter"),
])
def test_the_one_followed_or_taken_along_does_not_take_the_next_groups_verb(read, world, prompt, taken_along):
    groups = {g.label: g for g in read(world, prompt).groups}
    assert groups[taken_along].robot_interaction is None and groups[taken_along].intent != "robot"
