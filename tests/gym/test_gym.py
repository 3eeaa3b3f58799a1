"""The Gymnasium environment over GROVE scenarios: the API contract (check_env), determinism, how
episodes end (collision with a person or a wall, goal, timeout), vectorised workers, the baseline,
recording an episode as a bundle the metrics and exports read, and generation from a sentence.

Scenarios are the hand-built hospital bundle (five people: a visitor, a two-person queue, a
conversing pair), simulated for real (behavior trees, numba SFM).
"""

from __future__ import annotations

import dataclasses
import json
import math
from pathlib import Path

import numpy as np
import pytest

gymnasium = pytest.importorskip("gymnasium")

from gymnasium.utils.env_checker import check_env  # noqa: E402

import grove_tui.gym  # noqa: E402,F401  (registers grove/SocialNav-v0)
from grove_tui.analysis.metrics import Trajectories  # noqa: E402
from grove_tui.gym import ENV_ID, GymError, RewardWeights, SocialNavEnv  # noqa: E402
from grove_tui.gym.baseline import PathFollowingVOPolicy  # noqa: E402
from grove_tui.gym.observation import PEDESTRIAN_COLUMNS, segment_clear, wall_distance  # noqa: E402
from grove_tui.scenario.bundle import load_bundle  # noqa: E402
from grove_tui.scenario.model import Scenario  # noqa: E402


def with_robot(source: Path, out: Path, start, goal, via=()) -> Path:
    """A copy of `source` whose robot's planned path goes from `start` through `via` to `goal`."""
    import shutil

    shutil.copytree(source, out)
    scenario = Scenario.load(out / "scenario.yaml")
    start, goal = tuple(float(v) for v in start), tuple(float(v) for v in goal)
    path = (start, *(tuple(float(v) for v in p) for p in via), goal)
    robot = dataclasses.replace(scenario.robot, start=start, goal=goal, path=path)
    dataclasses.replace(scenario, robot=robot).save(out / "scenario.yaml")
    return out


def run(env, actions) -> list:
    """(observation, reward, terminated, truncated, info) of each step, stopping at the episode's end."""
    out = []
    for action in actions:
        step = env.step(action)
        out.append(step)
        if step[2] or step[3]:
            break
    return out


def test_check_env_passes_for_both_kinematics(bundle):
    for kinematics in ("unicycle", "holonomic"):
        env = SocialNavEnv(bundle, kinematics=kinematics)
        check_env(env, skip_render_check=True)
        # the registered id builds the same environment
        made = gymnasium.make(ENV_ID, bundles=[bundle], kinematics=kinematics)
        assert made.observation_space == env.observation_space
        assert made.action_space == env.action_space


def test_observation_layout_and_frame(bundle):
    env = SocialNavEnv(bundle, kinematics="unicycle", observation={"pedestrians": 3, "patch_cells": 16})
    obs, info = env.reset(seed=0)
    assert obs["pedestrians"].shape == (3, len(PEDESTRIAN_COLUMNS))
    assert obs["occupancy"].shape == (16, 16) and obs["occupancy"].dtype == np.uint8
    scenario = Scenario.load(bundle / "scenario.yaml")
    start, goal = np.array(scenario.robot.start), np.array(scenario.robot.goal)
    # the goal, rotated into the robot's heading frame, keeps its distance
    assert obs["goal"][2] == pytest.approx(np.hypot(*(goal - start)), abs=1e-4)
    assert np.hypot(*obs["goal"][:2]) == pytest.approx(obs["goal"][2], abs=1e-4)
    heading = math.atan2(obs["robot"][3], obs["robot"][2])
    world_goal = start + np.array([[math.cos(heading), -math.sin(heading)],
                                   [math.sin(heading), math.cos(heading)]]) @ obs["goal"][:2]
    assert world_goal == pytest.approx(goal, abs=1e-4)
    # people nearest first; the gap column is centre distance minus both radii
    people = obs["pedestrians"]
    assert people[:, 0].tolist() == [1.0, 1.0, 1.0]
    gaps = people[:, 6]
    assert np.all(np.diff(gaps) >= 0)
    assert gaps[0] == pytest.approx(np.hypot(*people[0, 1:3]) - people[0, 5] - 0.3, abs=1e-4)
    # agent 1 is Surprised, the others Regular: one 1 per row in the behavior columns
    assert np.all(people[:, 7:].sum(axis=1) == 1.0)
    assert info["metrics"]["minimum_distance_to_target"] == pytest.approx(obs["goal"][2], abs=1e-4)


