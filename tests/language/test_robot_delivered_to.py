"""Round 57 (r57c): "the robot <carries> something out to X, who is <doing> in Y" puts X at Y and the robot
goes to Y (language/robot_deliveries.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,place", [
    ("residential", "The robot carries a tray of biscuits from the kitchen over to Grandad, who is dozing in the living room.",
     "living_room"),
    ("hotel", "The robot takes a parcel from the lobby across to the receptionist, who is sorting keys at the reception desk.",
     None),
])
def test_the_person_is_where_the_robot_goes(read, world, prompt, place):
    reading = read(world, prompt)
    assert reading.robot is not None and reading.robot.destination is not None
    located = [g.location for g in reading.groups if g.location is not None]
    assert located and located[-1] == reading.robot.destination
    if place is not None:
        assert reading.robot.destination == place
