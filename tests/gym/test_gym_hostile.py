"""The Gym environment under hostile config, options and actions (issue 35: 20 uncaught exceptions from 7
causes, and a hang). Every one is now a GymError (a GroveError) naming the value and its documented bound,
and gymnasium's own InvalidAction / ResetNeeded where gymnasium has one.
"""

from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np
import pytest

gymnasium = pytest.importorskip("gymnasium")

import grove_tui.gym  # noqa: E402,F401  (registers grove/SocialNav-v0)
from grove_tui.errors import GroveError  # noqa: E402
from grove_tui.gym import ENV_ID, GymError, SocialNavEnv  # noqa: E402
from grove_tui.gym.config import ENV_BOUNDS, OBSERVATION_BOUNDS  # noqa: E402


@pytest.fixture(scope="module")
def env(bundle):
    made = SocialNavEnv(bundle)
    yield made
    made.close()


@pytest.mark.parametrize("action", ["fast", {"v": 1.0}, complex(1.0, 2.0), [complex(1, 1), 0.0], 10**400,
                                    [10**400, 0], [True, False], [0.5], [0.1, 0.2, 0.3], None, [float("nan"), 0.0],
                                    [float("inf"), 0.0], object()],
                         ids=["string", "dict", "complex", "complex list", "10**400", "10**400 list", "bools",
                              "one number", "three numbers", "None", "nan", "inf", "object"])
def test_actions_that_are_not_two_finite_numbers_are_refused(env, action):
    env.reset(seed=0)
    with pytest.raises(GymError, match="an action must be two finite numbers") as caught:
        env.step(action)
    assert isinstance(caught.value, gymnasium.error.InvalidAction) and isinstance(caught.value, GroveError)
    assert len(str(caught.value)) < 200
    env.step(np.array([0.3, 0.0], dtype=np.float32))  # the episode goes on after a refused action


def test_numpy_and_python_numbers_are_actions(env):
    env.reset(seed=0)
    for action in ([0.3, 0.1], (1, 0), np.array([0.2, -0.1]), np.array([[0.2, 0.0]], dtype=np.float32)):
        env.step(action)


def test_steps_outside_an_episode_are_gymnasiums_reset_needed(bundle):
    fresh = SocialNavEnv(bundle)
    with pytest.raises(gymnasium.error.ResetNeeded):
        fresh.step([0.0, 0.0])
    with pytest.raises(GymError, match="before reset"):
        fresh.step([0.0, 0.0])


@pytest.mark.parametrize("kwargs, contains", [
    ({"control_period": math.inf}, "control_period must be a number >= 0.001 and <= 10 s, got inf"),
    ({"control_period": "0.2"}, "control_period must be a number >= 0.001 and <= 10 s, got the string '0.2'"),
    ({"sim_dt": "0.05"}, "sim_dt must be a number"),
    ({"sim_dt": 1e-300}, "sim_dt must be a number >= 0.001 and <= 0.5 s, got 1e-300"),
    ({"sim_dt": 0.001, "control_period": 5.0}, "5,000 simulation steps per step; at most 1,000"),
    ({"time_limit": 1e300}, "time_limit must be a number >= 1 and <= 3600 s"),
    ({"time_limit": 1e6}, "time_limit must be a number >= 1 and <= 3600 s"),
    ({"time_limit": complex(1, 1)}, "time_limit must be a number"),
    ({"metrics_every": 10**400}, "metrics_every must be a whole number"),
    ({"start_jitter": float("nan")}, "start_jitter must be a number"),
    ({"max_angular_speed": 0}, "max_angular_speed must be a number > 0"),
    ({"observation": {"pedestrians": 10**9}}, "observation pedestrians must be a whole number >= 1 and <= 256"),
    ({"observation": {"patch_cells": 10**6}}, "observation patch_cells must be a whole number >= 1 and <= 256"),
    ({"observation": {"sensor_range": "8"}}, "observation sensor_range must be a number"),
    ({"observation": {3: 1}}, "unknown observation field(s) 3"),
    ({"observation": [1, 2]}, "observation must be a ObservationConfig or a dict"),
    ({"reward": {"success": 1e308}}, "reward success must be a number >= -1000 and <= 1000"),
    ({"reward": {"intimate_distance": -1.0}}, "reward intimate_distance must be a number > 0"),
    ({"kinematics": ["unicycle"]}, "unknown kinematics"),
    ({"pedestrian_model": 5}, "pedestrian_model must be a model's name"),
    ({"speed": 2.0}, "unknown argument(s) speed"),
    ({"render_mode": "human"}, "does not render"),
], ids=lambda value: str(value)[:40])
def test_config_values_out_of_their_bounds_are_refused(bundle, kwargs, contains):
    started = time.perf_counter()
    with pytest.raises(GymError) as caught:
        SocialNavEnv(bundle, **kwargs)
    assert contains in str(caught.value), str(caught.value)
    assert time.perf_counter() - started < 5.0


@pytest.mark.parametrize("bundles, contains", [(5, "bundles must be a bundle folder or a list of them, got 5"),
                                               ([3.5], "each bundle must be a folder path, got 3.5"),
                                               ({"a": 1}, "bundles must be a bundle folder")])
def test_bundles_of_the_wrong_kind_are_refused(bundles, contains):
    with pytest.raises(GymError, match=contains.replace("(", r"\(")):
        SocialNavEnv(bundles)


@pytest.mark.parametrize("seeds", [5, "0123", [1.5], [-1], [2**40]])
def test_seeds_of_the_wrong_kind_are_refused_before_any_model_loads(seeds, tmp_path):
    with pytest.raises(GymError, match="seed"):
        SocialNavEnv(world="hospital", preset="normal", prompt="ten visitors walk", seeds=seeds, cache=tmp_path)


def test_unknown_keywords_through_gymnasium_make_are_grove_errors(bundle):
    with pytest.raises(GymError, match="unknown argument"):
        gymnasium.make(ENV_ID, bundles=str(bundle), pedestrains=8)


@pytest.mark.parametrize("options, contains", [({"scenario": float("nan")}, "options['scenario'] must be a whole number"),
                                               ({"scenario": 1}, "options['scenario'] must be a whole number >= 0 and <= 0"),
                                               ({"scenario": "0"}, "the string '0'"),
                                               ({"scenery": 0}, "unknown reset option(s) scenery"),
                                               ([0], "reset options must be a dict")])
def test_reset_options_are_checked(env, options, contains):
    with pytest.raises(GymError) as caught:
        env.reset(options=options)
    assert contains in str(caught.value)


def test_the_bounds_are_the_documented_ones():
    text = (Path(__file__).resolve().parents[2] / "docs" / "training.md").read_text(encoding="utf-8")
    for name, bound in {**ENV_BOUNDS, **OBSERVATION_BOUNDS}.items():
        assert f"`{name}`" in text and bound.describe().replace("a whole number ", "").replace("a number ", "") in text, name


def test_a_long_time_limit_does_not_allocate_the_whole_episode_up_front(bundle):
    env = SocialNavEnv(bundle, time_limit=3600.0)
    env.reset(seed=0)
    assert env.history.t.shape[0] <= 1024  # grown as the episode runs; 1e6 s once took 4.2 GB here
    env.close()