def test_segment_clear_needs_room_for_the_body():
    walls = np.array([[0.0, 0.0, 4.0, 0.0]])  # one wall along the x axis
    assert segment_clear(np.array([0.0, 1.0]), np.array([4.0, 1.0]), walls, 0.3)
    assert not segment_clear(np.array([0.0, 1.0]), np.array([4.0, 0.2]), walls, 0.3)  # ends too close
    assert not segment_clear(np.array([2.0, 1.0]), np.array([2.0, -1.0]), walls, 0.3)  # crosses it
    assert segment_clear(np.array([5.0, 1.0]), np.array([5.0, -1.0]), walls, 0.3)  # goes round its end


def test_waypoint_is_the_farthest_path_point_in_straight_reach(bundle, tmp_path):
    env = SocialNavEnv(bundle, kinematics="holonomic")
    env.reset(seed=0)
    walls = env.current.walls
    # free corridor below the start: every point in straight reach, the subgoal is the last one
    free = with_robot(bundle, tmp_path / "free", (28.0, 4.0), (31.0, 2.5), via=[(28.0, 3.0), (29.5, 3.0)])
    obs, _ = SocialNavEnv(free, kinematics="holonomic").reset(seed=0)
    assert obs["waypoint"][:2] == pytest.approx(np.array([31.0, 2.5]) - (28.0, 4.0), abs=1e-4)
    # a path that turns behind the wall nearest to the start: the subgoal stays on this side
    start = np.array([28.0, 4.0])
    a, ab = walls[:, 0:2], walls[:, 2:4] - walls[:, 0:2]
    t = np.clip(((start - a) * ab).sum(1) / np.maximum((ab * ab).sum(1), 1e-12), 0, 1)
    points = a + ab * t[:, None]
    k = int(np.argmin(np.hypot(*(points - start).T)))
    wall_point = points[k]
    inward = (start - wall_point) / np.hypot(*(start - wall_point))
    near_side = wall_point + 0.6 * inward
    far_side = wall_point - 0.6 * inward
    assert not segment_clear(start, far_side, walls, 0.3)
    turning = with_robot(bundle, tmp_path / "turning", start, far_side, via=[near_side])
    env = SocialNavEnv(turning, kinematics="holonomic")
    obs, _ = env.reset(seed=0)
    assert obs["waypoint"][:2] == pytest.approx(near_side - start, abs=1e-4)
    assert env.waypoint_index == 1


def test_progress_follows_the_planned_path_round_a_wall(bundle, tmp_path):
    # The goal is behind the wall nearest to the start; the path runs 3 m along the wall first. Driving
    # along it takes the robot farther from the goal as the crow flies, and is still progress.
    env = SocialNavEnv(bundle, kinematics="holonomic")
    env.reset(seed=0)
    walls = env.current.walls
    start = np.array([28.0, 4.0])
    a, ab = walls[:, 0:2], walls[:, 2:4] - walls[:, 0:2]
    t = np.clip(((start - a) * ab).sum(1) / np.maximum((ab * ab).sum(1), 1e-12), 0, 1)
    points = a + ab * t[:, None]
    k = int(np.argmin(np.hypot(*(points - start).T)))
    inward = (start - points[k]) / np.hypot(*(start - points[k]))
    along = ab[k] / np.hypot(*ab[k])
    corner = start + 3.0 * along
    goal = points[k] - 0.6 * inward
    assert segment_clear(start, corner, walls, 0.3) and not segment_clear(start, goal, walls, 0.3)
    env = SocialNavEnv(with_robot(bundle, tmp_path / "round", start, goal, via=[corner]), kinematics="holonomic")
    env.reset(seed=0)
    steps = run(env, [along * 0.8] * 5)
    progress = sum(s[4]["reward_terms"]["progress"] for s in steps)
    assert steps[-1][4]["distance_to_goal"] > np.hypot(*(goal - start)) + 0.1
    assert progress == pytest.approx(0.1 * 0.8 * 0.2 * 5, rel=0.05)


