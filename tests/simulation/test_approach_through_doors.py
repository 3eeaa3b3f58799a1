"""Approaching someone in the next room goes through the door, not to a point in the wall beside it.

The point `closest_dist` short of the other person, on the straight line from the approacher, can lie in
the wall between two rooms; walking to the planner's nearest free point on the near side of that wall
left the approacher standing against it for the whole reaction."""

from __future__ import annotations

import numpy as np
import pytest

from grove_tui.navigation.grid import build_grid
from grove_tui.navigation.theta_star import ThetaStarPlanner
from grove_tui.world import parse_world
from helpers.hall import agent, simulate

TWO_ROOMS = """
name: two_rooms
description: Two 10 m x 12 m rooms side by side, joined by a 1.4 m door in the middle of the wall between.
zones:
  - name: west_room
    type: room
    description: The west room.
    boundary: [[0, 0], [10, 0], [10, 12], [0, 12]]
    doors:
      - {name: middle_door, position: [10, 6], width: 1.4, leads_to: east_room}
  - name: east_room
    type: room
    description: The east room.
    boundary: [[10, 0], [20, 0], [20, 12], [10, 12]]
    doors:
      - {name: exit_door, position: [20, 6], width: 2.0, leads_to: outside, exit: true}
"""


@pytest.fixture(scope="module")
def two_rooms():
    world, problems = parse_world(TWO_ROOMS, "two_rooms.yaml")
    assert not problems
    grid = build_grid(world)
    return world, grid, ThetaStarPlanner(grid)


@pytest.mark.parametrize("approacher, other", [((3.0, 10.0), (10.7, 2.0)), ((4.0, 1.5), (10.8, 9.5))])
def test_approach_agent_goes_round_through_the_door(two_rooms, approacher, other):
    bodies = ['<ApproachAgent target_agent_id="2" closest_dist="0.8" max_vel="1.2" duration="40"/>',
              '<StopAndWaitTimerAction wait_duration="60"/>']
    sim = simulate(two_rooms, [agent(1, approacher), agent(2, other)], bodies)
    gaps = []
    while sim.time < 30.0:
        sim.step()
        gaps.append(float(np.hypot(*(sim.crowd.pos[0] - sim.crowd.pos[1]))))
    assert sim.crowd.pos[0, 0] > 10.0, "the approacher never went through the door into the east room"
    assert min(gaps) < 1.3
