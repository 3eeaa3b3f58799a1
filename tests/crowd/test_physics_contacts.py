"""Issue 19: bodies do not overlap (<= 5 cm) in a dense room, through HFV 2000 contact forces.

A body is SFMParams.body_fraction of the agent's radius (the shoulders; issue 32), so overlaps are
measured between bodies, not between the envelopes the planner keeps clear."""

from __future__ import annotations

import numpy as np
import pytest

from grove_tui.crowd.crowd import Crowd
from grove_tui.crowd.sfm import SFMParams

ROOM = np.array([[0, 0, 6, 0], [6, 0, 6, 6], [6, 6, 0, 6], [0, 6, 0, 0]], dtype=np.float64)


def squeeze(params: SFMParams, seconds: float = 15.0) -> tuple[float, float]:
    """64 people in a 6 m x 6 m room all push to its centre (then to a corner); worst overlaps seen."""
    crowd = Crowd(ROOM, params=params, dt=0.05)
    body = 0.25 * params.body_fraction
    for k in range(64):
        x, y = 0.6 + 0.68 * (k % 8), 0.6 + 0.68 * (k // 8)
        crowd.add_agent((x, y), radius=0.25, desired_speed=1.3, goals=[(3.0, 3.0)], goal_radius=0.05)
    worst_pair = worst_wall = 0.0
    for step in range(int(seconds / 0.05)):
        if step == int(seconds / 0.05) // 2:
            for i in range(64):  # then everyone presses into the north-east corner
                crowd.set_goals(i, [(6.0, 6.0)], goal_radius=0.05)
        crowd.step(1)
        pos = crowd.pos
        gap = np.hypot(*(pos[:, None] - pos[None]).transpose(2, 0, 1)) + np.eye(64) * 9.0
        worst_pair = max(worst_pair, float((2.0 * body - gap).max()))
        to_wall = np.minimum.reduce([pos[:, 0], pos[:, 1], 6.0 - pos[:, 0], 6.0 - pos[:, 1]])
        worst_wall = max(worst_wall, float((body - to_wall).max()))
    return worst_pair, worst_wall


def test_bodies_overlap_at_most_five_centimetres_in_a_dense_room():
    pair, wall = squeeze(SFMParams())
    assert pair <= 0.05, f"two bodies overlapped by {100 * pair:.1f} cm"
    assert wall <= 0.05, f"a body overlapped a wall by {100 * wall:.1f} cm"


def test_lightsfm_stays_selectable_and_soft():
    """HuNavSim's forces, by name, as Gazebo runs them: the same room squeezes bodies together (the test above can fail)."""
    assert SFMParams.named("lightsfm") == SFMParams.lightsfm()
    assert SFMParams.named("grove") == SFMParams()
    with pytest.raises(ValueError, match="lightsfm"):
        SFMParams.named("helbing")
    pair, _wall = squeeze(SFMParams.named("lightsfm"))
    assert pair > 0.05


def test_contacts_start_at_the_shoulders_not_at_the_planners_envelope():
    """Two people of radius 0.25 m standing 0.47 m apart do not touch (bodies 0.23 m, issue 32); 0.455 m
    apart they are pushed apart by body compression. Only the compression acts: no drive, no social force."""
    params = SFMParams(social_weight=0.0, friction_weight=0.0, density_radius=0.0)
    body = 0.25 * params.body_fraction
    assert body == pytest.approx(0.23)
    pushes = []
    for gap in (0.47, 0.455):
        crowd = Crowd(params=params, dt=0.05)
        a = crowd.add_agent((0.0, 0.0), radius=0.25)
        b = crowd.add_agent((gap, 0.0), radius=0.25)
        crowd.step(1)
        pushes.append(float(crowd.vel[b, 0] - crowd.vel[a, 0]))
    assert pushes[0] == 0.0
    assert pushes[1] == pytest.approx(2 * min(params.body_weight * (2 * body - 0.455) * 0.05, 1.0), rel=1e-6)
    with pytest.raises(ValueError, match="body_fraction"):
        SFMParams(body_fraction=0.0)