def test_occupancy_patch_sees_the_wall_ahead(bundle, tmp_path):
    env = SocialNavEnv(bundle, kinematics="holonomic", observation={"patch_cells": 21, "patch_resolution": 0.2})
    obs, _ = env.reset(seed=0)
    patch = obs["occupancy"]
    position = env.sim.crowd.robot_pos
    grid = env.current.patch_grid
    # every cell agrees with the world-aligned grid lookup at its centre
    for i in range(21):
        for j in range(21):
            x = position[0] + (j - 10) * 0.2
            y = position[1] + (i - 10) * 0.2
            row, col = grid.world_to_cell(x, y)
            assert patch[i, j] == grid.occupied[row, col]
    assert 0 < patch.sum() < patch.size  # walls nearby, free space around the robot
    assert patch[10, 10] == 0


def test_same_seeds_and_actions_give_the_same_observations(bundle):
    actions = np.random.default_rng(7).uniform([0.0, -1.5], [0.8, 1.5], size=(60, 2)).astype(np.float32)

    def episode(env, seed):
        obs, _ = env.reset(seed=seed)
        steps = run(env, actions)
        return [obs] + [s[0] for s in steps], [s[1] for s in steps]

    first, second = SocialNavEnv(bundle), SocialNavEnv(bundle)
    obs_a, rewards_a = episode(first, 3)
    obs_b, rewards_b = episode(second, 3)
    obs_c, rewards_c = episode(first, 3)  # the same env again, after another episode
    assert len(obs_a) == len(obs_b) == len(obs_c) > 10
    for a, b, c in zip(obs_a, obs_b, obs_c, strict=True):
        for key in a:
            assert np.array_equal(a[key], b[key]) and np.array_equal(a[key], c[key]), key
    assert rewards_a == rewards_b == rewards_c
    # and a different action sequence does change them (the test can fail)
    obs_d, _ = episode(SocialNavEnv(bundle), 3)
    other = np.random.default_rng(8).uniform([0.0, -1.5], [0.8, 1.5], size=(60, 2)).astype(np.float32)
    env = SocialNavEnv(bundle)
    env.reset(seed=3)
    changed = run(env, other)
    assert not np.array_equal(changed[-1][0]["robot"], obs_d[len(changed)]["robot"])


def test_people_move_by_the_pedestrian_model_of_the_settings_or_the_one_named(bundle, monkeypatch):
    def people_after(env) -> np.ndarray:
        env.reset(seed=0)
        steps = run(env, [np.array([0.0, 0.0], dtype=np.float32)] * 40)
        return steps[-1][0]["pedestrians"]

    grove = people_after(SocialNavEnv(bundle, pedestrian_model="grove"))
    lightsfm = people_after(SocialNavEnv(bundle, pedestrian_model="lightsfm"))
    assert not np.array_equal(grove, lightsfm)  # the two models do move people differently here
    monkeypatch.setenv("GROVE_SIMULATION__PEDESTRIAN_MODEL", "lightsfm")
    assert np.array_equal(people_after(SocialNavEnv(bundle)), lightsfm)  # `grove simulate`'s setting


