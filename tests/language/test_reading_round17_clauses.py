"""Clause classes of round 17, with sentences of their own over several worlds (none from the
understanding sets): people taken somewhere by someone said in the passive ("is taken to X by Z") are
read as the active is, the taker walking there and the taken following; an activity said by a noun
after a light verb ("have a natter", "swap stories") is conversing."""

from __future__ import annotations

import pytest

# ---- A. passive escort: the taker walks, the taken follow ------------------------------------------


@pytest.mark.parametrize("world,prompt,taker,taken,destination", [
    ("hospital", "An elderly patient is wheeled to radiology by a porter", "porter", "patient", "radiology"),
    ("hospital", "A child is carried to the cafeteria by her dad", "dad", "child", "cafeteria"),
    ("primary_school", "Two reception children are walked to the hall by a teaching assistant",
     "assistant", "child", "school_hall"),
    ("primary_school", "A pupil with a grazed knee is led to the medical room by a dinner lady",
     "dinner lady", "pupil", "medical_room"),
    ("station", "A lost child is taken to the ticket office by a guard", "guard", "child", None),
    ("museum", "A school group is shown to the cafe by a guide", "guide", "group", None),
])
def test_people_taken_in_the_passive_follow_their_taker(read, world, prompt, taker, taken, destination):
    groups = read(world, prompt).groups
    leader = next(g for g in groups if g.intent == "walk")  # said second, read after the taken (round 18)
    follower = next(g for g in groups if g.intent == "follow")
    assert follower.label == taken
    if taker is not None:
        assert leader.label == taker
    if destination is not None:
        assert leader.destination == destination


# ---- B. an activity said by a noun -------------------------------------------------------------------


@pytest.mark.parametrize("world,prompt,intent", [
    ("warehouse", "two pickers have a natter by the loading bay", "converse"),
    ("hospital", "two nurses have a quick chinwag at reception", "converse"),
    ("office", "Three engineers swap stories in the kitchen", "converse"),
    ("hospital", "a porter and a cleaner compare notes in the corridor", "converse"),
    ("station", "Two commuters have a gossip on platform 1", "converse"),
])
def test_an_activity_said_by_a_noun(read, world, prompt, intent):
    assert read(world, prompt).groups[0].intent == intent
