"""Four small readings (language/counts.py, sentence.py, adjective_people.py, fronted_time_commas.py,
settled_after_leaving.py): a count before a hyphened word that opens with "A" ("Two A-level students"); a
noun-less adjective person after describing words ("an aggressive drunk"); a fronted "After the X" with a
name after it and no comma; and running off to hide somewhere, which is going there."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,label,count", [
    ("museum", "Three A-level pupils drift from the entrance hall to the cafe.", "pupil", 3),
    ("office", "Four B-team engineers wait in the kitchen.", "engineer", 4),
    ("office", "Two developers and an A-list client sit in the boardroom.", "client", 1),
])
def test_a_hyphened_word_opened_by_a_letter_keeps_the_count_before_it(read, world, prompt, label, count):
    groups = read(world, prompt).groups
    group = next(g for g in groups if g.label == label)
    assert (group.count.kind, group.count.value) == ("exact", count)
    assert all(g.location is not None or g.destination is not None for g in groups)


@pytest.mark.parametrize("world,prompt", [
    ("station", "A belligerent drunk on platform 2 stands in the robot's way."),
    ("mall", "A rather friendly local asks the robot where the bookshop is."),
])
def test_a_described_adjective_person_is_one_person(read, world, prompt):
    groups = read(world, prompt).groups
    assert len(groups) == 1 and (groups[0].count.kind, groups[0].count.value) == ("exact", 1)


@pytest.mark.parametrize("world,prompt,label,destination", [
    ("residential", "After the quarrel Grandma marches out the front door.", "grandma", "front_door"),
    ("hospital", "After the briefing Dr Okoye walks to the pharmacy.", "doctor", "pharmacy"),
])
def test_a_fronted_time_runs_no_name_into_it(read, world, prompt, label, destination):
    groups = read(world, prompt).groups
    assert len(groups) == 1 and groups[0].destination == destination


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("residential", "A little girl runs off and hides in the master bedroom.", None, "master_bedroom"),
    ("residential", "The twins sneak out of the kitchen and hide behind the sofa.", "kitchen", "sofa"),
    ("office", "An intern slips away and hides in the server room.", None, "server_room"),
])
def test_running_off_to_hide_somewhere_is_going_there(read, world, prompt, start, destination):
    groups = read(world, prompt).groups
    assert len(groups) == 1 and groups[0].intent == "walk"
    assert (groups[0].start, groups[0].destination) == (start, destination)


def test_hiding_where_one_is_stays_there(read):
    group = read("residential", "A boy hides in the bathroom.").groups[0]
    assert group.intent == "wait" and group.location == "bathroom"
