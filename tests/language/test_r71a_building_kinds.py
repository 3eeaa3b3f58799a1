"""A kind of building or shop the world lacks ("the supermarket", "the library", "the gym") is refused, never
read by meaning as a loosely similar room, while a world that is that kind, or has it, keeps it
(language/place_kinds.py, language/place_kind_words.py); a word that makes a kind of place with its
neighbour is not respelt as a name word of the world ("the post office" is no "poster office")."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, kind", [
    ("museum", "Two students wander off towards the library.", "library"),
    ("office", "Three interns head out in the direction of the restaurant.", "restaurant"),
    ("station", "A commuter nips over to the supermarket.", "supermarket"),
    ("airport", "Two pilots make their way to the hotel.", "hotel"),
    ("residential", "Dad walks out to the garage.", "garage"),
    ("zoo", "A family heads for the cinema.", "cinema"),
])
def test_a_kind_of_building_the_world_lacks_is_refused(read, world, prompt, kind):
    reading = read(world, prompt)
    assert any(kind in u for u in reading.unknown_places)
    assert reading.groups[0].destination is None


@pytest.mark.parametrize("world, prompt, role, place", [
    ("supermarket", "A family walks into the supermarket.", "destination", None),  # the world itself
    ("primary_school", "Four pupils walk to the library.", "destination", "library"),
    ("hotel", "Two guests head to the restaurant.", "destination", "restaurant"),
])
def test_a_kind_of_building_the_world_is_or_has_is_kept(read, world, prompt, role, place):
    reading = read(world, prompt)
    assert not reading.unknown_places
    if place is not None:
        assert getattr(reading.groups[0], role) == place


@pytest.mark.parametrize("world, prompt, kind", [
    ("library", "A pensioner pops round to the post office.", "post office"),  # not "poster office" (posters)
    ("cinema", "Two kids nip out to the sweet shop.", "sweet shop"),
])
def test_a_word_making_a_kind_of_place_is_not_respelt(read, world, prompt, kind):
    reading = read(world, prompt)
    assert kind in reading.unknown_places and reading.groups[0].destination is None


@pytest.mark.parametrize("world, prompt, place", [
    ("student_union", "Two freshers head to the college bar.", "bar"),
    ("museum", "A dad pops into the library cafe.", "cafe"),
])
def test_a_building_said_of_a_place_is_no_kind_named(read, world, prompt, place):
    reading = read(world, prompt)
    assert reading.groups[0].destination == place and not reading.unknown_places
