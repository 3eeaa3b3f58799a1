"""Group classes of round 42 (r42people), each with sentences of its own over at least two worlds (none
from the understanding sets):
1. describing words listed with a comma before a person ("a pale, dizzy visitor", "a frail, elderly
   patient") leave one person: as a subject, and as the person a helper takes along a route, who is a
   second group that follows.
2. people who dawdle round, around or about a place wander there; dawdling to a place stays a walk."""

from __future__ import annotations

import pytest


# ---- 1. a comma between describing words before a person ------------------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("office", "The receptionist guides a pale, dizzy visitor to the kitchen.", "kitchen"),
    ("hospital", "A porter pushes a frail, elderly patient from the ward to x-ray.", "radiology"),
    ("hall_of_residence", "The warden helps a pale, tipsy fresher from reception back to G02.", "bedroom_g02"),
    ("mall", "A guard walks a tearful, frightened boy to the fountain.", "fountain"),
])
def test_a_helped_person_with_listed_describing_words_follows(read, world, prompt, destination):
    helper, helped = read(world, prompt).groups
    assert (helped.count.kind, helped.count.value, helped.intent) == ("exact", 1, "follow")
    assert helper.destination == destination


@pytest.mark.parametrize("world,prompt,value", [
    ("office", "A pale, dizzy visitor walks to the kitchen.", 1),
    ("office", "Two tired, hungry interns walk to the kitchen.", 2),
    ("mall", "Two tired, hungry shoppers walk to the food court.", 2),
    ("hospital", "Three pale, shaky patients walk to the cafeteria.", 3),
])
def test_people_with_listed_describing_words_are_one_group(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == ("exact", value)


# ---- guards: a comma that ends a place or a list of people -------------------------------------------

@pytest.mark.parametrize("world,prompt,counts", [
    ("office", "In the kitchen, two interns chat.", [2]),
    ("hospital", "A nurse waits at the desk, two porters stand by the lifts.", [1, 2]),
    ("mall", "A lost, tearful boy waits at the fountain.", [1]),
    ("office", "A tall man, a short woman and a boy walk to the kitchen.", [1, 1, 1]),
])
def test_commas_between_people_and_places_keep_their_groups(read, world, prompt, counts):
    groups = read(world, prompt).groups
    assert [g.count.value for g in groups] == counts


# ---- 2. dawdling round a place is wandering there ------------------------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("garden_centre", "Two sisters dawdle round the pet aquatics section.", "pet_aquatics"),
    ("mall", "Two pensioners dawdle round the toy shop.", "toy_store"),
    ("hospital", "A visitor dawdles around the cafeteria.", "cafeteria"),
    ("office", "A temp dawdles about the kitchen.", "kitchen"),
])
def test_dawdling_round_a_place_is_wandering(read, world, prompt, location):
    (group,) = read(world, prompt).groups
    assert (group.intent, group.location) == ("wander", location)


@pytest.mark.parametrize("world,prompt,intent", [
    ("mall", "Two pensioners dawdle to the toy shop.", "walk"),
    ("hospital", "A visitor dawdles from the cafeteria to the pharmacy.", "walk"),
    ("mall", "A teenager mooches about the food court.", "wander"),
    ("office", "Two interns wait in the kitchen.", "wait"),
])
def test_going_somewhere_slowly_keeps_its_intent(read, world, prompt, intent):
    (group,) = read(world, prompt).groups
    assert group.intent == intent
