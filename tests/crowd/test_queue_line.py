"""Which way a queue's line runs: straight out from the front of the thing served, whether the tree names
that thing or only its zone ("queue at security": the zone, served at a scanner's point)."""

from __future__ import annotations

import math

import pytest

from grove_tui.crowd.coordination import queue_line_direction
from grove_tui.navigation.grid import build_grid
from grove_tui.world import load_world


class GridFloor:
    def __init__(self, world):
        self.world = world
        self.grid = build_grid(world)

    def is_free(self, x: float, y: float) -> bool:
        return self.grid.is_free(x, y)


@pytest.mark.parametrize("world_name, zone", [("airport", "security_checkpoint"), ("hospital", "pharmacy"),
                                              ("station", "ticket_hall"), ("museum", "entrance_hall")])
def test_a_line_named_by_its_zone_runs_out_from_the_front_of_the_thing_served(world_name, zone):
    world = load_world(world_name)
    floor = GridFloor(world)
    for entity in world.zone(zone).entities:
        if "queue" not in entity.tags and "service" not in entity.tags:
            continue
        point = entity.interaction_point
        by_entity, _ = queue_line_direction(floor, entity.name, point, 0.6)
        by_zone, _ = queue_line_direction(floor, zone, point, 0.6)
        assert by_zone == by_entity, entity.name
        # away from the thing, not along its front
        cx = sum(p[0] for p in entity.footprint) / len(entity.footprint)
        cy = sum(p[1] for p in entity.footprint) / len(entity.footprint)
        away = (point[0] - cx, point[1] - cy)
        assert by_zone[0] * away[0] + by_zone[1] * away[1] > 0.3 * math.hypot(*away), entity.name
