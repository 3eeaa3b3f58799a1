"""People classes of round 32, each with sentences of its own over at least two worlds (none from the
understanding sets): a long chain of modifiers before a counted person noun; a year of study before a
describing word and the person noun; some of a collective ("two of the crew"); person nouns the
lexicon lacks, by their shape ("posties", "the croupier bolts")."""

from __future__ import annotations

import pytest


def _one(reading):
    (g,) = reading.groups
    return g


# ---- 1. a long chain of modifiers keeps its count ----------------------------------------------------------

@pytest.mark.parametrize("world,prompt,value,start,destination", [
    ("hospital", "Five long-serving night-shift porters walk from the cafeteria to the pharmacy.", 5,
     "cafeteria", "pharmacy"),
    ("supermarket", "Four hard-working weekend shelf stackers wander from the bakery to the tills.", 4,
     "bakery", "checkouts"),
    ("mall", "Six tired night-shift shelf stackers walk from the food court to the exit.", 6,
     "food_court", "north_exit"),
    ("station", "Three loyal night-shift shelf stackers walk from the ticket hall to platform 2.", 3,
     "ticket_hall", "platform_2"),
])
def test_a_long_modifier_chain_keeps_its_count(read, world, prompt, value, start, destination):
    g = _one(read(world, prompt))
    assert (g.count.kind, g.count.value) == ("exact", value)
    assert (g.start, g.destination) == (start, destination)


def test_short_modifier_chains_keep_their_reading(read):
    for world, prompt, value in [
            ("hospital", "Six night-shift shelf stackers walk to the pharmacy.", 6),
            ("mall", "Four long-serving cleaners walk to the exit.", 4),
            ("supermarket", "Two loyal shelf stackers walk from the bakery to the tills.", 2),
            ("station", "Six loyal night-shift track walkers walk from the ticket hall to platform 2.", 6)]:
        g = _one(read(world, prompt))
        assert (g.count.kind, g.count.value) == ("exact", value)


# ---- 2. a year of study before a describing word: one group -----------------------------------------------

@pytest.mark.parametrize("world,prompt,value", [
    ("hospital", "Six third-year medical students walk from the cafeteria to the pharmacy.", 6),
    ("dental_clinic", "Two third-year dental students walk from the waiting room to the reception desk.", 2),
    ("vet_hospital", "Three final-year veterinary students walk from the reception to the kennels.", 3),
    ("university", "Five second-year foreign exchange students walk from the library to the refectory.", 5),
    ("museum", "Five first-year fine art students walk from the cafe to the modern gallery.", 5),
])
def test_a_year_of_study_before_a_describing_word_is_one_group(read, world, prompt, value):
    g = _one(read(world, prompt))
    assert (g.count.kind, g.count.value) == ("exact", value)


def test_a_year_of_study_alone_keeps_its_reading(read):
    g = _one(read("hospital", "Two third-years walk to the pharmacy."))
    assert (g.count.kind, g.count.value) == ("exact", 2)
    g = _one(read("hospital", "A second-year walks to the pharmacy."))
    assert (g.count.kind, g.count.value) == ("exact", 1)
    g = _one(read("university", "Four final-year law students wander from the library to the refectory."))
    assert (g.count.kind, g.count.value) == ("exact", 4)


# ---- 3. some of a collective: one group, as many as said ---------------------------------------------------

@pytest.mark.parametrize("world,prompt,kind,value", [
    ("fire_station", "Two of the crew walk from the kitchen to the appliance bay.", "exact", 2),
    ("mall", "Three of the team walk from the food court to the exit.", "exact", 3),
    ("hospital", "A few of the staff walk from the cafeteria to the pharmacy.", "vague", None),
    ("hotel", "Four of the kitchen staff walk from the lobby to the bar.", "exact", 4),
    ("mall", "Three of the cast walk from the food court to the exit.", "exact", 3),
])
def test_some_of_a_collective_is_one_group(read, world, prompt, kind, value):
    g = _one(read(world, prompt))
    assert g.count.kind == kind
    if value is not None:
        assert g.count.value == value
    assert g.intent == "walk"


def test_some_of_a_plural_or_counted_group_keeps_its_whole(read):
    r = read("hospital", "Two of the guards walk to the pharmacy.")
    assert [g.count.value for g in r.groups][-1] == 2 and len(r.groups) == 2
    r = read("hospital", "Two of the six porters walk to the pharmacy.")
    assert [g.count.value for g in r.groups] == [6, 2]
    r = read("hospital", "Ten nurses wait in the lobby; two of the nurses walk to the pharmacy.")
    assert [g.count.value for g in r.groups] == [10, 2]


# ---- 4. person nouns the lexicon lacks, by their shape ----------------------------------------------------

@pytest.mark.parametrize("world,prompt,value,start,destination", [
    ("post_office", "Three posties walk from the canteen to the sorting office.", 3, "canteen", "sorting_office"),
    ("post_office", "Two posties carry sacks from the sorting office to the canteen.", 2, "sorting_office", "canteen"),
    ("hotel", "The sommelier dashes from the bar to the lobby.", 1, "bar", "lobby"),
    ("mall", "The croupier bolts from the food court to the exit.", 1, "food_court", "north_exit"),
    ("hospital", "The croupier scurries over to the pharmacy.", 1, None, "pharmacy"),
])
def test_a_person_noun_the_lexicon_lacks_is_a_person(read, world, prompt, value, start, destination):
    r = read(world, prompt)
    g = _one(r)
    assert (g.count.kind, g.count.value) == ("exact", value)
    assert g.destination == destination
    if start is not None:
        assert g.start == start
    assert not r.corrections


def test_known_person_nouns_and_place_words_keep_their_reading(read):
    g = _one(read("hospital", "A cashier darts into the pharmacy."))
    assert (g.count.kind, g.count.value) == ("exact", 1)
    g = _one(read("mall", "Two techies stroll from the food court to the exit."))
    assert (g.count.kind, g.count.value) == ("exact", 2)
    g = _one(read("museum", "The hotelier strolls from the cafe to the modern gallery."))
    assert (g.count.kind, g.count.value) == ("exact", 1)
