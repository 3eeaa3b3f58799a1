"""Round 16 of the reader's counts: nouns of quantity ("a score of", "a classful of"), two-word roles
in the plural ("two dinner ladies"), words written apart or hyphenated ("newly-weds", "after school
club"), a number word after a unit ("ten five-a-side regulars") and a chain of nouns ending in a
person ("two coach company reps")."""

import pytest


@pytest.mark.parametrize("world,prompt,label", [
    ("museum", "A score of pupils walk to the cafe.", "pupil"),
    ("hospital", "A score of visitors wait in reception.", "visitor"),
    ("mall", "About a score of shoppers wait at the food court.", "shopper"),
])
def test_a_score_is_twenty(read, world, prompt, label):
    (g,) = read(world, prompt).groups
    assert g.label == label and g.count.value == 20 and g.count.low >= 16


@pytest.mark.parametrize("world,prompt,label", [
    ("primary_school", "A classful of children walk to the hall.", "child"),
    ("museum", "A classful of pupils wait in the lobby.", "pupil"),
])
def test_a_classful_is_a_class(read, world, prompt, label):
    (g,) = read(world, prompt).groups
    assert g.label == label and g.count.kind == "vague" and (g.count.low, g.count.high) == (25, 30)


@pytest.mark.parametrize("world,prompt,label,value", [
    ("primary_school", "A dinner lady walks to the hall.", "dinner lady", 1),
    ("primary_school", "Two dinner ladies walk to the hall.", "dinner lady", 2),
    ("office", "Three tea ladies walk to the kitchen.", "tea lady", 3),
])
def test_a_two_word_role_is_labelled_by_its_role(read, world, prompt, label, value):
    (g,) = read(world, prompt).groups
    assert (g.label, g.count.value) == (label, value)


@pytest.mark.parametrize("world,prompt", [
    ("hotel", "The newly-weds walk to the bar."),
    ("cinema", "The newly weds wait in the foyer."),
])
def test_newly_weds_apart_are_a_couple(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.label == "newlywed" and g.count.value == 2 and g.together


@pytest.mark.parametrize("world,prompt,label,value", [
    ("primary_school", "Ten after school club kids wait in the hall.", "kid", 10),
    ("sports_centre", "Ten five-a-side regulars wait in the cafe.", "regular", 10),
    ("bus_station", "Two coach company reps wait in the cafe.", "representative", 2),
])
def test_a_count_before_a_modified_person_is_kept(read, world, prompt, label, value):
    (g,) = read(world, prompt).groups
    assert (g.label, g.count.kind, g.count.value) == (label, "exact", value)


@pytest.mark.parametrize("world,prompt,label,value", [
    ("sports_centre", "Three football club coaches walk to the cafe.", "coach", 3),
    ("airport", "Two cabin crew walk to gate 3.", "cabin crew", 2),
])
def test_guard_counts_that_already_held(read, world, prompt, label, value):
    """Held before this round; kept by the chain and plural rules above."""
    (g,) = read(world, prompt).groups
    assert (g.label, g.count.value) == (label, value)


@pytest.mark.parametrize("world,prompt,value", [
    ("museum", "Twenty five tourists wait in the lobby.", 25),
    ("museum", "One hundred and five tourists wait in the lobby.", 105),
])
def test_numbers_in_words_still_add_up(read, world, prompt, value):
    (g,) = read(world, prompt).groups
    assert g.count.value == value


@pytest.mark.parametrize("world,prompt,label,kind,value", [
    ("primary_school", "The school group (25 children) walks to the hall.", "child", "exact", 25),
    ("museum", "A tour group (twenty tourists) waits in the lobby.", "tourist", "exact", 20),
    ("hotel", "The wedding party (about 40 guests) walks to the bar.", "guest", "approximate", 40),
])
def test_a_count_in_brackets_is_the_group(read, world, prompt, label, kind, value):
    (g,) = read(world, prompt).groups
    assert (g.label, g.count.kind, g.count.value) == (label, kind, value)


@pytest.mark.parametrize("world,prompt,value,intent,place", [
    ("hotel", "Ten guests wait in the lobby; the other 6 are in the bar.", 6, "wait", "bar"),
    ("hotel", "Ten guests wait in the lobby and the remaining 4 walk to the bar.", 4, "walk", "bar"),
    ("mall", "Two guards stand at the entrance while the other 3 patrol the food court.", 3, "wander", "food_court"),
])
def test_the_other_n_are_more_of_them(read, world, prompt, value, intent, place):
    first, other = read(world, prompt).groups
    assert other.label == first.label and (other.count.kind, other.count.value) == ("exact", value)
    assert other.intent == intent and place in (other.location, other.destination)


@pytest.mark.parametrize("world,prompt,kind,value", [
    ("museum", "Visitors drift in twos and threes to the cafe.", "vague", None),
    ("museum", "Thirty visitors drift in twos and threes to the cafe.", "exact", 30),
    ("airport", "Passengers wander in threes towards gate 3.", "vague", None),
])
def test_in_twos_and_threes_is_small_parties_together(read, world, prompt, kind, value):
    """Decided: like "in pairs" and "in groups of two or three", the people move in small parties
    (together); the total is what is said (bare plural 3-6 when none)."""
    (g,) = read(world, prompt).groups
    assert g.together and g.count.kind == kind and (value is None or g.count.value == value)


@pytest.mark.parametrize("world,prompt,value", [
    ("mall", "A family with two kids walks to the food court.", 4),
    ("museum", "A family with three children waits in the lobby.", 5),
])
def test_a_family_with_children_is_the_children_and_two_parents(read, world, prompt, value):
    (g,) = read(world, prompt).groups
    assert (g.label, g.count.kind, g.count.value, g.together) == ("family", "implied", value, True)


@pytest.mark.parametrize("world,prompt,label,value", [
    ("mall", "Three prams are pushed to the food court.", "parent", 3),
    ("museum", "Two wheelchairs roll to the cafe.", "wheelchair user", 2),
])
def test_people_counted_by_what_they_move(read, world, prompt, label, value):
    (g,) = read(world, prompt).groups
    assert (g.label, g.count.value) == (label, value)


@pytest.mark.parametrize("world,prompt,label,value", [
    ("cinema", "Forty-ish film fans wait in the foyer.", "fan", 40),
    ("museum", "Twenty ish tourists wait in the lobby.", "tourist", 20),
])
def test_a_number_word_with_ish_is_about_that_many(read, world, prompt, label, value):
    (g,) = read(world, prompt).groups
    assert (g.label, g.count.kind, g.count.value) == (label, "approximate", value)


@pytest.mark.parametrize("world,prompt,label,value", [
    ("hotel", "Ten-plus guests wait in the lobby.", "guest", 10),
    ("cinema", "40-plus fans wait in the foyer.", "fan", 40),
])
def test_a_number_with_plus_written_out_is_at_least_that_many(read, world, prompt, label, value):
    (g,) = read(world, prompt).groups
    assert (g.label, g.count.kind, g.count.value) == (label, "approximate", value)
