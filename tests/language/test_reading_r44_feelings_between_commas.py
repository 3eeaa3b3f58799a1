"""Round 44: a feeling set apart between commas inside the clause ("stops, spellbound, and stares at the
robot") says how the one group looks at it, as a fronted or trailing feeling does."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,reaction", [
    ("museum", "A boy in the great hall stops, spellbound, and stares at the robot.", "Curious"),
    ("office", "Two interns put down their coffees, intrigued, to watch the robot.", "Curious"),
    ("museum", "A guard, wary, watches the robot from the cloakroom.", "Scared"),
])
def test_a_feeling_between_commas_colours_the_look(read, world, prompt, reaction):
    (g,) = read(world, prompt).groups
    assert (g.robot_interaction, g.robot_reaction) == ("look", reaction)
