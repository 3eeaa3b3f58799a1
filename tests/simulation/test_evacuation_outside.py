"""Nobody wanders outside uncounted: an evacuee pushed out through the exit is evacuated, anyone else
pushed out is held back in; spawns never sit on an exit."""

from __future__ import annotations

import numpy as np
import shapely

from grove_tui.generation.postprocess import SPAWN_EXIT_CLEARANCE, FreeSpace
from grove_tui.navigation.velocity_field import build_velocity_field
from helpers.hall import agent, simulate

LEAVE = '<FollowVelocityField exit="exit_door" field="group_0"/>'


def exit_field(hall, start):
    world, grid, planner = hall
    exit_point = world.roi("exit_door").point
    return build_velocity_field(grid, planner.plan(start, exit_point), exit_point, planner=planner)


def test_an_evacuee_already_outside_is_counted_through_the_exit(hall):
    # 1.2 m past the door line, beyond the exit point's radius: the case that went uncounted.
    sim = simulate(hall, [agent(1, (19.0, 6.0), group=0), agent(2, (10.0, 6.0), group=0)], [LEAVE, LEAVE],
                   fields={"group_0": exit_field(hall, (10.0, 6.0))})
    sim.crowd.pos[0] = (21.2, 6.0)  # shoved out by the crowd behind (a spawn outside would be moved in)
    sim.step()
    assert not sim.crowd.active[0] and sim.crowd.active[1]
    assert [(e.agent_id, e.kind, e.detail) for e in sim.events] == [(1, "evacuated", "exit_door")]
    assert sim.frame().counters.evacuated == 1


def test_anyone_else_pushed_outside_is_held_back_in(hall):
    """Only people whose task is to leave leave: someone else shoved over the exit's door line is put
    back inside at the door, still in the run (keep_inside), and it is said once."""
    world = hall[0]
    sim = simulate(hall, [agent(1, (19.0, 6.0))], ['<GoTo target="counter" x="2.2" y="6"/>'])
    sim.crowd.pos[0] = (21.0, 6.0)
    sim.step()
    assert sim.crowd.active[0]
    x, y = (float(v) for v in sim.crowd.pos[0])
    assert world.outline().contains(shapely.Point(x, y)) and x > 19.5  # back in at the door, not elsewhere
    sim.crowd.pos[0] = (21.0, 6.0)
    sim.step()
    assert [(e.kind, e.detail) for e in sim.events] == [("kept_in", "exit_door")]
    assert sim.frame().counters.evacuated == 0


def test_dense_evacuation_everyone_is_inside_or_counted(hall):
    """120 people packed 0.8 m apart push toward a 2 m exit: whoever is shoved past the exit point is
    counted, and at no time is an active agent more than a step past the building's outline."""
    world = hall[0]
    starts = [(3.0 + 0.8 * (i % 20), 1.5 + 0.8 * (i // 20)) for i in range(120)]
    sim = simulate(hall, [agent(i + 1, p, group=0, max_vel=1.8) for i, p in enumerate(starts)], [LEAVE] * 120,
                   fields={"group_0": exit_field(hall, (10.0, 4.0))})
    building = world.outline()
    worst_outside = 0.0
    while sim.time < 120.0 and sim.crowd.active[:120].any():
        sim.step()
        active = sim.crowd.active[:120]
        pos = sim.crowd.pos[:120][active]
        if len(pos):
            distances = shapely.distance(building, shapely.points(pos))
            worst_outside = max(worst_outside, float(distances.max()))
    evacuated = [e.agent_id for e in sim.events if e.kind == "evacuated"]
    still_in = np.flatnonzero(sim.crowd.active[:120])
    assert len(set(evacuated)) == len(evacuated)  # each person counted once
    assert len(evacuated) + len(still_in) == 120
    assert len(evacuated) == 120, f"{len(still_in)} people did not get out in 120 s"
    # Between two behavior ticks (0.1 s) an agent moves at most a few tens of centimetres.
    assert worst_outside < 0.5, worst_outside
    assert not [e for e in sim.events if e.kind == "left_building"]


def test_spawns_keep_clear_of_exits(hall):
    world, grid, _ = hall
    space = FreeSpace(world, grid)
    exit_xy = np.array(world.find("exit_door").position)
    points = np.array(space.sample("hall", 150, np.random.default_rng(1), 0.6, key="spawn"))
    assert np.hypot(*(points - exit_xy).T).min() >= SPAWN_EXIT_CLEARANCE
