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
