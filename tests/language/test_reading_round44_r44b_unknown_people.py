"""Round 44 (r44b): people said by nouns the reader did not take for people.

1. a counted plural that is also a verb's form ("potters" potter about, "ramblers"), the subject of a verb
   after it or described by a participle: people, not the verb of a bare count (language/people.py);
2. one person told by a feeling about the robot in an aside before the verb ("a newbie by the mummy case,
   startled by the robot, edges away"): a person whatever noun names them (language/feeling_people.py);
3. a family's youngest or eldest said by the family's name ("the Patels' eldest waits ..."): one child
   (language/little_ones.py)."""

from __future__ import annotations

import pytest


# ---- 1. counted plurals that are verbs' forms too ---------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,count", [
    ("museum", "Twelve ramblers trudge from the foyer to the cafe.", 12),
    ("pottery_studio", "Six potters carry their bowls to the kiln room.", 6),
    ("city_farm", "The eight potterers in the yard head for the cafe.", 8),
])
def test_a_counted_plural_that_is_a_verb_too_is_people(read, world, prompt, count):
    (group,) = read(world, prompt).groups
    assert group.count.value == count


def test_a_fronted_whole_of_such_people_keeps_its_part(read):
    whole, part = read("museum", "Of ten ramblers resting in the cafe, a pair wander off to the gift shop.").groups
    assert (whole.count.value, part.count.value, part.relation, part.destination) == (10, 2, "subset_of:0", "gift_shop")


def test_a_range_of_such_people_in_a_room_on_fire_is_that_range(read):
    (group,) = read("museum", "Smoke pours from the cafe and the four or five ramblers in there get out fast.").groups
    assert (group.count.low, group.count.high, group.intent) == (4, 5, "evacuate")


# ---- 2. a feeling about the robot said in an aside ---------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,reaction", [
    ("museum", "A newbie by the mummy case, startled by the robot, edges away.", "Surprised"),
    ("climbing_centre", "A first-timer at the bouldering wall, spooked by the robot, backs off.", "Scared"),
])
def test_one_person_told_by_a_feeling_in_an_aside(read, world, prompt, reaction):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value, group.robot_reaction) == ("exact", 1, reaction)


# ---- 3. a family's youngest or eldest by the family's name ----------------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("museum", "The Patels' eldest waits by the mummy case.", "mummy_case"),
    ("mall", "When the robot beeps, the Smiths' youngest by the fountain bursts into tears.", "fountain"),
])
def test_a_familys_youngest_by_its_name_is_one_child(read, world, prompt, place):
    (group,) = read(world, prompt).groups
    assert (group.count.value, group.location) == (1, place)
