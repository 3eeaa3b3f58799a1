"""Group and count classes of round 36, each with sentences of its own over at least two worlds (none
from the understanding sets): a plural no list names, counted by "a dozen" with kind words between
("a dozen rugby juniors"), or going by a verb the parser takes for a name ("juniors clatter from ..."); a
person taken along by a verb the parser tags a name or a noun ("a pair of guards march a detained teenager
...", "a porter wheels frail Mrs Patel ...") is a second group that follows the first."""

from __future__ import annotations

import pytest


# ---- 1. "a dozen" and kind words before a plural no list names -------------------------------------------

@pytest.mark.parametrize("world,prompt,value", [
    ("hospital", "A dozen rugby juniors clatter from the cafeteria to the main entrance.", 12),
    ("station", "A dozen cub scouts clatter from the ticket hall to platform 2.", 12),
    ("airport", "A dozen rugby juniors walk from check-in to the food court.", 12),
    ("museum", "Half a dozen chess juniors clatter into the ancient Egypt gallery.", 6),
    ("mall", "A dozen chess juniors clatter into the food court.", 12),
    ("ice_rink", "A dozen cub scouts walk from the café to the west gate.", 12),
    ("hotel", "A dozen hockey juniors walk from the lobby to the restaurant.", 12),
])
def test_a_dozen_of_an_unlisted_kind_is_twelve(read, world, prompt, value):
    (g,) = read(world, prompt).groups
    assert (g.count.kind, g.count.value) == ("exact", value)


# ---- 2. taken along by a verb the parser tags a name or a noun -------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "A porter wheels frail Mrs Patel from the cafeteria to ward B.", "cafeteria", "ward_b"),
    ("hotel", "A porter wheels frail Mr Hale from the lobby to the restaurant.", "lobby", "restaurant"),
    ("museum", "A curator wheels frail Mrs Okafor from the entrance hall to the cafe.", "entrance_hall", "cafe"),
    ("police_station", "A pair of constables march a detained shoplifter from custody into interview room one.",
     "custody_suite", "interview_room_1"),
    ("mall", "A pair of guards march a detained teenager from the food court to the main entrance.",
     "food_court", "main_entrance"),
    ("airport", "A pair of officers march a detained traveller from check-in to the security check.",
     "check_in_hall", "security_checkpoint"),
])
def test_someone_taken_along_by_a_mistagged_verb_follows(read, world, prompt, start, destination):
    mover, moved = read(world, prompt).groups
    assert moved.intent == "follow" and moved.follows == mover.who
    assert (mover.start, mover.destination) == (start, destination)
    assert (moved.start, moved.destination) == (start, destination)


# ---- guards: readings that must stay as they were --------------------------------------------------------

@pytest.mark.parametrize("world,prompt,value", [
    ("ice_rink", "Twelve hockey juniors walk from the café to the west gate.", 12),
    ("mall", "A dozen teenagers clatter from the food court to the main entrance.", 12),
    ("mall", "Two chess juniors walk to the food court.", 2),
    ("mall", "Thirty under-11 footballers clatter into the food court.", 30),
])
def test_counted_kinds_keep_their_count(read, world, prompt, value):
    (g,) = read(world, prompt).groups
    assert g.count.value == value


@pytest.mark.parametrize("world,prompt,groups", [
    ("mall", "A guard walks elderly Mr Grant from the food court to the main entrance.", 2),
    ("hospital", "A porter wheels a trolley from the cafeteria to ward B.", 1),
    ("mall", "A pair of guards march to the main entrance.", 1),
    ("station", "A porter wheels luggage from the ticket hall to platform 2.", 1),
    ("museum", "A porter wheels old Mr Dobbs from the entrance hall to the cafe.", 2),
])
def test_taking_along_keeps_its_groups(read, world, prompt, groups):
    assert len(read(world, prompt).groups) == groups
