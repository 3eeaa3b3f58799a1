"""Round 19 of the reader's people: one person whose verb the parser took for a plural noun
("a new starter walks", "counsel for the claimant heads", "Sam, our toddler, waddles")."""

import pytest


@pytest.mark.parametrize("world,prompt,label,where", [
    ("hospital", "a new starter walks from the cafe to the pharmacy", "starter", ("cafeteria", "pharmacy")),
    ("residential", "the new lodger strolls from the hallway to the kitchen", "lodger", ("hallway", "kitchen")),
    ("courthouse", "counsel for the claimant heads from the robing room to the entrance hall", "counsel",
     ("robing_room", "entrance_hall")),
    ("courthouse", "a trainee usher ambles over to the robing room", "usher", (None, "robing_room")),
    ("office", "A temp marches from the reception desk to the kitchen", "temp", None),
])
def test_one_person_whose_verb_looks_like_a_plural_noun(read, world, prompt, label, where):
    (g,) = read(world, prompt).groups
    assert g.label == label and (g.count.kind, g.count.value) == ("exact", 1) and g.intent == "walk"
    assert where is None or (g.start, g.destination) == where


def test_a_verb_of_taking_after_one_person(read):
    first, second = read("hospital", "a nursing auxiliary wheels Mrs Bello from ward b to the x-ray room").groups
    assert (first.label, first.count.value, first.intent) == ("auxiliary", 1, "walk")
    assert second.count.value == 1 and second.intent == "follow"


@pytest.mark.parametrize("world,prompt", [
    ("residential", "Sam, our toddler, waddles after the robot"),
    ("primary_school", "Ruby, the new girl in Year 2, trots after the robot"),
])
def test_a_named_person_with_an_aside_then_a_verb(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.count.kind, g.count.value) == ("exact", 1) and g.robot_interaction == "follow"
