"""Issue 19: people leave only after crossing the door line, through the opening, never while still inside."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from grove_tui.navigation.velocity_field import build_velocity_field
from helpers.hall import agent, simulate

LEAVE = '<FollowVelocityField exit="exit_door" field="group_0"/>'


def test_nobody_is_removed_before_crossing_the_door_line(hall):
    world, grid, planner = hall
    exit_point = world.roi("exit_door").point
    starts = [(12.0 + 1.0 * (i % 6), 3.0 + 1.0 * (i // 6)) for i in range(36)]
    field = build_velocity_field(grid, planner.plan((14.0, 6.0), exit_point), exit_point, planner=planner)
    sim = simulate(hall, [agent(i + 1, p, group=0, radius=0.25) for i, p in enumerate(starts)], [LEAVE] * 36,
                   fields={"group_0": field})
    building = world.outline()
    removed_at: dict[int, tuple[float, float]] = {}
    while sim.time < 90.0 and len(removed_at) < 36:
        before = sim.crowd.pos[:36].copy()
        sim.step()
        for row in np.flatnonzero(~sim.crowd.active[:36]).tolist():
            # where it stood when it was taken out (it no longer moves once inactive)
            removed_at.setdefault(row, (float(before[row, 0]), float(before[row, 1])))
    assert len(removed_at) == 36, f"only {len(removed_at)} of 36 got out in 90 s"
    final = sim.crowd.pos[:36]
    # The centre of every removed person is past the door line (outside the building)...
    assert not shapely.intersects_xy(building, final[:, 0], final[:, 1]).any()
    # ...and got there through the 2 m opening at y 5..7, not around a wall.
    assert np.all(np.abs(final[:, 1] - 6.0) < 1.0)
    assert [e.kind for e in sim.events].count("evacuated") == 36


def test_the_door_not_the_walk_sets_the_evacuation_time(hall):
    """36 people through a 2 m door drain at a door's rate: a few persons per second, not all at once."""
    world, grid, planner = hall
    exit_point = world.roi("exit_door").point
    starts = [(15.0 + 0.7 * (i % 6), 3.5 + 0.9 * (i // 6)) for i in range(36)]
    field = build_velocity_field(grid, planner.plan((17.0, 6.0), exit_point), exit_point, planner=planner)
    sim = simulate(hall, [agent(i + 1, p, group=0, radius=0.25, max_vel=1.34) for i, p in enumerate(starts)],
                   [LEAVE] * 36, fields={"group_0": field})
    while sim.time < 90.0 and sim.crowd.active[:36].any():
        sim.step()
    times = sorted(e.t for e in sim.events if e.kind == "evacuated")
    assert len(times) == 36
    flow = (len(times) - 1) / (times[-1] - times[0])
    # Empirical specific flow is 1.3-1.9 /s/m (RiMEA 12): a 2 m door passes at most ~4 persons/s.
    assert flow < 6.0, f"{flow:.1f} persons/s through a 2 m door"


def test_recorded_trajectories_end_at_the_door_line_and_validate_in_pedpy(hall, tmp_path):
    """Issue 30: a person leaves the recording on the step its centre crosses the exit's door line, so
    no frame holds anyone outside the walkable area and PedPy's is_trajectory_valid holds."""
    pedpy = pytest.importorskip("pedpy")
    world, grid, planner = hall
    exit_point = world.roi("exit_door").point
    starts = [(14.0 + 0.9 * (i % 5), 3.5 + 1.0 * (i // 5)) for i in range(20)]
    field = build_velocity_field(grid, planner.plan((16.0, 6.0), exit_point), exit_point, planner=planner)
    sim = simulate(hall, [agent(i + 1, p, group=0, radius=0.25, max_vel=1.34) for i, p in enumerate(starts)],
                   [LEAVE] * 20, fields={"group_0": field})
    while sim.time < 60.0 and sim.crowd.active[:20].any():
        sim.step()
    assert [e.kind for e in sim.events].count("evacuated") == 20
    rows = sim.recorder.to_array()
    inside = shapely.contains_xy(world.walkable(), rows["x"], rows["y"])
    assert inside.all(), f"{int((~inside).sum())} of {len(rows)} recorded positions outside the walkable area"
    path = sim.recorder.write_jupedsim_sqlite(tmp_path / "run.sqlite", world.walkable().wkt)
    traj = pedpy.load_trajectory_from_jupedsim_sqlite(trajectory_file=path)
    walkable = pedpy.load_walkable_area_from_jupedsim_sqlite(trajectory_file=path)
    assert pedpy.is_trajectory_valid(traj_data=traj, walkable_area=walkable)
