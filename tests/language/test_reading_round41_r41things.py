"""Classes of round 41 (counts and places), each with sentences of its own over at least two worlds (none
from the understanding sets):

1. food, drink and a nap after a place preposition are no place to refuse ("stock up on crisps",
   "woken from a nap", "startled out of a doze");
2. a party said as the outing it is on, counted with "of" ("a works do of fifteen", "a school trip of
   thirty"): that many people together."""

from __future__ import annotations

import pytest


# ---- 1. food, drink and naps are no place ----------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,word", [
    ("museum", "Woken from a nap on the bench, an old man shuffles towards the cafe.", "nap"),
    ("hospital", "A porter, startled out of a doze in the corridor, hurries to the lifts.", "doze"),
    ("office", "Roused from a siesta on the sofa, an intern drifts to the kitchen.", "siesta"),
    ("food_court", "Three teenagers head to the counter to load up on doughnuts.", "doughnuts"),
    ("mall", "Two students go to the food court to stock up on crisps and fizzy drinks.", "crisps"),
    ("brewery", "Five lads wander into the tap room to stock up on lager before kick-off.", "lager"),
    ("station", "Jolted out of a snooze on the bench, a commuter runs for platform 2.", "snooze"),
])
def test_food_drink_and_naps_are_no_place_to_refuse(read, world, prompt, word):
    reading = read(world, prompt)
    assert word not in reading.unknown_places
    assert reading.groups


# ---- guards: a room named for food or drink is still a place, and a missing room is still refused ----------

@pytest.mark.parametrize("world,prompt,refused", [
    ("mall", "Two visitors walk to the beer garden.", "beer garden"),
    ("museum", "A guard walks from the cafe to the wine cellar.", "wine cellar"),
])
def test_rooms_named_for_food_are_still_refused_when_missing(read, world, prompt, refused):
    assert refused in read(world, prompt).unknown_places


# ---- 2. an outing counted with "of" is that many people ---------------------------------------------------

@pytest.mark.parametrize("world,prompt,count", [
    ("office", "A leaving do of twelve heads to the kitchen.", 12),
    ("office", "A works outing of twenty gathers in the lobby.", 20),
    ("mall", "A birthday bash of ten troops out of the cinema.", 10),
    ("museum", "A school trip of thirty files into the great hall.", 30),
    ("station", "A works do of fifteen waits on platform 2.", 15),
    ("brewery", "A hen do of 8 stumbles into the tap room.", 8),
])
def test_an_outing_of_n_is_n_people(read, world, prompt, count):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == ("exact", count)


# ---- guards: an outing measured in time, and a party already known, keep their reading ------------------------

@pytest.mark.parametrize("world,prompt,counts", [
    ("museum", "After a trip of two hours, a man walks to the cafe.", [1]),
    ("museum", "A hen party of nine wanders into the cafe.", [9]),
    ("station", "A family of five hurries to platform 2.", [5]),
])
def test_outings_in_time_and_known_parties_keep_their_reading(read, world, prompt, counts):
    assert [g.count.value for g in read(world, prompt).groups] == counts