def test_start_jitter_moves_the_start_by_the_seed(bundle):
    env = SocialNavEnv(bundle, start_jitter=0.5)
    scenario_start = np.array(Scenario.load(bundle / "scenario.yaml").robot.start)
    starts = {}
    for seed in (0, 1, 2, 0):
        env.reset(seed=seed)
        start = env.sim.crowd.robot_pos
        assert np.hypot(*(start - scenario_start)) <= 0.5 + 0.1
        assert env.current.grid.is_free(*start) and env.path[0] == pytest.approx(start)
        starts.setdefault(seed, []).append(tuple(np.round(start, 6)))
    assert starts[0][0] == starts[0][1]  # the same seed, the same start
    assert len({starts[0][0], starts[1][0], starts[2][0]}) == 3


def test_collision_with_a_person_terminates(bundle):
    env = SocialNavEnv(bundle, kinematics="holonomic")
    env.reset(seed=0)
    # A person stepping into the robot's body (not a chase: how fast people dodge a robot driving at them is
    # the crowd model's business, tested in tests/crowd); the episode must end on the contact.
    crowd = env.sim.crowd
    robot = crowd.robot_pos
    nearest = int(np.argmin(np.hypot(*(crowd.pos - robot).T)))
    away = (crowd.pos[nearest] - robot) / max(float(np.hypot(*(crowd.pos[nearest] - robot))), 1e-6)
    crowd.pos[nearest] = robot + away * (crowd.radius[nearest] + env.robot_radius - 0.15)
    obs, reward, terminated, truncated, info = env.step(np.zeros(2))
    assert terminated and not truncated
    assert info["collision"] == "person" and info["outcome"] == "collision"
    assert info["reward_terms"]["collision"] == pytest.approx(RewardWeights().collision)
    assert info["reward_terms"]["intimate"] < 0  # it came through the intimate space first
    assert obs["pedestrians"][0, 6] < 0.02 + 1e-6
    assert info["metrics"]["robot_on_person_collision"] + info["metrics"]["person_on_robot_collision"] >= 1
    with pytest.raises(GymError, match="after the episode ended") as caught:
        env.step([0.0, 0.0])
    assert "reset()" in caught.value.hint and caught.value.exit_code == 2


def test_driving_into_a_wall_terminates(bundle):
    env = SocialNavEnv(bundle, kinematics="holonomic")
    env.reset(seed=0)
    walls = env.current.walls
    start = env.sim.crowd.robot_pos
    a = walls[:, 0:2]
    ab = walls[:, 2:4] - a
    t = np.clip(((start - a) * ab).sum(1) / np.maximum((ab * ab).sum(1), 1e-12), 0, 1)
    points = a + ab * t[:, None]
    nearest = points[np.argmin(np.hypot(*(points - start).T))]
    towards = (nearest - start) / np.hypot(*(nearest - start))
    steps = run(env, [towards * 0.8] * 100)
    _, _, terminated, truncated, info = steps[-1]
    assert terminated and not truncated and info["collision"] == "obstacle"
    assert wall_distance(env.sim.crowd.robot_pos, walls) < 0.3
    assert info["reward_terms"]["collision"] == pytest.approx(-0.25)


def test_reaching_the_goal_terminates_with_the_success_reward(bundle, tmp_path):
    start = Scenario.load(bundle / "scenario.yaml").robot.start
    goal = (start[0], start[1] - 1.5)  # the corridor is free below the start
    # unicycle: the robot starts facing along its path, here straight at the goal
    env = SocialNavEnv(with_robot(bundle, tmp_path / "goal", start, goal), kinematics="unicycle")
    env.reset(seed=0)
    steps = run(env, [[0.8, 0.0]] * 50)
    _, reward, terminated, truncated, info = steps[-1]
    assert terminated and not truncated and info["reached_goal"] and info["outcome"] == "goal"
    assert info["distance_to_goal"] <= 0.6
    assert info["reward_terms"]["success"] == 1.0
    assert reward == pytest.approx(sum(info["reward_terms"].values()))
    progress = sum(s[4]["reward_terms"]["progress"] for s in steps)
    assert progress == pytest.approx(0.1 * (1.5 - info["distance_to_goal"]), abs=1e-6)
    assert info["metrics"]["completed"] == 1.0


