"""Round 15 of the reader's people: a thing's word naming a role with a noun before it ("the keynote
speaker", "a session chair"), a first name as the subject of a verb of aspect ("Stan keeps following
it"), a person taken along described by an adverb and an adjective ("a partially sighted woman"),
and a collective of an audience or a congregation with "of" and a count."""

import pytest


@pytest.mark.parametrize("world,prompt,label", [
    ("convention_centre", "The guest speaker walks from the registration foyer to the main hall.", "speaker"),
    ("university", "The keynote speaker heads from the library to the lecture theatre.", "speaker"),
    ("convention_centre", "A session chair walks to the main hall.", "chair"),
    ("hotel", "The committee chair waits in the lobby.", "chair"),
])
def test_a_role_said_by_a_things_word_with_a_modifier_is_one_person(read, world, prompt, label):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert (groups[0].label, groups[0].count.kind, groups[0].count.value) == (label, "exact", 1)


@pytest.mark.parametrize("world,prompt,label", [
    ("museum", "Stan keeps following the robot round the gallery.", "stan"),
    ("hotel", "Delighted by the robot, Priya keeps trailing it round the lobby.", "priya"),
    ("mall", "Curious, Maria starts wandering round the food court.", "maria"),
    ("library", "Bored, Kevin keeps pacing round the reading room.", "kevin"),
])
def test_a_first_name_doing_a_verb_of_aspect_is_one_person(read, world, prompt, label):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert (groups[0].label, groups[0].count.kind, groups[0].count.value) == (label, "exact", 1)


@pytest.mark.parametrize("world,prompt,label,place", [
    ("museum", "A guide shows a visually impaired man to the cafe.", "man", "cafe"),
    ("hospital", "A porter takes a very frail patient to the pharmacy.", "patient", "pharmacy"),
    ("hotel", "The concierge leads a slightly confused guest from reception to the ballroom.", "guest", "ballroom"),
])
def test_a_person_taken_along_with_an_adverb_before_them_is_a_group(read, world, prompt, label, place):
    leader, led = read(world, prompt).groups
    assert (led.label, led.count.value, led.intent) == (label, 1, "follow")
    assert leader.destination == led.destination == place


@pytest.mark.parametrize("world,prompt,n,low,high", [
    ("convention_centre", "An audience of about forty leave the main hall.", 40, 32, 48),
    ("museum", "A congregation of roughly 80 walk to the cafe.", 80, 64, 96),
])
def test_an_audience_of_about_a_count_is_that_count_approximately(read, world, prompt, n, low, high):
    g, = read(world, prompt).groups
    assert (g.count.kind, g.count.value, g.count.low, g.count.high) == ("approximate", n, low, high)


def test_an_audience_said_alone_is_a_crowd_not_six(read):
    g, = read("cinema", "The audience leave by the fire exit.").groups
    assert g.label == "audience" and g.count.kind == "implied" and g.count.low >= 20
