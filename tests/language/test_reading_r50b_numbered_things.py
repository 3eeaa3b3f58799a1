"""Round 50 (r50b): a numbered thing inside a zone, said by its number in a scene clause before the
subject, is where they start, not its zone (numbered_things.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("vaccination_centre", "Once they are done in booth four, two nurses head over to the observation desk.",
     "booth_4", "observation_desk"),
    ("vaccination_centre", "Having had her jab in booth 2, an old lady goes to the observation area.",
     "booth_2", "observation_area"),
    ("tennis_club", "After their match on court seven, two players walk to the bar.", "court_7", "bar_lounge"),
])
def test_a_numbered_thing_said_before_the_subject_is_where_they_start(read, world, prompt, start, destination):
    (group,) = read(world, prompt).groups
    assert (group.start, group.destination) == (start, destination)
