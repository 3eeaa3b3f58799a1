"""Round 54 (r54b): a fronted stay spent handling a thing ("After twenty minutes struggling with the paint
frame, ...") says where the people were all that while, so the thing itself, not its room, is their start
(language/participle_stays.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start", [
    ("fire_station", "After a quarter of an hour tinkering with the breathing apparatus sets, a firefighter walks "
     "to the showers.", "ba_sets"),
    ("playhouse", "After twenty minutes struggling with the paint frame, two stagehands head off to the scene dock "
     "doors.", "paint_frame"),
    ("nightclub", "After twenty minutes messing about with the ID scanner, a bouncer walks to the cloakroom.",
     "id_scanner"),
])
def test_a_thing_handled_in_a_fronted_stay_is_the_start(read, world, prompt, start):
    (group,) = read(world, prompt).groups
    assert group.start == start
