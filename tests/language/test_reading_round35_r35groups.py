"""Group and count classes of round 35, each with sentences of its own over at least two worlds (none
from the understanding sets): a member collective sized with "of" and a number ("the cast of 14",
"a troupe of eight") is so many people; a part of a named team or watch ("Six of Blue Watch") is so
many people; a stampede, a hurtle, a careen is a fast pace."""

from __future__ import annotations

import pytest


# ---- 1. a member collective sized with "of" and a number ------------------------------------------------

@pytest.mark.parametrize("world,prompt,value", [
    ("playhouse", "The cast of 9 walk from the stage to the green room.", 9),
    ("hospital", "A troupe of eight walk from the cafeteria to the main entrance.", 8),
    ("mall", "The ensemble of twelve waits by the fountain.", 12),
    ("concert_venue", "The band of five wander to the bar.", 5),
    ("hotel", "The cast of 14 wait in the lobby.", 14),
])
def test_a_collective_sized_with_of_is_so_many_people(read, world, prompt, value):
    (g,) = read(world, prompt).groups
    assert (g.count.kind, g.count.value) == ("exact", value)


# ---- 2. a part of a named team, watch or crew ------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,value", [
    ("fire_station", "Four of Red Watch stroll from the mess to the appliance bay.", 4),
    ("mall", "Three of Team Kestrel wait by the fountain.", 3),
    ("hospital", "Two of Green Team walk to the cafeteria.", 2),
    ("stadium", "Five of Team Falcon hurry to the west gate.", 5),
])
def test_a_part_of_a_named_team_is_so_many_people(read, world, prompt, value):
    groups = read(world, prompt).groups
    assert [(g.count.kind, g.count.value) for g in groups] == [("exact", value)]


# ---- 3. a stampede is a fast pace -------------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("mall", "Thirty shoppers stampede from the main entrance into the food court."),
    ("hospital", "Two porters hurtle from the cafeteria to the main entrance."),
    ("stadium", "A dozen fans careen towards the west gate."),
    ("supermarket", "Five kids pelt down to the tills."),
])
def test_a_stampede_is_fast(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.pace == "fast"


# ---- 4. someone moved along, said with an adjective only people are ------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("playhouse", "An usher wheels an elderly patron from the foyer to the studio.", "foyer", "studio_theatre"),
    ("zoo", "A keeper wheels a disabled patron to the cafe.", None, "cafe"),
    ("hospital", "A porter wheels a frail patron from the cafeteria to the main entrance.", "cafeteria", "main_entrance"),
    ("hotel", "A porter wheels an elderly novice from the lobby to the lift.", "lobby", "lift_lobby"),
    ("hotel", "A porter wheels a frail alumnus from the lobby to the lift.", "lobby", "lift_lobby"),
    ("mall", "A guard pushes an elderly heir to the food court.", None, "food_court"),
])
def test_someone_described_and_moved_along_is_a_person(read, world, prompt, start, destination):
    mover, moved = read(world, prompt).groups
    assert (mover.count.value, moved.count.value) == (1, 1)
    assert moved.intent == "follow"
    assert (moved.start, moved.destination) == (start, destination)


# ---- guards: readings that must stay as they were --------------------------------------------------------

@pytest.mark.parametrize("world,prompt,value", [
    ("mall", "A team of 5 cleaners walk to the food court.", 5),
    ("fire_station", "Four of the crew walk to the rescue pump.", 4),
    ("playhouse", "A crew of 6 walk to the get-in doors.", 6),
    ("hotel", "A gang of 7 stroll from the lobby to the restaurant.", 7),
    ("mall", "A choir of twenty waits by the fountain.", 20),
])
def test_a_collective_with_its_people_said_keeps_its_count(read, world, prompt, value):
    (g,) = read(world, prompt).groups
    assert g.count.value == value


@pytest.mark.parametrize("world,prompt", [
    ("mall", "The nurse in charge walks to the food court."),
    ("hospital", "A porter walks to the cafeteria."),
])
def test_a_plain_walk_keeps_its_pace(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.pace == "normal"


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "A porter wheels a heavy trolley from the ward to the cafeteria."),
    ("hospital", "A porter wheels an empty bed from the ward to the cafeteria."),
    ("supermarket", "A cleaner pushes a battered cart to the tills."),
    ("vet_hospital", "A nurse carries a sleepy terrier from the foyer into consult 3."),
    ("zoo", "A keeper carries a sleepy lemur to the cafe."),
])
def test_a_thing_moved_along_is_no_person(read, world, prompt):
    assert len(read(world, prompt).groups) == 1
