""""form" for "from", "too" for "to" and "there" for "their" before a place read back as meant, only
where the sentence lacks the right word (language/homophone_slips.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "Three nurses walk form there ward too the cafeteria.", "ward_a", "cafeteria"),
    ("museum", "Two guides stroll form the cafe too the entrance hall.", "cafe", "entrance_hall"),
    ("museum", "Two guides stroll from the cafe too the entrance hall.", "cafe", "entrance_hall"),
])
def test_slips_of_from_to_and_their_read_as_meant(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)


def test_a_right_too_and_there_are_left_alone():
    from grove_tui.language.homophone_slips import with_homophone_slips
    from grove_tui.language.reading import place_index
    from grove_tui.world import load_world

    index = place_index(load_world("museum"))
    text = "A man walks to the cafe, and his wife goes there too."
    assert with_homophone_slips(text, index) == text


def test_people_who_form_a_line_still_form_it(read):
    (g,) = read("museum", "Around thirty visitors form a long line at the cafe.").groups
    assert g.intent == "queue"
