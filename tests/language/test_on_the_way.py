"""Being on one's way is no place: "on her way from X to Y" starts at X ("way" is no door called
"the way in"), "on their way to Y" goes to Y (on_the_way)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, start, destination", [
    (W + "student_union.yaml", "A fresher clutches a stack of flyers on her way from the union shop to the main hall.",
     "union_shop", "main_hall"),
    (W + "garden_centre.yaml", "Two pensioners dawdle on their way from the cafe to the tills.", "cafe", "tills"),
    (W + "diy_store.yaml", "A builder grumbles on his way to the trade counter.", None, "trade_counter"),
])
def test_on_ones_way_is_going_no_place(world, sentence, start, destination):
    group = read_prompt(sentence, load_world(world)).groups[0]
    assert (group.start, group.destination) == (start, destination)
