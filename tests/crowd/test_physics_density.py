"""Issue 19: speed falls with density like Weidmann's curve: v(3/m^2) <= 0.5 v(0.5/m^2) (RiMEA test 4)."""

from __future__ import annotations

import math

import numpy as np

from grove_tui.crowd.crowd import Crowd
from grove_tui.crowd.sfm import SFMParams

WIDTH = 4.0


def speed_at_density(density: float, params: SFMParams) -> float:
    """Mean speed of the people in the middle of a block walking down a wide corridor at `density`."""
    walls = np.array([[-50.0, 0.0, 500.0, 0.0], [-50.0, WIDTH, 500.0, WIDTH]])
    crowd = Crowd(walls, params=params, dt=0.05)
    spacing = 1.0 / math.sqrt(density)
    rows = max(int(WIDTH / spacing), 1)
    columns = int(30.0 / spacing)
    for c in range(columns):
        for r in range(rows):
            y = (r + 0.5) * WIDTH / rows
            crowd.add_agent((c * spacing, y), radius=0.2, desired_speed=1.34, goals=[(1000.0, y)], goal_radius=0.3)
    crowd.step(40)  # 2 s to get going
    start = crowd.pos[:, 0].copy()
    crowd.step(60)  # then 3 s measured
    middle = (start > 10.0) & (start < 20.0)  # away from the block's free front and empty back
    return float(np.mean(crowd.pos[middle, 0] - start[middle]) / 3.0)


def test_speed_falls_with_density_like_weidmann():
    sparse = speed_at_density(0.5, SFMParams())
    dense = speed_at_density(3.0, SFMParams())
    assert sparse > 1.0, sparse  # free walking at 0.5 /m^2 (Weidmann 1.30 m/s)
    assert dense <= 0.5 * sparse, (sparse, dense)


def test_lightsfm_crowds_walk_at_free_speed_whatever_the_density():
    """The check above can fail: without the density term the dense block is barely slower."""
    sparse = speed_at_density(0.5, SFMParams.lightsfm())
    dense = speed_at_density(3.0, SFMParams.lightsfm())
    assert dense > 0.5 * sparse, (sparse, dense)
