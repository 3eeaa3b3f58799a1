"""People classes of round 34, each with sentences of its own over at least two worlds (none from the
understanding sets): what a person wears after "in" is no place and keeps the person ("a diver in a
wetsuit pads ..."); a count, a modifier taken for a verb and the plural's verb taken for a noun ("ten cub
scouts bowl ..."), or a plural's verb taken for a noun before a later clause ("six swimmers pad to the
pool, a lifeguard watches"); a place phrase fronted before one person with no comma; people who urge
or watch the subject in an aside between commas; a plural no list names after "a couple of" whose
verb no list names; a "-timer" person."""

from __future__ import annotations

import pytest


def _one(reading):
    (g,) = reading.groups
    return g


# ---- 1. what a person wears: no place, the person kept --------------------------------------------------------

@pytest.mark.parametrize("world,prompt,count,destination", [
    ("aquarium", "A diver in a wetsuit pads from the staff corridor into the cafe.", 1, "cafe"),
    ("swimming_baths", "A swimmer in goggles pads to the main pool.", 1, "main_pool"),
    ("concert_venue", "The trio, three singers in concert black, wait backstage.", 3, None),
    ("aquarium", "A keeper in a wetsuit pads to the cafe.", 1, "cafe"),
])
def test_what_a_person_wears_is_no_place(read, world, prompt, count, destination):
    r = read(world, prompt)
    g = _one(r)
    assert g.count.value == count and g.who != "people"
    assert g.destination == destination
    assert r.unknown_places == ()
    assert g.start != "goggles_rack"


def test_worn_things_keep_their_reading(read):
    for world, prompt, count, place in [
            ("hospital", "A man in a hi-vis jacket walks to the pharmacy.", 1, "pharmacy"),
            ("hospital", "Two medics in scrubs walk to the pharmacy.", 2, "pharmacy"),
            ("fire_station", "A firefighter in a helmet walks from the reception to the kitchen.", 1, "kitchen"),
            ("mall", "Three lads in football shirts wander around the food court.", 3, "food_court")]:
        g = _one(read(world, prompt))
        assert g.count.value == count
        assert place in (g.destination, g.location)


def test_a_place_named_with_a_clothing_word_is_a_place(read):
    g = _one(read("residential", "A man waits by the coat rack."))
    assert g.location == "coat_rack"


# ---- 2. a plural's verb taken for a noun ---------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,count,place", [
    ("bowling_alley", "Ten cub scouts bowl on the bumper lanes.", 10, "bumper_lanes"),
    ("hospital", "Eight cub scouts bowl near the pharmacy.", 8, "pharmacy"),
    ("swimming_baths", "Six swimmers pad to the main pool, a lifeguard watches.", 6, "main_pool"),
    ("mall", "Six cub scouts pad to the exit.", 6, "west_entrance"),
    ("museum", "Ten sea scouts pad to the cafe.", 10, "cafe"),
])
def test_a_plurals_verb_taken_for_a_noun_keeps_the_group(read, world, prompt, count, place):
    r = read(world, prompt)
    g = r.groups[0]
    assert g.count.value == count and g.who != "people"
    assert place in (g.destination, g.location)


def test_plural_verbs_the_parser_knows_keep_their_reading(read):
    for world, prompt, count in [
            ("hospital", "Eight cub scouts file into the pharmacy.", 8),
            ("mall", "Twelve cub scouts queue at the food court.", 12),
            ("hospital", "Four nurses pad to the pharmacy, a porter waits in the lobby.", 4),
            ("museum", "Twelve pupils pad to the cafe, a guide watches.", 12)]:
        assert read(world, prompt).groups[0].count.value == count


# ---- 3. a place phrase fronted before one person -------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("airport", "By the check-in desks a toddler gapes at the robot.", None),
    ("hospital", "Near the vending machines a little girl stares at the robot.", "vending_machine"),
    ("mall", "Beside the escalators a small boy gawps at the robot.", None),
    ("swimming_baths", "Near the main pool a little boy gawps at the robot.", "main_pool"),
])
def test_a_fronted_place_phrase_before_one_person(read, world, prompt, place):
    g = _one(read(world, prompt))
    assert (g.count.kind, g.count.value) == ("exact", 1)
    assert g.who != "people"
    if place is not None:
        assert g.location == place


def test_fronted_phrases_keep_their_reading(read):
    g = _one(read("museum", "Next to the gift shop a lone tourist checks a map."))
    assert (g.count.value, g.location) == (1, "gift_shop")
    g = _one(read("hospital", "By the time the robot arrives, a nurse waits at the pharmacy."))
    assert (g.count.value, g.location) == (1, "pharmacy")
    g = _one(read("hospital", "In the pharmacy, two porters wait."))
    assert (g.count.value, g.location) == (2, "pharmacy")


# ---- 4. people who urge or watch the subject in an aside -----------------------------------------------------

@pytest.mark.parametrize("world,prompt,count,destination", [
    ("hospital", "Three nurses, cheered on by the patients, walk to the pharmacy.", 3, "pharmacy"),
    ("mall", "A boy, watched by his parents, walks to the exit.", 1, "west_entrance"),
    ("primary_school", "Two pupils, egged on by their classmates, walk to the hall.", 2, "school_hall"),
    ("museum", "A girl, urged on by her friends, walks to the cafe.", 1, "cafe"),
])
def test_an_aside_of_people_urging_the_subject(read, world, prompt, count, destination):
    g = _one(read(world, prompt))
    assert g.count.value == count and g.destination == destination


def test_people_who_go_along_in_an_aside_keep_their_reading(read):
    r = read("hospital", "A nurse, followed by two porters, walks to the pharmacy.")
    assert sum(g.count.value for g in r.groups) == 3


# ---- 5. a plural no list names after "a couple of"; a "-timer" -------------------------------------------------

@pytest.mark.parametrize("world,prompt,count", [
    ("art_gallery", "A couple of first-year sketchers pack up their easels.", 2),
    ("museum", "A pair of trainee doodlers put down their pencils.", 2),
    ("museum", "A first-timer wanders around the cafe.", 1),
    ("mall", "A couple of old-timers sit in the food court.", 2),
    ("hospital", "A part-timer walks to the pharmacy.", 1),
    ("airport", "Two nervous first-timers wait in the departure lounge.", 2),
])
def test_people_no_list_names(read, world, prompt, count):
    g = _one(read(world, prompt))
    assert g.count.value == count and g.who != "people"


def test_a_timer_thing_is_no_person(read):
    g = _one(read("hospital", "A nurse sets a timer and walks to the pharmacy."))
    assert (g.count.value, g.destination) == (1, "pharmacy")
