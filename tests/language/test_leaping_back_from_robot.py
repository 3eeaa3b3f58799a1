"""Leaping or springing back(wards) away from the robot is avoiding it, whatever word of direction
stands between the verb and "away from" (language/robot_shrinking.py); a fronted "Taken by surprise,"
or "Caught unawares," makes it Surprised (language/fronted_surprise.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,reaction", [
    ("museum", "A small child springs backwards away from the robot.", "Scared"),
    ("hospital", "Caught by surprise, a porter by the lifts jumps backward away from the robot.", "Surprised"),
    ("station", "Taken by surprise, a commuter on platform 2 hops hastily clear of the robot.", "Surprised"),
])
def test_leaping_back_away_from_the_robot_avoids_it(read, world, prompt, reaction):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.robot_interaction, g.robot_reaction) == ("robot", "avoid", reaction)
