"""Round 49 (r49b): one person no list names, alone in a second clause after "and a" ("..., and a
roadie waits by the bar"), is a second group, and "hangs about" is waiting
(language/and_a_person.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("hotel", "Two guests walk to the lobby, and a roadie waits by the bar."),
    ("hotel", "Two guests walk to the lobby, and a roadie hangs around by the bar."),
    ("research_lab_building", "Around 4pm a trio of grad students lug dewars from goods-in to the cold room, and "
     "a postdoc hangs about by the espresso machine."),
])
def test_a_lone_unlisted_person_after_and_a_is_a_second_group(read, world, prompt):
    groups = read(world, prompt).groups
    assert len(groups) == 2
    assert groups[1].count.value == 1 and groups[1].intent == "wait"


def test_hanging_about_is_waiting(read):
    (group,) = read("hotel", "A roadie hangs about by the bar.").groups
    assert group.count.value == 1 and group.intent == "wait" and group.location == "bar"
