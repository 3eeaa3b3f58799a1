"""What people hide behind or under ("ducks behind the curtains", "crouches under the duvet"): a thing
one shelters by, nothing to refuse when the world lacks it; a room the world lacks is still refused.
Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt", [
    ("office", "When the robot rolls in, a nervous intern hides behind a cardboard box."),
    ("hotel", "A small boy crouches under the bedspread as the robot comes into the lobby."),
    ("museum", "Scared, a little girl ducks behind her dad's umbrella as the robot approaches."),
])
def test_a_thing_hidden_behind_is_not_refused(read, world, prompt):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    assert reading.groups


def test_a_room_the_world_lacks_is_still_refused(read):
    reading = read("office", "A nervous intern hides behind the boiler room.")
    assert reading.unknown_places != ()