def test_timeout_truncates(bundle):
    env = SocialNavEnv(bundle, time_limit=1.0, reward={"timeout": -0.5})
    env.reset(seed=0)
    steps = run(env, [[0.0, 0.0]] * 10)
    assert len(steps) == 5  # 1 s of 0.2 s control periods
    _, _, terminated, truncated, info = steps[-1]
    assert truncated and not terminated and info["outcome"] == "timeout"
    assert info["reward_terms"]["timeout"] == -0.5
    assert info["time"] == pytest.approx(1.0)


def test_bad_arguments_are_grove_errors(bundle, tmp_path):
    with pytest.raises(GymError, match="kinematics"):
        SocialNavEnv(bundle, kinematics="diff-drive")
    with pytest.raises(GymError, match="multiple of sim_dt"):
        SocialNavEnv(bundle, control_period=0.07)
    with pytest.raises(GymError, match="not a scenario bundle"):
        SocialNavEnv(tmp_path)
    with pytest.raises(GymError, match="unknown reward field"):
        SocialNavEnv(bundle, reward={"sucess": 2.0})
    with pytest.raises(GymError, match="unknown pedestrian model 'helbing'"):
        SocialNavEnv(bundle, pedestrian_model="helbing")
    env = SocialNavEnv(bundle)
    env.reset(seed=0)
    with pytest.raises(GymError, match="two finite numbers"):
        env.step([float("nan"), 0.0])


def test_scenarios_take_turns_and_the_seed_picks_the_first(bundle, tmp_path):
    start = Scenario.load(bundle / "scenario.yaml").robot.start
    other = with_robot(bundle, tmp_path / "other", start, (start[0] + 3.0, start[1]))
    env = SocialNavEnv([bundle, other])
    seen = [Path(env.reset(seed=1)[1]["scenario"]).name]
    seen += [Path(env.reset()[1]["scenario"]).name for _ in range(3)]
    assert seen == ["other", "bundle", "other", "bundle"]


def test_four_async_workers_step_together(bundle):
    def make():
        return gymnasium.make(ENV_ID, bundles=[bundle], kinematics="holonomic")

    envs = gymnasium.vector.AsyncVectorEnv([make] * 4)
    try:
        obs, infos = envs.reset(seed=[0, 1, 2, 3])
        assert obs["pedestrians"].shape == (4, 8, len(PEDESTRIAN_COLUMNS))
        assert obs["occupancy"].shape == (4, 32, 32)
        # the same scenario everywhere and the same start: the workers agree with one in-process env
        single = SocialNavEnv(bundle, kinematics="holonomic")
        single_obs, _ = single.reset(seed=0)
        assert np.array_equal(obs["robot"][0], single_obs["robot"])
        actions = np.tile(np.array([[0.8, 0.0], [0.0, 0.8], [-0.8, 0.0], [0.0, -0.8]], dtype=np.float32), (1, 1))
        ended = np.zeros(4, dtype=bool)
        for _ in range(40):
            obs, rewards, terminated, truncated, infos = envs.step(actions)
            assert rewards.shape == (4,) and np.all(np.isfinite(rewards))
            ended |= terminated | truncated
        assert "metrics" in infos and "distance_to_goal" in infos
        # the four drove in four directions: four different robot velocities
        assert len({tuple(np.round(v, 3)) for v in obs["robot"][:, :2]}) == 4 or ended.any()
    finally:
        envs.close()


