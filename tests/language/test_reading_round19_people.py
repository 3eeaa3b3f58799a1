"""Round 19 of the reader's people: one person whose verb the parser took for a plural noun
("a new starter walks", "counsel for the claimant heads", "Sam, our toddler, waddles"); ages said
with a hyphen ("his 4-year-old", "two 8-year-olds"); "some 25 well-wishers"; "a quartet of"; people the robot
is meant to follow are a group; someone only waited for is no group."""

import pytest


@pytest.mark.parametrize("world,prompt,label,where", [
    # "new starter" is a person by two words since 2026-11-30 (lexicon.MULTIWORD_PEOPLE): the label keeps both
    ("hospital", "a new starter walks from the cafe to the pharmacy", "new starter", ("cafeteria", "pharmacy")),
    ("courthouse", "counsel for the claimant heads from the robing room to the entrance hall", "counsel",
     ("robing_room", "entrance_hall")),
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
])
def test_a_named_person_with_an_aside_then_a_verb(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.count.kind, g.count.value) == ("exact", 1) and g.robot_interaction == "follow"


@pytest.mark.parametrize("world,prompt,destination", [
    ("mall", "a dad and his 4-year-old walk from the food court to the toy shop", "toy_store"),
    ("zoo", "a granny and her six-year-old head from the cafe to the penguins", "penguin_beach"),
])
def test_a_possessive_pair_with_an_age_noun_is_two_groups_of_one(read, world, prompt, destination):
    groups = read(world, prompt).groups
    assert [(g.count.value, g.label, g.destination) for g in groups][1:] == [(1, "child", destination)]
    assert len(groups) == 2 and groups[0].destination == destination


@pytest.mark.parametrize("world,prompt,count", [
    ("mall", "two 8-year-olds run to the toy shop", 2),
    ("mall", "two 8-year-old girls wait by the fountain", 2),
    ("zoo", "three 9-year-olds stare at the robot", 3),
    ("hospital", "an 80-year-old waits in the cafe", 1),
])
def test_ages_said_with_a_hyphen_count_the_people(read, world, prompt, count):
    (g,) = read(world, prompt).groups
    assert (g.count.kind, g.count.value) == ("exact", count)


@pytest.mark.parametrize("world,prompt,value", [
    ("zoo", "some 20 well-wishers wait at the cafe", 20),
    ("hospital", "When visiting ends, some 25 well-wishers walk out of ward b to the main entrance", 25),
    ("zoo", "When the gates open at 9 am, some 30 day-trippers wander in from the entrance to the cafe", 30),
])
def test_an_approximate_count_of_a_hyphenated_person_word(read, world, prompt, value):
    (g,) = read(world, prompt).groups
    assert (g.count.kind, g.count.value) == ("approximate", value)


@pytest.mark.parametrize("world,prompt,value", [
    ("mall", "a quartet of teenagers wanders round the food court", 4),
    ("mall", "a quintet of kids runs to the toy shop", 5),
    ("zoo", "a quartet of keepers walks to the cafe", 4),
])
def test_a_quartet_or_quintet_counts(read, world, prompt, value):
    (g,) = read(world, prompt).groups
    assert g.count.value == value


@pytest.mark.parametrize("world,prompt,label,count", [
    ("office", "the robot is meant to follow the two interns to the kitchen", "intern", 2),
    ("office", "the robot has to follow the two interns", "intern", 2),
    ("museum", "the robot is meant to follow the two guides round the gallery", "guide", 2),
    ("museum", "The robot should follow the four tourists", "tourist", 4),
])
def test_people_the_robot_has_to_follow_are_a_group(read, world, prompt, label, count):
    r = read(world, prompt)
    (g,) = r.groups
    assert (g.label, g.count.value) == (label, count) and r.robot is not None and r.robot.task == "follow"


@pytest.mark.parametrize("world,prompt,label", [
    ("hospital", "A visiting dad sits in the cafe for 30 min until his daughter turns up", "dad"),
    ("hospital", "a woman waits in the pharmacy until her husband arrives", "woman"),
    ("station", "Grandma sits in the cafe until her grandson shows up", "grandma"),
    ("station", "two teens loiter on platform 1 until their mum comes back.", "teen"),
])
def test_someone_waited_for_is_no_group(read, world, prompt, label):
    (g,) = read(world, prompt).groups
    assert g.label == label and g.intent == "wait"


def test_someone_who_arrives_then_acts_is_a_group(read):
    groups = read("hospital", "a boy cries in the cafe until a nurse takes him to ward b").groups
    assert len(groups) == 2
