"""Round 12 of the reader's people: person nouns of two words or with a modifier keep their count,
"queue" misspelt still queues, people who only describe a place are no group, and a list of people
each placed on their own keeps each place."""

import pytest

COMPOUND_PEOPLE = [
    ("hotel", "Two team leaders walk from the lobby to the restaurant.", "team leader", 2),
    ("hotel", "Seven night-shift workers leave through the main entrance.", "worker", 7),
    ("hotel", "Three part-time cleaners walk to the restaurant.", "cleaner", 3),
    ("ferry_terminal", "Two part-time stewards walk to the check-in hall.", "steward", 2),
    ("university", "Four year 2 students walk to the library.", "student", 4),
    ("university", "Two grade 9 pupils wait by the entrance.", "pupil", 2),
    ("university", "The head of department walks to the lecture theatre.", "head", 1),
    ("library", "After the meeting the head goes back to the reading room.", "head", 1),
    ("warehouse", "In dispatch a temp worker, visibly nervous, keeps well clear of the robot.", "worker", 1),
]


@pytest.mark.parametrize("world,prompt,label,count", COMPOUND_PEOPLE)
def test_a_modified_person_noun_keeps_its_count(read, world, prompt, label, count):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert (groups[0].label, groups[0].count.kind, groups[0].count.value) == (label, "exact", count)


@pytest.mark.parametrize("world,prompt", [
    ("hotel", "5 guests queing at reception"),
    ("hotel", "Six guests are qeueing for the restaurant."),
    ("library", "four readers queuin by the front desk"),
    ("ferry_terminal", "twenty passengers queing for the ferry"),
    ("sports_centre", "8 swimmers qeuing at reception"),
])
def test_queue_misspelt_still_queues(read, world, prompt):
    assert [g.intent for g in read(world, prompt).groups] == ["queue"]


@pytest.mark.parametrize("world,prompt", [
    ("hotel", "A porter walks to the bar where very tired guests sit."),
    ("primary_school", "A parent walks from the foyer to the room where poorly children wait to be collected."),
    ("library", "A librarian walks to the reading room where really quiet students study."),
    ("courthouse", "A clerk goes to the waiting area where extremely nervous witnesses sit."),
    ("sports_centre", "A coach walks to the pool where very nervous swimmers wait to start."),
])
def test_people_of_a_where_clause_describe_the_place(read, world, prompt):
    groups = read(world, prompt).groups
    assert len(groups) == 1 and groups[0].intent == "walk"


@pytest.mark.parametrize("world,prompt,places", [
    ("hotel", "In the lobby: a porter at the reception desk, three guests at the lifts and a cleaner walking "
              "to the bar.", ["reception_desk", "lift_lobby"]),
    ("library", "In the reading room: a librarian at the issue desk, five students at the study tables and a "
                "reader walking to the exit.", ["issue_desk", "reading_tables"]),
    ("warehouse", "In dispatch: a marshal at the transport desk, two loaders at the outbound pallets and a "
                  "driver walking to the dock doors.", ["dispatch_desk", "outbound_staging"]),
])
def test_each_listed_person_keeps_its_own_place(read, world, prompt, places):
    groups = read(world, prompt).groups
    assert [g.location for g in groups[:-1]] == places
    assert groups[-1].intent == "walk" and groups[-1].destination is not None
