"""A word of anger or low mood set before the subject ("Livid, an old man ...", "Weary, two guards ...") is
no one called so: one group, the feeling read from the prompt (language/fronted_feelings.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count,reaction", [
    ("museum", "Livid, an old man strides over to the robot and hammers on its lid.", 1, "Threatening"),
    ("hotel", "Fuming, a guest marches up to the robot and thumps its screen.", 1, "Threatening"),
    ("station", "Weary, two guards trudge to the ticket office.", 2, None),
    ("mall", "Grumpy, a toddler sits on the floor by the escalator.", 1, None),
])
def test_fronted_mood_is_no_person(read, world, prompt, count, reaction):
    reading = read(world, prompt)
    (group,) = reading.groups
    assert group.count.value == count
    assert group.robot_reaction == reaction
