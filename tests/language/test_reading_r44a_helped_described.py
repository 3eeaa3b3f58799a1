"""A person helped along, described by a word the small parser tags as a name before another describing
word ("helps a tipsy young guest from ..."): a lower-case word is no name, and the person is still the
one helped, a second group that follows (language/people.py, person_head)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,label,start,destination", [
    ("station", "A guard helps a tipsy elderly man from the cafe to platform 2.", "man", "cafe", "platform_2"),
    ("hotel", "The night porter helps a tipsy young guest from the bar to the lifts.", "guest", "bar", "lift_lobby"),
    ("hospital", "A porter helps a tipsy young visitor from the cafeteria to the main entrance.", "visitor",
     "cafeteria", "main_entrance"),
    ("university", "A porter helps a tipsy second-year from the bar back to the library.", "student", None, None),
])
def test_a_described_person_helped_along_follows(read, world, prompt, label, start, destination):
    helper, helped = read(world, prompt).groups
    assert (helped.label, helped.intent, helped.follows) == (label, "follow", helper.who)
    if start is not None:
        assert (helper.start, helper.destination, helped.destination) == (start, destination, destination)
