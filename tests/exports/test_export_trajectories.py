"""A simulated bundle's trajectories load in PedPy; metrics of the same run come out sane."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner
from helpers.handmade import build_hospital_bundle

from grove_tui.cli import main
from grove_tui.exports.trajectories import TrajectoryExportError, export_trajectories

pedpy = pytest.importorskip("pedpy")
SIMULATED_SECONDS = 20.0  # the `simulated` fixture's run (tests/conftest.py)


def test_pedpy_loads_our_trajectories_and_computes_density_and_speed(simulated, tmp_path):
    paths = export_trajectories(simulated, tmp_path)
    assert [p.name for p in paths] == ["trajectories.csv", "trajectories.sqlite", "trajectories.txt"]
    traj = pedpy.load_trajectory_from_jupedsim_sqlite(trajectory_file=tmp_path / "trajectories.sqlite")
    walkable = pedpy.load_walkable_area_from_jupedsim_sqlite(trajectory_file=tmp_path / "trajectories.sqlite")
    assert set(traj.data["id"].unique()) == {1, 2, 3, 4, 5}
    assert walkable.polygon.area > 1000  # the hospital's floor, in m^2
    area = pedpy.MeasurementArea([(26, 0.5), (40, 0.5), (40, 15), (26, 15)])  # the entrance lobby
    density = pedpy.compute_classic_density(traj_data=traj, measurement_area=area)
    assert density["density"].iloc[0] > 0  # everyone starts in the lobby
    speed = pedpy.compute_individual_speed(traj_data=traj, frame_step=5,
                                           speed_calculation=pedpy.SpeedCalculation.BORDER_SINGLE_SIDED)
    assert 0.2 < speed["speed"].max() < 2.0  # walking speeds
    text = pedpy.load_trajectory_from_txt(trajectory_file=tmp_path / "trajectories.txt")
    assert len(text.data) == len(traj.data)


def test_grove_metrics_writes_metrics_json(simulated):
    result = CliRunner().invoke(main, ["metrics", str(simulated), "--json"])
    assert result.exit_code == 0, result.output
    report = json.loads(result.output)
    assert report["crowd"]["wall_penetrations"] == 0
    assert report["crowd"]["agents"] == 5
    assert report["robot"]["path_length"] > 1.0
    assert 0.0 <= report["robot"]["intimate_space_intrusions"] <= 100.0
    on_disk = json.loads((simulated / "metrics.json").read_text())
    assert on_disk["crowd"]["agents"] == 5
    robot = on_disk["robot"]
    forces = ("social_force_on_agents", "social_force_on_robot", "social_work", "obstacle_force_on_robot",
              "obstacle_force_on_agents")
    bands = ("group_intimate_space_intrusions", "group_personal_space_intrusions", "group_social_space_intrusions")
    assert {k: report["robot"][k] for k in forces + bands} == {k: robot[k] for k in forces + bands}
    # The robot drives through the lobby among the five people, along the hospital's walls.
    assert robot["social_force_on_robot"] > 0 and robot["social_force_on_agents"] > 0
    assert robot["obstacle_force_on_robot"] > 0 and robot["obstacle_force_on_agents"] > 0
    # Social work adds |sum of the people's pushes on the robot| (at most the sum of their moduli)
    # to the obstacle force on it and the pushes it causes.
    caused = robot["obstacle_force_on_robot"] + robot["social_force_on_agents"]
    assert caused <= robot["social_work"] <= caused + robot["social_force_on_robot"] + 1e-9
    # Agents 4 and 5 are the scenario's group 1; the robot's route passes where they start.
    shares = [robot[k] for k in bands]
    assert all(0.0 <= share <= 100.0 for share in shares) and 0.0 < sum(shares) <= 100.0


def test_export_before_simulating_says_what_to_do(tmp_path):
    bundle = build_hospital_bundle(tmp_path / "fresh")
    with pytest.raises(TrajectoryExportError, match="simulate first"):
        export_trajectories(bundle, tmp_path / "out")
    result = CliRunner().invoke(main, ["export", "trajectories", str(bundle), "--out", str(tmp_path / "o2")])
    assert result.exit_code == 2 and "simulate first" in result.output
