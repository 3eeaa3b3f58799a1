"""HuNavSim 2.0's danger (fear, panic) and surprise (visibility, shock, reaction) costs, on trajectories
whose values can be worked out by hand, and in a simulated bundle's metrics.json."""

from __future__ import annotations

import math

import numpy as np
import pytest

from grove_tui.analysis.hunav2_metrics import (D_PROXEMICS, FOV_DEG, fear_panic, hunav2_costs, line_of_sight,
                                               shock_react, visibility_angle_cost)
from grove_tui.analysis.metrics import Trajectories
from grove_tui.navigation.grid import OccupancyGrid


def _open_grid(wall_at_x: float | None = None) -> OccupancyGrid:
    occupied = np.zeros((100, 100), dtype=bool)  # 10 x 10 m, 0.1 m cells, origin (0, 0)
    if wall_at_x is not None:
        occupied[:, int(wall_at_x / 0.1)] = True
    return OccupancyGrid(origin=(0.0, 0.0), resolution=0.1, occupied=occupied, inflation=0.0)


def _traj(robot_xy, robot_v, person_xy, person_v, person_yaw, dt=0.05) -> Trajectories:
    frames = len(robot_xy)
    robot = np.column_stack([np.asarray(robot_xy, float), np.zeros(frames)])
    return Trajectories(t=np.arange(frames) * dt, ids=np.array([1]), people=np.asarray(person_xy, float)[:, None, :],
                        people_vel=np.asarray(person_v, float)[:, None, :],
                        people_yaw=np.asarray(person_yaw, float)[:, None], groups=np.array([-1]),
                        robot=robot, robot_vel=np.asarray(robot_v, float))


def test_fear_is_closing_speed_over_distance_and_zero_when_moving_away():
    fear, panic = fear_panic(np.array([0.0, 0.0]), np.array([1.0, 0.0]), np.array([[4.0, 0.0]]),
                             np.array([[0.0, 0.0]]), np.array([0.35]), 0.3)
    assert fear[0] == pytest.approx(1.0 / 4.0)
    assert panic[0] == 0.0  # head-on: no miss distance, sin(theta) = 0
    fear, _ = fear_panic(np.array([0.0, 0.0]), np.array([-1.0, 0.0]), np.array([[4.0, 0.0]]),
                         np.array([[0.0, 0.0]]), np.array([0.35]), 0.3)
    assert fear[0] == 0.0


def test_panic_grows_as_the_robot_passes_closer():
    def panic_at(offset):
        return fear_panic(np.array([0.0, 0.0]), np.array([1.0, 0.0]), np.array([[3.0, offset]]),
                          np.array([[0.0, 0.0]]), np.array([0.35]), 0.3)[1][0]

    d = math.hypot(3.0, 2.0)
    sin_theta = 2.0 / d
    assert panic_at(2.0) == pytest.approx(1.0 / ((d * sin_theta - 0.65) * sin_theta))
    assert panic_at(1.0) > panic_at(2.0) > 0.0
    assert panic_at(0.5) == 0.0  # the paths overlap (d_perp < R): the paper's formula leaves it to fear


def test_visibility_inside_the_field_of_view_only():
    yaw = np.array([0.0])
    ahead = visibility_angle_cost(np.array([3.0, 0.0]), np.array([[0.0, 0.0]]), yaw)[0]
    assert ahead == 0.0  # theta = 0: straight ahead is no surprise in eq. 3
    side = visibility_angle_cost(np.array([2.0, 2.0]), np.array([[0.0, 0.0]]), yaw)[0]
    half = math.radians(FOV_DEG) / 2
    assert side == pytest.approx(D_PROXEMICS / half * (math.pi / 4) / math.hypot(2, 2))
    behind = visibility_angle_cost(np.array([-2.0, 0.5]), np.array([[0.0, 0.0]]), yaw)[0]
    assert behind == 0.0


def test_line_of_sight_is_blocked_by_an_occupied_cell():
    grid = _open_grid(wall_at_x=5.0)
    assert line_of_sight(grid.occupied, grid.origin, 0.1, (1.0, 1.0), (4.0, 3.0))
    assert not line_of_sight(grid.occupied, grid.origin, 0.1, (1.0, 1.0), (8.0, 3.0))


def test_shock_only_in_the_recognition_window_reaction_until_the_reaction_time():
    d = np.array([2.0, 2.0, 2.0])
    shock, react = shock_react(d, np.array([0.05, 0.3, 0.7]))
    assert shock[0] == pytest.approx(D_PROXEMICS / 2 * (1 - 4 * 0.05 / 0.6)) and shock[1] == 0.0 == shock[2]
    assert react[0] == pytest.approx(D_PROXEMICS / 2 * (1 - 0.05 / 0.6))
    assert react[1] == pytest.approx(D_PROXEMICS / 2 * 0.5) and react[2] == 0.0


def test_run_costs_add_up_over_frames_and_a_wall_hides_the_robot():
    frames = 20
    robot_xy = [(6.0 - 0.05 * k, 3.0) for k in range(frames)]
    person = [(2.0, 2.0)] * frames
    traj = _traj(robot_xy, [(-1.0, 0.0)] * frames, person, [(0.0, 0.0)] * frames, [0.3] * frames)
    open_costs = hunav2_costs(traj, _open_grid())
    assert open_costs["danger_fear_cost"] > 0 and open_costs["danger_panic_cost"] > 0
    assert open_costs["surprise_visibility_cost"] > 0
    assert open_costs["surprise_shock_cost"] > 0 and open_costs["surprise_react_cost"] > open_costs["surprise_shock_cost"]
    hidden = hunav2_costs(traj, _open_grid(wall_at_x=4.0))
    assert hidden["surprise_visibility_cost"] == 0.0 == hidden["surprise_shock_cost"] == hidden["surprise_react_cost"]
    assert hidden["danger_fear_cost"] == pytest.approx(open_costs["danger_fear_cost"])  # danger ignores sight
    # fear by hand: sum over frames of |v_rel| / d while closing in
    expected = sum(1.0 / math.dist(r, p) for r, p in zip(robot_xy, person) if (p[0] - r[0]) * -1.0 > 0)
    assert open_costs["danger_fear_cost"] == pytest.approx(expected)
    no_robot = Trajectories(t=traj.t, ids=traj.ids, people=traj.people, people_vel=traj.people_vel,
                            people_yaw=traj.people_yaw, groups=traj.groups, robot=None, robot_vel=None)
    assert hunav2_costs(no_robot, _open_grid()) == {}


def test_simulated_bundle_reports_the_2_0_costs_beside_the_1_0_set(tmp_path):
    from helpers.handmade import build_hospital_bundle

    from grove_tui.analysis.bundle_metrics import bundle_metrics
    from grove_tui.scenario.bundle import replace_run_outputs
    from grove_tui.scenario.model import Scenario
    from grove_tui.simulation.simulation import Simulation

    bundle = build_hospital_bundle(tmp_path / "b")
    scenario = Scenario.load(bundle / "scenario.yaml")
    sim = Simulation.from_scenario(scenario, bundle)
    sim.run(15.0)
    replace_run_outputs(bundle, lambda stage: sim.recorder.write_csv(stage / "trajectories.csv"))
    report, _ = bundle_metrics(bundle)
    for name in ("danger_fear_cost", "danger_panic_cost", "surprise_visibility_cost", "surprise_shock_cost",
                 "surprise_react_cost", "social_force_on_agents", "minimum_distance_to_people"):
        assert name in report.robot and math.isfinite(report.robot[name]) and report.robot[name] >= 0