def test_baseline_follows_the_path_and_keeps_off_walls(bundle, tmp_path):
    # A free corridor stretch: the planned path from the start 6 m to the right.
    start = Scenario.load(bundle / "scenario.yaml").robot.start
    scenario = Scenario.load(bundle / "scenario.yaml")
    path = np.asarray(scenario.robot.path)
    # keep the first leg of the planned path only: it runs along the corridor
    goal = tuple(path[0] + 6.0 * (path[1] - path[0]) / np.hypot(*(path[1] - path[0])))
    out = with_robot(bundle, tmp_path / "leg", start, goal)
    for kinematics in ("unicycle", "holonomic"):
        env = SocialNavEnv(out, kinematics=kinematics)
        policy = PathFollowingVOPolicy(env)
        obs, _ = env.reset(seed=0)
        closest = math.inf
        for _ in range(200):
            obs, _, terminated, truncated, info = env.step(policy.act(obs))
            closest = min(closest, float(obs["pedestrians"][0, 6]) if obs["pedestrians"][0, 0] else math.inf)
            if terminated or truncated:
                break
        assert info["outcome"] == "goal", (kinematics, info["outcome"])
        assert closest > 0.02


def test_an_episode_records_as_a_bundle_the_metrics_read(bundle, tmp_path):
    from grove_tui.analysis.bundle_metrics import bundle_metrics
    from grove_tui.exports.pictures import draw_scenario
    from grove_tui.world import load_world

    env = SocialNavEnv(bundle, kinematics="unicycle")
    env.reset(seed=0)
    steps = run(env, [[0.6, 0.2]] * 30)
    out = env.record_episode(tmp_path / "episode")
    scenario, trees, _, _ = load_bundle(out)
    assert len(trees) == 5
    traj = Trajectories.from_csv(out / "trajectories.csv")
    # one row per simulation step (plus none at t=0): robot and every person
    assert traj.frames == len(steps) * env.substeps
    recorded = traj.robot[-1, :2]
    assert recorded == pytest.approx(env.sim.crowd.robot_pos, abs=1e-3)
    metrics = json.loads((out / "metrics.json").read_text())
    assert metrics["robot"]["path_length"] == pytest.approx(bundle_metrics(out, write=False)[0].robot["path_length"])
    assert metrics["robot"]["path_length"] > 0.5
    episode = json.loads((out / "episode.json").read_text())
    assert episode["steps"] == len(steps) and len(episode["actions"]) == len(steps)
    assert episode["actions"][0] == pytest.approx([0.6, 0.2])
    # the robot's path in the recorded scenario is the driven one, so `grove simulate` drives it again
    assert scenario.robot.path[0] == pytest.approx(Scenario.load(bundle / "scenario.yaml").robot.start)
    assert scenario.robot.path[-1] == pytest.approx(tuple(recorded), abs=1e-3)
    assert (out / "events.jsonl").exists()
    picture = draw_scenario(load_world("hospital"), scenario, out, tmp_path / "episode.png",
                            trajectories=out / "trajectories.csv", title="episode")
    assert Path(picture).stat().st_size > 1000
    # `grove simulate` replays it: its scripted robot now drives the policy's path
    from grove_tui.services.session import GroveSession

    GroveSession().simulate(out, 2.0)
    replay = Trajectories.from_csv(out / "trajectories.csv")
    moved = np.hypot(*(replay.robot[-1, :2] - np.asarray(scenario.robot.path[0])))
    assert moved > 0.5 and (out / "episode.json").exists()


@pytest.mark.slow
def test_scenarios_generated_from_a_sentence_are_cached(tmp_path):
    kwargs = dict(world="hospital", preset="normal", prompt="Three visitors walk from the entrance lobby to ward a",
                  seeds=[0, 1], cache=tmp_path / "cache")
    env = SocialNavEnv(**kwargs)
    bundles = [s.bundle_dir for s in env.scenarios]
    assert len(bundles) == 2 and bundles[0] != bundles[1]
    stamps = [(b / "scenario.yaml").stat().st_mtime_ns for b in bundles]
    again = SocialNavEnv(**kwargs)  # from the cache: the same folders, untouched
    assert [s.bundle_dir for s in again.scenarios] == bundles
    assert [(b / "scenario.yaml").stat().st_mtime_ns for b in bundles] == stamps
    obs, info = again.reset(seed=1)
    assert Path(info["scenario"]) == bundles[1]
    assert Scenario.load(bundles[1] / "scenario.yaml").seed == 1
    check_env(again, skip_render_check=True)
