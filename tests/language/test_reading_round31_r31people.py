"""People classes of round 31, each with sentences of its own over at least two worlds (none from the
understanding sets): a count before a long describing phrase; counted people who wheel, push or drag
things; a hyphenated modifier before a compound person noun; a fronted whole whose person noun is
hyphenated or has a name with "of" inside."""

from __future__ import annotations

import pytest


# ---- 1. a count before a long describing phrase ------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,kind,value", [
    ("museum", "Nine second-year art history students head from the cafe to the modern gallery.", "exact", 9),
    ("station", "Seven first-year engineering apprentices walk from the ticket hall to platform 2.", "exact", 7),
    ("mall", "Thirty-odd noisy Saturday-morning shoppers pour from the food court to the exit.", "approximate", 30),
    ("library", "Twenty-odd bleary-eyed exam-season students drift from the cafe to the reading room.",
     "approximate", 20),
])
def test_a_count_before_a_long_describing_phrase_keeps_its_count(read, world, prompt, kind, value):
    (g,) = read(world, prompt).groups
    assert (g.count.kind, g.count.value) == (kind, value)


def test_a_short_counted_phrase_keeps_its_count(read):
    (g,) = read("hospital", "Two tired nurses walk from the cafeteria to the pharmacy.").groups
    assert (g.count.kind, g.count.value) == ("exact", 2)
    (g,) = read("mall", "Twenty-odd shoppers walk from the food court to the exit.").groups
    assert (g.count.kind, g.count.value) == ("approximate", 20)


# ---- 2. counted people who wheel, push or drag things ----------------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "A couple of porters wheel beds from the pharmacy to the lifts.", "pharmacy", "elevator_hall"),
    ("hotel", "A couple of guests wheel suitcases from the lobby to the lifts.", "lobby", "lift_lobby"),
    ("mall", "A couple of mums wheel prams from the food court to the exit.", "food_court", "north_exit"),
    ("airport", "A couple of pilots wheel cases from check-in to security.", "check_in_hall", "security_checkpoint"),
])
def test_things_wheeled_by_counted_people_are_no_people(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.count.kind, g.count.value) == ("exact", 2)
    assert (g.start, g.destination) == (start, destination)


def test_things_pushed_after_a_pair_keep_their_reading(read):
    for world, prompt in [("hotel", "A pair of porters push luggage trolleys from the lobby to the lifts."),
                          ("supermarket", "A couple of pensioners push trolleys from the bakery to the tills."),
                          ("airport", "A pair of tourists drag suitcases from check-in to security.")]:
        (g,) = read(world, prompt).groups
        assert (g.count.kind, g.count.value) == ("exact", 2)


# ---- 3. a hyphenated modifier before a compound person noun or a group word -------------------------------

@pytest.mark.parametrize("world,prompt,value", [
    ("hospital", "Three off-shift porters amble from the cafeteria over to the pharmacy.", 3),
    ("hospital", "Two off-shift cleaners wander from the cafeteria to the pharmacy.", 2),
    ("mall", "Four off-duty shop assistants stroll from the food court to the fountain.", 4),
    ("library", "Three part-time library assistants walk from the issue desk to the cafe.", 3),
    ("hotel", "Two on-call maintenance engineers head from the lobby to the lifts.", 2),
])
def test_a_hyphenated_modifier_stays_with_its_person(read, world, prompt, value):
    (g,) = read(world, prompt).groups
    assert (g.count.kind, g.count.value) == ("exact", value)


def test_a_hyphenated_modifier_already_read_keeps_its_reading(read):
    (g,) = read("mall", "Two off-duty security guards stroll from the food court to the exit.").groups
    assert (g.count.kind, g.count.value) == ("exact", 2)
    (g,) = read("hotel", "Four on-call housekeepers head from the lobby to the lifts.").groups
    assert (g.count.kind, g.count.value) == ("exact", 4)


# ---- 4. a fronted whole whose person noun is hyphenated or has "of" inside --------------------------------

@pytest.mark.parametrize("world,prompt,whole,part,location", [
    ("library", "Of the ten sixth-formers in the reading room, three slip off to the cafe.", 10, 3, "reading_room"),
    ("station", "Of the twenty season-ticket holders in the ticket hall, five head to platform 2.", 20, 5,
     "ticket_hall"),
    ("museum", "Of the ten Duke of Edinburgh walkers in the cafe, four head to the modern gallery.", 10, 4, "cafe"),
    ("library", "Of the eight Duke of Edinburgh hikers in the reading room, two walk to the cafe.", 8, 2,
     "reading_room"),
])
def test_a_fronted_whole_with_a_hyphenated_or_of_name_has_its_part(read, world, prompt, whole, part, location):
    first, second = read(world, prompt).groups
    assert (first.count.value, first.location) == (whole, location)
    assert (second.count.value, second.relation, second.start) == (part, "subset_of:0", location)


def test_a_fronted_whole_already_read_keeps_its_part(read):
    first, second = read("mall", "Of the eight day-trippers at the fountain, two wander off to the food court.").groups
    assert (first.count.value, second.count.value, second.relation) == (8, 2, "subset_of:0")
    (g,) = read("museum", "Six Friends of the Museum volunteers walk from the cafe to the modern gallery.").groups
    assert g.count.value == 6
