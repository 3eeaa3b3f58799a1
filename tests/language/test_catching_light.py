"""A thing that "catches light" (the British way of saying it catches fire) is a hazard: people taken or
led out after it evacuate. "catches the light" is a shine, no hazard. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, goal", [
    ("hospital", "A toaster in the cafeteria catches light and the diners are taken out via the main entrance.",
     "cafeteria", "main_entrance"),
    ("hospital", "The curtains in the waiting room caught light, so the twelve visitors there are led out through "
     "the main entrance.", "main_waiting_room", "main_entrance"),
    ("office", "A printer catches light in the kitchen and the five interns there are taken out through the fire exit.",
     "kitchen", "fire_exit"),
])
def test_people_taken_out_after_a_thing_catches_light_evacuate(read, world, prompt, start, goal):
    group = read(world, prompt).groups[0]
    assert group.intent == "evacuate"
    assert (group.start, group.destination) == (start, goal)


def test_catching_the_light_is_no_hazard(read):
    group = read("office", "Two interns stand by the window where the sun catches the light.").groups[0]
    assert group.intent != "evacuate"
