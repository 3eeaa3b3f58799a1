"""Count classes of round 39, each with sentences of its own over at least two worlds (none from the
understanding sets): a crowd said by a collective the reader did not know ("a swarm of", "a stream of",
"a gaggle of", "a herd of", "a trickle of" people) is one vague crowd of those people, not one person
named "a swarm"; a count set off by commas after it still counts them."""

from __future__ import annotations

import pytest


# ---- 1. a crowd said by a collective noun of motion or of animals ------------------------------------

@pytest.mark.parametrize("world,prompt,low,high", [
    ("mall", "A swarm of teenagers mills around the fountain.", 15, 30),
    ("airport", "A stream of passengers heads from the arrivals hall to the taxi rank.", 10, 25),
    ("trampoline_park", "A gaggle of teenagers hangs around the foam pit.", 5, 12),
    ("zoo", "A herd of schoolchildren stampedes towards the penguin pool.", 8, 20),
    ("hospital", "A trickle of visitors drifts into the cafeteria.", 3, 8),
    ("museum", "The robot squeezes past a flock of pensioners in the great hall.", 8, 20),
    ("station", "A mob of football fans waits on platform 2.", 8, 20),
])
def test_a_crowd_said_by_an_unknown_collective_is_one_vague_crowd(read, world, prompt, low, high):
    (group,) = read(world, prompt).groups
    assert group.count.kind == "vague"
    assert (group.count.low, group.count.high) == (low, high)


@pytest.mark.parametrize("world,prompt,value", [
    ("station", "A stream of commuters, about forty of them, hurries off platform 2 towards the gates.", 40),
    ("hospital", "A herd of visitors, roughly a dozen of them, wanders into the cafeteria.", 12),
    ("mall", "A swarm of shoppers, roughly fifty of them, pours into the food court.", 50),
    ("ferry_terminal", "A gaggle of students, about a dozen of them, waits by passport control.", 12),
])
def test_a_count_after_an_unknown_collective_counts_its_members(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == ("approximate", value)


# ---- guards: the collectives the reader knew keep their reading --------------------------------------

@pytest.mark.parametrize("world,prompt,kind,low,high", [
    ("museum", "A horde of schoolkids mills under the whale skeleton.", "vague", 15, 30),
    ("mall", "A crowd of shoppers waits by the fountain.", "vague", 15, 30),
    ("airport", "A coachload of pensioners walks to the check-in hall.", "vague", 30, 50),  # a number nobody said
    ("hospital", "A group of visitors waits in the cafeteria.", "implied", 3, 5),
])
def test_known_collectives_keep_their_count(read, world, prompt, kind, low, high):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.low, group.count.high) == (kind, low, high)


# ---- 2. people said by an animal idiom, or by a plural age, are counted ------------------------------

@pytest.mark.parametrize("world,prompt,kind,value", [
    ("mall", "Roughly 40 early birds wait outside the main entrance.", "approximate", 40),
    ("climbing_centre", "Three gym rats head over to the changing rooms.", "exact", 3),
    ("hotel", "About a dozen party animals stagger out of the bar.", "approximate", 12),
    ("station", "Two night birds doze on the benches on platform 2.", "exact", 2),
    ("trampoline_park", "Half a dozen seven-year-olds scramble out of the foam pit.", "exact", 6),
    ("museum", "Four ten-year-olds climb onto the benches in the great hall.", "exact", 4),
    ("zoo", "Eight 6-year-olds clamber up to the penguin pool.", "exact", 8),
])
def test_people_said_by_an_idiom_or_an_age_are_counted(read, world, prompt, kind, value):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == (kind, value)


@pytest.mark.parametrize("world,prompt", [
    ("mall", "Two pigeons wait by the fountain."),
    ("residential", "The cat sleeps on the sofa."),
    ("zoo", "A few ducks paddle in the pond."),
])
def test_animals_alone_are_no_people(read, world, prompt):
    (group,) = read(world, prompt).groups
    assert group.count.kind == "vague"
