"""Count classes of round 38, each with sentences of its own over at least two worlds (none from the
understanding sets): the people a sentence names only by a word the reader does not know as a person,
whose count the subject still says: one ("the locum comes over", "a temp who started today waits"), a
pair ("a pair of brownies ... gape"), or an approximate number or range ("roughly 40 squaddies wait",
"three or four locums in the cafeteria"); a vague crowd was only a guess."""

from __future__ import annotations

import pytest


# ---- 1. one person or a pair named by an unknown word ------------------------------------------------

@pytest.mark.parametrize("world,prompt,value", [
    ("hospital", "As the ward round begins, the locum comes out of the cafeteria and over to ward B.", 1),
    ("office", "A temp who started this morning waits by the kitchen for an hour.", 1),
    ("trampoline_park", "Grinning, a pair of jumpers by the foam pit wave at the robot.", 2),
    ("fire_station", "A squaddie on a visit wanders round the appliance bay.", 1),
    ("mall", "The bigwig from head office strides over to the fountain.", 1),
    ("hospital", "A couple of would-be donors in the cafeteria stare at the robot.", 2),
])
def test_one_or_two_people_by_an_unknown_word_are_counted(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == ("exact", value)


# ---- 2. an approximate number or a range of people by an unknown word --------------------------------

@pytest.mark.parametrize("world,prompt,kind,value,low,high", [
    ("hospital", "Roughly 15 would-be donors wait in the cafeteria.", "approximate", 15, 12, 18),
    ("trampoline_park", "About 40 jumpers pile into the foam pit.", "approximate", 40, 32, 48),
    ("station", "Five or six couch potatoes on platform 2.", None, None, 5, 6),
    ("trampoline_park", "Five or six sleepy in-laws by the foam pit.", None, None, 5, 6),
    ("hospital", "Four or five would-be donors in the cafeteria.", None, None, 4, 5),
    ("museum", "Half a dozen sleepy in-laws in the great hall.", "exact", 6, 6, 6),
])
def test_an_approximate_count_by_an_unknown_word_is_kept(read, world, prompt, kind, value, low, high):
    (group,) = read(world, prompt).groups
    assert (group.count.low, group.count.high) == (low, high)
    if kind is not None:
        assert (group.count.kind, group.count.value) == (kind, value)


# ---- guards: sentences with no people keep their vague crowd -----------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("mall", "The fountain sparkles near the main entrance."),
    ("mall", "A busy afternoon in the food court."),
    ("hospital", "The lift breaks down on ward B."),
    ("museum", "The robot crosses the great hall."),
    ("office", "Two printers hum in the open office."),
    # a thing at rest, said with a verb people share: no person without a cue (a pronoun, "who", an ending)
    ("residential", "An old armchair sits by the living room window."),
    ("museum", "A brass plaque hangs beside the entrance."),
])
def test_a_sentence_naming_no_people_keeps_a_vague_crowd(read, world, prompt):
    (group,) = read(world, prompt).groups
    assert group.count.kind == "vague"
