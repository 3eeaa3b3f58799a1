"""The metrics' fast paths give exactly the numbers of their definitions (the app measures every frame
live, so overlaps, wall crossings, density and the line of sight run on indexes and compiled code)."""

from __future__ import annotations

import numpy as np
import pytest

from grove_tui.analysis.hunav2_metrics import line_of_sight, lines_of_sight
from grove_tui.analysis.metrics import (CrowdAccumulator, Trajectories, WallIndex, _segments_cross, agent_overlaps,
                                        wall_penetrations)


def random_run(seed: int, frames: int = 120, agents: int = 60) -> Trajectories:
    """People walking in a 12 m square, some leaving part-way (NaN afterwards), dense enough to overlap."""
    rng = np.random.default_rng(seed)
    start = rng.uniform(0, 12, (agents, 2))
    steps = rng.normal(0, 0.08, (frames, agents, 2))
    people = start[None] + np.cumsum(steps, axis=0)
    leave = rng.integers(frames // 3, frames * 2, agents)
    for k, frame in enumerate(leave):
        people[frame:, k] = np.nan
    vel = steps / 0.05
    vel[np.isnan(people)] = np.nan
    yaw = np.arctan2(vel[:, :, 1], vel[:, :, 0])
    return Trajectories(t=np.arange(frames) * 0.05, ids=np.arange(1, agents + 1), people=people, people_vel=vel,
                        people_yaw=yaw, groups=np.full(agents, -1), robot=None, robot_vel=None)


def chunk(traj: Trajectories, start: int, stop: int) -> Trajectories:
    return Trajectories(t=traj.t[start:stop], ids=traj.ids, people=traj.people[start:stop],
                        people_vel=traj.people_vel[start:stop], people_yaw=traj.people_yaw[start:stop],
                        groups=traj.groups, robot=None, robot_vel=None)


def overlaps_by_definition(traj: Trajectories, radius: float = 0.35, tolerance: float = 0.1) -> int:
    count = 0
    for f in range(traj.frames):
        pts = traj.people[f][np.isfinite(traj.people[f][:, 0])]
        d = np.hypot(pts[:, None, 0] - pts[None, :, 0], pts[:, None, 1] - pts[None, :, 1])
        count += int((d[np.triu_indices(len(pts), k=1)] < 2 * radius - tolerance).sum())
    return count


def density_by_definition(traj: Trajectories, cell: float = 2.0) -> float:
    best = 0
    for f in range(traj.frames):
        pts = traj.people[f][np.isfinite(traj.people[f][:, 0])]
        if len(pts):
            best = max(best, int(np.unique(np.floor(pts / cell).astype(np.int64), axis=0, return_counts=True)[1].max()))
    return best / (cell * cell)


def bresenham_by_definition(occupied, origin, resolution, a, b) -> bool:
    height, width = occupied.shape
    x0, y0 = int((a[0] - origin[0]) / resolution), int((a[1] - origin[1]) / resolution)
    x1, y1 = int((b[0] - origin[0]) / resolution), int((b[1] - origin[1]) / resolution)
    dx, dy, sx, sy = abs(x1 - x0), abs(y1 - y0), 1 if x0 < x1 else -1, 1 if y0 < y1 else -1
    err, x, y = dx - dy, x0, y0
    while True:
        if not (0 <= x < width and 0 <= y < height) or occupied[y, x]:
            return False
        if x == x1 and y == y1:
            return True
        e2 = 2 * err
        if e2 > -dy:
            err, x = err - dy, x + sx
        if e2 < dx:
            err, y = err + dx, y + sy


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_chunked_crowd_metrics_equal_their_definitions(seed):
    traj = random_run(seed)
    rng = np.random.default_rng(seed + 10)
    # Walls of every length and direction, some through the crowd, some on cell lines.
    walls = np.vstack([rng.uniform(-1, 13, (25, 4)), [[3.0, 0.0, 3.0, 12.0], [0.0, 6.0, 12.0, 6.0], [5, 5, 5.4, 5.4]]])
    goals = {int(i): tuple(rng.uniform(0, 12, 2)) for i in traj.ids[::2]}
    accumulator = CrowdAccumulator(traj.ids, walls=walls, final_goals=goals, walkable_area=144.0)
    cuts = sorted({0, traj.frames, *rng.integers(1, traj.frames, 6).tolist()})
    for start, stop in zip(cuts, cuts[1:]):
        accumulator.add(chunk(traj, start, stop))
    got = accumulator.result()

    crossings, through = wall_penetrations(traj, walls)
    assert crossings > 0 and got["wall_penetrations"] == crossings and got["agents_through_walls"] == through
    assert overlaps_by_definition(traj) > 0 and got["agent_overlaps"] == overlaps_by_definition(traj)
    assert agent_overlaps(traj) == overlaps_by_definition(traj)
    assert got["peak_local_density"] == density_by_definition(traj)
    reached = 0
    for k, agent in enumerate(traj.ids):
        if int(agent) in goals:
            pts = traj.people[:, k][np.isfinite(traj.people[:, k, 0])]
            reached += bool(np.hypot(*(pts - goals[int(agent)]).T).min() <= 0.6)
    assert got["goal_reach_rate"] == reached / len(goals)


def test_the_wall_index_finds_every_crossing_a_full_test_finds():
    rng = np.random.default_rng(5)
    walls = rng.uniform(0, 20, (60, 4))
    p = rng.uniform(0, 20, (4000, 2))
    q = p + rng.normal(0, 0.3, (4000, 2))
    q[:50] = rng.uniform(0, 20, (50, 2))  # long moves across many cells
    expected = _segments_cross(p, q, walls)
    assert expected.sum() > 20
    assert np.array_equal(WallIndex(walls).crossings(p, q), expected)


def test_compiled_line_of_sight_walks_the_same_cells():
    rng = np.random.default_rng(3)
    occupied = rng.random((40, 60)) < 0.08
    origin, resolution = (-1.5, 2.25), 0.1
    starts = rng.uniform([-2.0, 1.5], [5.0, 6.5], (500, 2))
    b = (2.05, 4.0)
    expected = [bresenham_by_definition(occupied, origin, resolution, a, b) for a in starts]
    assert 50 < sum(expected) < 450
    assert lines_of_sight(occupied, origin, resolution, starts, b).tolist() == expected
    assert [line_of_sight(occupied, origin, resolution, tuple(a), b) for a in starts[:20]] == expected[:20]
