"""A room said by what is done there in words the meaning model does not know as that room's (issue 29):
"the room where clay is wedged" is the one whose description says "wedging". Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, goal", [
    ("pottery_studio", "Two members walk from the tea room to the room where clay is wedged.", "handbuilding_room"),
    ("art_school", "Three second-years head from the library to the room where photos are developed.", "darkroom"),
])
def test_the_room_where_it_is_done_is_the_one_whose_words_say_it(read, world, prompt, goal):
    assert read(world, prompt).groups[0].destination == goal
