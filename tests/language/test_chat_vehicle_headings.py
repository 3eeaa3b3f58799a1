"""A vehicle's news before a chat's colon or dash ("coach running late:", "train delayed -") names
nobody: only the people after it are groups (language/chat_headings.py)."""

from __future__ import annotations

import pytest

CASES = [
    ("stadium", "coach delayed - 8 fans waitin @ the north stand", [("fan", 8)]),
    ("airport", "Shuttle bus running late: 10 ppl @ gate A1", [("person", 10)]),
    ("station", "the 9:15 train delayed: 12 ppl waitin on platform 2, guard in ticket office",
     [("person", 12), ("guard", 1)]),
]


@pytest.mark.parametrize("world,prompt,groups", CASES)
def test_the_heading_is_nobody(read, world, prompt, groups):
    read_groups = read(world, prompt).groups
    assert [(g.label, g.count.value) for g in read_groups] == groups
    assert all(g.intent == "wait" for g in read_groups)


def test_a_coach_in_a_sentence_is_still_a_person(read):
    (coach,) = read("stadium", "The coach walks to the north stand.").groups
    assert coach.label == "coach"
    (coach,) = read("stadium", "The coach is late, so he runs to the north stand.").groups
    assert coach.label == "coach"
