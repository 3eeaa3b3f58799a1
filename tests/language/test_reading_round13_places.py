"""Place classes of round 13, each with sentences of its own over at least two worlds (none from the
understanding sets): a building word with a kind before it the world lacks ("the garden centre"); a
purpose listing several things, or whose object is a hyphenated name; chat's "4" before a last plural;
a room described by what its people do there, said with a pronoun ("where they deliberate")."""

from __future__ import annotations

import pytest


# ---- A. a building word with a kind before it names a kind of place, refused where the world lacks it ----

@pytest.mark.parametrize("world,prompt,refused", [
    ("supermarket", "A couple walk from the bakery to the garden centre.", "garden centre"),
    ("supermarket", "Two staff go to the leisure centre.", "leisure centre"),
    ("mall", "Two teenagers walk from the food court to the garden centre.", "garden centre"),
    ("office", "A man walks to the garden centre.", "garden centre"),
    ("hotel", "A guest walks to the data centre.", "data centre"),
    ("hospital", "Two nurses go to the day centre.", "day centre"),
])
def test_a_kind_of_centre_the_world_lacks_is_refused(read, world, prompt, refused):
    reading = read(world, prompt)
    assert (reading.unknown_places, reading.groups[0].destination) == ((refused,), None)


@pytest.mark.parametrize("world,prompt,place", [
    ("hospital", "A nurse walks to the medical centre.", None),  # the hospital itself: no refusal
    ("office", "Five developers walk to the data centre.", "server_room"),  # the world's own, by meaning
    ("sports_centre", "Two boys walk to the leisure centre.", None),
])
def test_a_centre_the_world_is_or_has_is_not_refused(read, world, prompt, place):
    reading = read(world, prompt)
    assert (reading.unknown_places, reading.groups[0].destination) == ((), place)


# ---- B. a purpose's things: each of a list, and a hyphenated name -----------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("mall", "A woman walks from the cinema to buy paracetamol and a tube of cream.", "pharmacy"),
    ("mall", "A dad walks over from the toy shop to buy plasters and paracetamol.", "pharmacy"),
    ("supermarket", "A man walks from the café to buy plasters and paracetamol.", "pharmacy"),
    ("museum", "Two kids go to photograph the T-rex.", "t_rex_skeleton"),
    ("museum", "A guard goes to check on the T-rex.", "t_rex_skeleton"),
])
def test_a_purpose_is_done_where_its_things_are(read, world, prompt, place):
    assert read(world, prompt).groups[0].destination == place


def test_a_purpose_with_a_list_keeps_all_of_it(read):
    assert read("mall", "A dad walks over from the toy shop to buy plasters and paracetamol.").groups[0].purpose \
        == "to buy plasters and paracetamol"


# ---- C. chat's "4" before the last word: "for" ------------------------------------------------------

@pytest.mark.parametrize("world,prompt,location,purpose", [
    ("supermarket", "3 ppl queuing @ pharmacy 4 prescriptions", "pharmacy", "for prescriptions"),
    ("hotel", "5 guests waiting @ reception 4 keys", "reception_desk", "for keys"),
])
def test_chat_four_before_a_last_plural_is_for(read, world, prompt, location, purpose):
    group = read(world, prompt).groups[0]
    assert (group.location, group.purpose) == (location, purpose)


@pytest.mark.parametrize("world,prompt,count", [
    ("supermarket", "5 ppl waiting @ cafe 4 mins", 5),
    ("station", "2 staff at the ticket office 4 nurses", 2),
])
def test_chat_four_before_minutes_or_people_stays_a_number(read, world, prompt, count):
    group = read(world, prompt).groups[0]
    assert (group.count.value, group.purpose) == (count, None)


# ---- D. a room by what its people do there, said with a pronoun -------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("courthouse", "The jury walk to the room where they deliberate.", "jury_room"),
    ("courthouse", "Two jurors walk from court 2 to the room where they talk about the case.", "jury_room"),
    ("hotel", "Two guests walk from the bar to the room where they sleep.", None),  # a guest room, not the lobby
    ("residential", "The kids run to the room where they sleep.", "child_bedroom"),
])
def test_a_room_by_what_its_people_do_there(read, world, prompt, place):
    destination = read(world, prompt).groups[0].destination
    if place is None:
        assert destination is not None and destination.startswith("room_")
    else:
        assert destination == place
