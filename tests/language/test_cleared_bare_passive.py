"""People said to be cleared or evacuated with no particle, the clause ending there ("everyone in the
reading room is evacuated", "the diners are quickly cleared"), evacuate from where they are
(language/cleared_passive.py). "cleared to board" is leave to go, not an emptying."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start", [
    ("library", "A fire alarm goes off and everyone in the reading room, about thirty readers, is evacuated.",
     "reading_room"),
    ("mall", "After a gas leak, the thirty diners in the food court are quickly cleared.", "food_court"),
    ("hospital", "The patients in the main waiting room are cleared after a power cut.", "main_waiting_room"),
])
def test_people_cleared_with_no_particle_evacuate_from_where_they_are(read, world, prompt, start):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.start) == ("evacuate", start)


def test_cleared_to_board_is_no_evacuation(read):
    (g,) = read("mall", "The twenty people at the gate are cleared to board.").groups
    assert g.intent != "evacuate"
