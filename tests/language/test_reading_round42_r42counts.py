"""Count classes of round 42, each with sentences of its own over at least two worlds (none from the
understanding sets):
1. a rough count ("sixty-odd", "30-odd", "twenty or so", "forty-ish") keeps its number where the
   phrase starts earlier ("through the sixty-odd backpackers", "get the 30-odd parents in X out") or
   where a number word opens the sentence before a describing aside ("Twenty-ish racers, helmets
   tucked under their arms, are queuing ...").
2. a count in apposition after a collective keeps its number when its people are named by a kind noun
   and a plural the reader lists nowhere ("the birthday crowd, nine cub scouts, ...", "the group, ten
   brass majorettes, ..."): the collective is that many, not its usual size."""

from __future__ import annotations

import pytest


# ---- 1. rough counts keep their number ----------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,value", [
    ("airport", "The robot is threading through the eighty-odd passengers who are milling about.", 80),
    ("airport", "The robot is threading through the sixty-odd travellers who are milling about.", 60),
    ("food_court", "The robot is threading through the thirty-odd diners who are queuing at the noodle bar.", 30),
    ("swimming_baths", "Get the forty-odd parents in the spectator gallery out through the fire exit.", 40),
    ("hospital", "The robot is threading through the twenty or so visitors who are milling about.", 20),
    ("mall", "The robot is threading through the thirty or so shoppers who are milling about.", 30),
    ("karting_centre", "Twenty-ish racers, helmets tucked under their arms, are queuing at the track.", 20),
    ("museum", "Twenty-ish sketchers, pads tucked under their arms, are waiting in the foyer.", 20),
    ("office", "Fifteen-ish temps, badges clipped to their collars, are waiting in the lobby.", 15),
])
def test_rough_counts_keep_their_number(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == ("approximate", value)


# ---- guards: counts the reader already read --------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,kind,value", [
    ("airport", "Sixty-odd backpackers mill about.", "approximate", 60),
    ("office", "The robot guides the thirty-odd visitors to the kitchen.", "approximate", 30),
    ("hospital", "The robot weaves through the forty-odd visitors who are crowding the cafeteria.", "approximate", 40),
    ("airport", "The robot weaves through the twenty backpackers who are milling about.", "exact", 20),
    ("mall", "Thirty-ish skaters, boards tucked under their arms, are waiting by the fountain.", "approximate", 30),
])
def test_counts_already_read_stay(read, world, prompt, kind, value):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == (kind, value)


# ---- 2. a kind noun before a counted plural, in apposition ----------------------------------------------

@pytest.mark.parametrize("world,prompt,value", [
    ("karting_centre", "The birthday crowd, nine cub scouts, are eating pizza in the café.", 9),
    ("karting_centre", "The crowd, eight band roadies, are waiting in the café.", 8),
    ("hospital", "The party, six cub scouts, wait in the cafeteria.", 6),
    ("hospital", "The group, eight church bellringers, wait in the cafeteria.", 8),
    ("mall", "The group, ten brass majorettes, wait by the fountain.", 10),
    ("office", "The party, nine cub scouts, are waiting in the lobby.", 9),
])
def test_apposed_count_of_a_kind_and_plural(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == ("exact", value)


@pytest.mark.parametrize("world,prompt,value", [
    ("airport", "Twelve hockey players, sticks over their shoulders, queue at security.", 12),
    ("office", "The party, six hockey cheerleaders, wait in the lobby.", 6),
    ("museum", "Nine cub scouts wait in the foyer.", 9),
    ("station", "The team, seven rugby players, wait at the ticket office.", 7),
])
def test_counted_kinds_already_read_stay(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == ("exact", value)


@pytest.mark.parametrize("world,prompt", [
    ("office", "Nine ticket machines beep in the lobby."),
    ("hospital", "Four vending machines hum in the cafeteria."),
])
def test_counted_things_stay_no_people(read, world, prompt):
    assert all(g.count.kind == "vague" for g in read(world, prompt).groups)
