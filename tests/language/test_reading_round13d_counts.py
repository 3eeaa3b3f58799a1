"""Round 13d of the reader's people and counts: people flanked, escorted or followed by others share
the verb after both; a "with" phrase about a person does not split a subject; a person noun naming
the kind of a thing is nobody; a school class or team named by its number is a group of a class's
size; and counts in the forms researchers type."""

import pytest


@pytest.mark.parametrize("world,prompt,place", [
    ("courthouse", "A defendant flanked by two guards walks to the courtroom.", "courtroom_1"),
    ("courthouse", "A defendant, accompanied by two guards, walks to the courtroom.", "courtroom_1"),
    ("hospital", "A patient escorted by a nurse walks to x-ray.", "radiology"),
    ("museum", "A child followed by her dad runs to the cafe.", "cafe"),
])
def test_people_in_company_of_others_share_the_walk(read, world, prompt, place):
    first, second = read(world, prompt).groups
    assert first.destination == second.destination == place
    assert first.intent == "walk" and first.start is None


@pytest.mark.parametrize("world,prompt,place", [
    ("museum", "A child followed by her dad runs to the cafe.", "cafe"),
    ("hotel", "A guest, trailed by two porters, walks to the lifts.", None),
])
def test_the_follower_said_by_a_participle_follows(read, world, prompt, place):
    first, follower = read(world, prompt).groups
    assert follower.intent == "follow" and first.intent == "walk"
    assert first.destination == follower.destination is not None
    assert place is None or first.destination == place


@pytest.mark.parametrize("world,prompt,place", [
    ("primary_school", "A boy with a broken arm and his mum wait at the office.", "school_office"),
    ("hospital", "A girl with a sprained ankle and her dad wait in reception.", "reception_desk"),
])
def test_a_with_phrase_about_a_person_keeps_the_companion_s_verb(read, world, prompt, place):
    # one group per noun phrase, each of one, both waiting where the clause says
    groups = read(world, prompt).groups
    assert [(g.count.value, g.intent, g.location) for g in groups] == [(1, "wait", place)] * 2


@pytest.mark.parametrize("world,prompt,place", [
    ("primary_school", "A boy with a broken arm and two teachers wait at the office.", "school_office"),
    ("airport", "A man with a huge suitcase and two kids wait at the check-in.", None),
])
def test_a_with_phrase_does_not_split_other_subjects(read, world, prompt, place):
    first, second = read(world, prompt).groups
    assert first.intent == second.intent == "wait"
    assert first.location == second.location
    if place is not None:
        assert first.location == place


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "The nurses and their patient files are in the office."),
    ("hotel", "The manager and the guest files are in the office."),
    ("library", "The librarian and the visitor passes are at the front desk."),
])
def test_a_person_noun_naming_a_thing_is_nobody(read, world, prompt):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert groups[0].intent == "wait"


@pytest.mark.parametrize("world,prompt,n", [
    ("primary_school", "Year 4 and year 5 walk to the hall.", 2),
    ("primary_school", "Class 3 lines up in the playground.", 1),
    ("university", "Year 2 walks to the lecture theatre.", 1),
    ("primary_school", "Form 7B waits outside the office.", 1),
])
def test_a_school_class_named_by_number_is_a_class(read, world, prompt, n):
    groups = read(world, prompt).groups
    assert len(groups) == n
    for g in groups:
        assert (g.label, g.count.kind, g.count.low, g.count.high) == ("pupil", "vague", 25, 30)


@pytest.mark.parametrize("world,prompt", [
    ("primary_school", "A teacher takes year 3 to the hall."),
    ("university", "A lecturer takes year 2 to the library."),
])
def test_a_class_led_by_a_teacher_follows(read, world, prompt):
    teacher, cls = read(world, prompt).groups
    assert cls.intent == "follow" and cls.count.kind in ("vague", "implied") and cls.count.value >= 3


@pytest.mark.parametrize("world,prompt", [
    ("primary_school", "The teacher of class 3 waits in the hall while year 4 walks to the playground."),
    ("university", "A lecturer walks to the year 2 common room while year 1 waits in the foyer."),
])
def test_a_class_said_as_whose_or_where_is_no_group(read, world, prompt):
    first, cls = read(world, prompt).groups  # only the second class is people
    assert first.count.value == 1 and cls.label == "pupil" and cls.count.low == 25


@pytest.mark.parametrize("world,prompt,value", [
    ("airport", "Over 40 passengers wait at gate B1.", 40),
    ("hotel", "Under a dozen guests wait in the bar.", 12),
    ("mall", "No more than 10 shoppers wait at the food court.", 10),
    ("library", "Fewer than twenty students study in the reading room.", 20),
    ("station", "More than 30 commuters wait on platform 1.", 30),
])
def test_a_bound_is_about_that_many(read, world, prompt, value):
    c = read(world, prompt).groups[0].count
    assert (c.kind, c.value) == ("approximate", value) and c.low < value < c.high


@pytest.mark.parametrize("world,prompt,value", [
    ("courthouse", "An 8-strong jury walks to the jury room.", 8),
    ("hotel", "An eight-strong hen party walks to the bar.", 8),
    ("ferry_terminal", "A 40-strong coach party waits in the departure lounge.", 40),
])
def test_a_strong_collective_has_that_many(read, world, prompt, value):
    c = read(world, prompt).groups[0].count
    assert (c.kind, c.value) == ("exact", value)


@pytest.mark.parametrize("world,prompt,value", [
    ("airport", "Five passengers wait at gate B1 and another 5 wait at gate B2.", 5),
    ("hospital", "Two porters wait in reception and another three porters walk to the pharmacy.", 3),
])
def test_another_with_a_number_is_that_many_more(read, world, prompt, value):
    groups = read(world, prompt).groups
    assert groups[-1].count.value == value and groups[-1].relation == "more_of:0"
