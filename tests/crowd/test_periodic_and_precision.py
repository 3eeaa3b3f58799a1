"""Issue 32: corridors with no ends (periodic x) and the single-precision pair terms."""

from __future__ import annotations

import math

import numpy as np
import pytest

from grove_tui.analysis.empirical import corridor_speed
from grove_tui.crowd.crowd import Crowd, CrowdError
from grove_tui.crowd.sfm import SFMParams

WALLS = np.array([[-5.0, 0.0, 35.0, 0.0], [-5.0, 4.0, 35.0, 4.0]])


def test_people_wrap_round_the_seam_and_feel_each_other_across_it():
    crowd = Crowd(WALLS, periodic_x=(0.0, 30.0))
    walker = crowd.add_agent((29.5, 2.0), goals=[(1e6, 2.0)], desired_speed=1.3)
    crowd.step(20)
    assert 0.0 <= crowd.pos[walker, 0] < 2.0  # walked off the end and came back at the start
    # two people face to face across the seam repel each other as if the corridor went on
    pair = Crowd(WALLS, periodic_x=(0.0, 30.0))
    a = pair.add_agent((29.8, 2.0))
    b = pair.add_agent((0.3, 2.0))
    pair.step(1)
    assert pair.vel[a, 0] < 0.0 < pair.vel[b, 0]


def test_a_periodic_corridor_is_refused_shorter_than_three_cutoffs():
    with pytest.raises(CrowdError, match="periodic_x"):
        Crowd(WALLS, periodic_x=(0.0, 5.0))


def test_single_precision_stays_within_tolerance_of_double():
    def one_step(precision: str) -> np.ndarray:
        crowd = Crowd(np.array([[0.0, 0.0, 20.0, 0.0], [0.0, 10.0, 20.0, 10.0]]), precision=precision)
        for k in range(200):
            crowd.add_agent((1.0 + (k % 20) * 0.9, 1.0 + (k // 20) * 0.85), goals=[(30.0, 5.0)], desired_speed=1.3)
        crowd.step(1)
        return crowd.vel.copy()

    assert np.abs(one_step("float32") - one_step("float64")).max() < 1e-5
    # and what the crowd does over time: the speed at 2 persons/m^2 in a corridor with no ends
    double = corridor_speed(2.0, SFMParams(), transient=5.0, measure=5.0)
    single = corridor_speed(2.0, SFMParams(), transient=5.0, measure=5.0, precision="float32")
    assert single == pytest.approx(double, rel=0.03)
    with pytest.raises(CrowdError, match="precision"):
        Crowd(precision="float16")


def test_periodic_corridor_speed_matches_weidmann_at_one_per_square_metre():
    speed = corridor_speed(1.0, SFMParams(), transient=10.0, measure=10.0)
    assert math.isclose(speed, 1.058, rel_tol=0.15)
