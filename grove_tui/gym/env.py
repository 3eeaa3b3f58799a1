"""`grove/SocialNav-v0`: a robot driven by a policy through a generated pedestrian scenario.

The pedestrians run exactly as in the product (behavior trees ticking at 10 Hz, numba SFM at dt,
reactions to the robot); the policy replaces the robot's scripted path with a velocity command held
for one control period.

Observation (a Dict; all float32 except the patch; frame as in observation.py):
    robot        (7,)    vx, vy (frame), cos(yaw), sin(yaw) (world), radius, max speed, share of time left
    goal         (3,)    x, y of the goal (frame), distance to it
    waypoint     (3,)    x, y (frame) and distance of the robot's subgoal on its planned path (Theta* on the
                         scenario's grid), as arena-rosnav's training set-ups give a global planner's
                         subgoal: the path's points are passed in order, each once the robot is within
                         WAYPOINT_REACHED of it or can drive straight to the next one (its body clear of
                         every wall); when the robot was pushed where it cannot drive straight to that
                         point, the subgoal is the latest earlier point it can reach straight
    pedestrians  (K, 13) the K nearest people within sensor range, nearest first; columns
                         present, x, y, vx, vy, radius, gap (centre distance minus both radii), then the
                         one-hot behavior (Regular, Impassive, Surprised, Scared, Curious, Threatening);
                         rows without a person are zero
    occupancy    (P, P)  uint8, 1 = blocked; cell [i, j] at frame x = (j - (P-1)/2) res, y = (i - (P-1)/2) res

Action (Box, physical units): unicycle (v, w) with v in [0, max speed] m/s and w in [-max_angular_speed,
max_angular_speed] rad/s; holonomic (vx, vy) in the world frame, each in [-max speed, max speed], the
norm clipped to max speed by the simulator.

terminated: the robot reached its goal (within goal_tolerance) or collided (a gap to a person below
the HuNavSim evaluator's 2 cm, or its body overlapping a wall); truncated: the time limit passed.

Every argument, reset option and action is checked against the bounds of gym/config.py (documented in
docs/training.md) before it is used: GymError otherwise, also gymnasium's InvalidAction for an action
and ResetNeeded for a step outside an episode.
"""

from __future__ import annotations

import dataclasses
import math
import os
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import gymnasium
import numpy as np
from gymnasium import spaces

from grove_tui.analysis.metrics import COLLISION_GAP, Trajectories, robot_metrics
from grove_tui.errors import GroveError, GymError
from grove_tui.gym.config import (BEHAVIORS, ENV_BOUNDS, Bound, KINEMATICS, MAX_SUBSTEPS, GymActionError, GymResetNeeded,
                                  ObservationConfig, RewardWeights, checked_number, checked_paths, checked_seeds,
                                  checked_text, coerce)
from grove_tui.gym.observation import (PEDESTRIAN_COLUMNS, behavior_one_hot, nearest_pedestrians,
                                       occupancy_patch, rotation, segment_clear, wall_distance)
from grove_tui.gym.scenarios import LoadedScenario, bundle_list, generated_scenarios, load_scenario
from grove_tui.scenario.model import RobotSpec
from grove_tui.simulation.simulation import Simulation

ENV_ID = "grove/SocialNav-v0"
# HuNavSim evaluator's completion rule: within goal radius (0.3 m) + 0.3 m of the goal.
GOAL_TOLERANCE = 0.6
# Without a stated limit an episode may last twice the planned path at full speed, plus time to wait
# for people to clear a door; never less than TIME_LIMIT_FLOOR.
TIME_LIMIT_FACTOR = 2.0
TIME_LIMIT_SLACK = 10.0
TIME_LIMIT_FLOOR = 20.0
WAYPOINT_REACHED = 0.5  # metres: a path point this close counts as passed
POSITION_LIMIT = 1.0e4  # metres; observation bounds, far beyond any world
HISTORY_START = 1024  # control steps the episode history holds before it first grows


Observation = dict[str, np.ndarray]  # the Dict space's arrays by key (observation.py)
Info = dict[str, Any]  # Any: Gymnasium's info is a free-form dict (its step() and reset() return types)


class SocialNavEnv(gymnasium.Env):
    """A Gymnasium environment over GROVE scenarios (see the module docstring for spaces and ends).

    Scenarios: `bundles` (one bundle folder or a list), or `world`, `preset`, `prompt` and `seeds`,
    which generates one scenario per seed through the services layer and caches it. Each reset loads
    the next scenario in turn; reset(seed=s) starts the turn at scenario s modulo their number.
    Everything else is deterministic: the same seeds and actions give the same observations. With
    start_jitter > 0 the robot starts up to that many metres from the scenario's start, drawn from the
    env's seeded generator (variety for training and evaluation).
    """

    metadata = {"render_modes": []}

    def __init__(self, bundles: str | os.PathLike[str] | Iterable[str | os.PathLike[str]] | None = None, *,
                 world: str | None = None, preset: str | None = None, prompt: str | None = None,
                 seeds: Iterable[int] = (0,), cache: str | os.PathLike[str] | None = None,
                 kinematics: str = "unicycle", control_period: float = 0.2, sim_dt: float = 0.05,
                 time_limit: float | None = None, max_angular_speed: float = 1.5,
                 goal_tolerance: float = GOAL_TOLERANCE, start_jitter: float = 0.0,
                 reward: RewardWeights | dict | None = None,
                 observation: ObservationConfig | dict | None = None, metrics_every: int = 1,
                 pedestrian_model: str | None = None, render_mode: str | None = None, **unknown: object) -> None:  # unknown: refused
        super().__init__()
        if unknown:
            names = ", ".join(sorted(map(str, unknown))[:5])
            raise GymError(f"unknown argument(s) {names} for {ENV_ID}",
                           hint="known: bundles, world, preset, prompt, seeds, cache, kinematics, control_period, "
                                "sim_dt, time_limit, max_angular_speed, goal_tolerance, start_jitter, reward, "
                                "observation, metrics_every, pedestrian_model (docs/training.md)")
        if render_mode is not None:
            raise GymError(f"render_mode {render_mode!r}: this environment does not render",
                           hint="record an episode (env.unwrapped.record_episode) and draw it with grove picture")
        if not isinstance(kinematics, str) or kinematics not in KINEMATICS:
            raise GymError(f"unknown kinematics {kinematics!r}", hint=f"use one of {', '.join(KINEMATICS)}")
        sim_dt = checked_number(sim_dt, "sim_dt", ENV_BOUNDS["sim_dt"])
        control_period = checked_number(control_period, "control_period", ENV_BOUNDS["control_period"])
        substeps = round(control_period / sim_dt)
        if substeps < 1 or abs(substeps * sim_dt - control_period) > 1e-9:
            raise GymError(f"control_period {control_period!r} s must be a positive multiple of sim_dt {sim_dt} s")
        if substeps > MAX_SUBSTEPS:
            raise GymError(f"control_period / sim_dt is {substeps:,} simulation steps per step; at most "
                           f"{MAX_SUBSTEPS:,}")
        if time_limit is not None:
            time_limit = checked_number(time_limit, "time_limit", ENV_BOUNDS["time_limit"])
        max_angular_speed = checked_number(max_angular_speed, "max_angular_speed", ENV_BOUNDS["max_angular_speed"])
        goal_tolerance = checked_number(goal_tolerance, "goal_tolerance", ENV_BOUNDS["goal_tolerance"])
        start_jitter = checked_number(start_jitter, "start_jitter", ENV_BOUNDS["start_jitter"])
        metrics_every = checked_number(metrics_every, "metrics_every", ENV_BOUNDS["metrics_every"])
        if pedestrian_model is not None and not isinstance(pedestrian_model, str):
            raise GymError(f"pedestrian_model must be a model's name, got {pedestrian_model!r}"[:200])
        if cache is not None and not isinstance(cache, (str, os.PathLike)):
            raise GymError(f"cache must be a folder path, got {type(cache).__name__}")
        self.kinematics = kinematics
        self.sim_dt = float(sim_dt)
        self.substeps = int(substeps)
        self.control_period = self.substeps * self.sim_dt
        self.time_limit_setting = time_limit
        self.max_angular_speed = float(max_angular_speed)
        self.goal_tolerance = float(goal_tolerance)
        self.start_jitter = float(start_jitter)
        self.weights: RewardWeights = coerce(reward, RewardWeights, "reward")  # type: ignore[assignment]
        self.obs_config: ObservationConfig = coerce(  # type: ignore[assignment]
            observation, ObservationConfig, "observation")
        self.metrics_every = metrics_every
        # The people move as `grove simulate` and the app move them: the settings' model unless named.
        from grove_tui.services.session import pedestrian_params

        try:
            self.pedestrian_params = pedestrian_params(pedestrian_model)
        except GroveError as exc:
            raise GymError(f"pedestrian_model: {exc}", hint=exc.hint) from None

        if bundles is not None:
            if world is not None or prompt is not None:
                raise GymError("give either bundles or world/preset/prompt, not both")
            paths = bundle_list(checked_paths(bundles))
        else:
            if world is None or preset is None or prompt is None:
                raise GymError("no scenarios", hint="pass bundles=..., or world=, preset=, prompt= and seeds=")
            paths = generated_scenarios(checked_text(world, "world"), checked_text(preset, "preset"),
                                        checked_text(prompt, "prompt"), checked_seeds(seeds), cache=cache)
        self.scenarios: list[LoadedScenario] = [load_scenario(p, self.obs_config.patch_resolution) for p in paths]
        self._one_hot = [behavior_one_hot(s.behaviors) for s in self.scenarios]

        max_speed = max(float(s.robot.max_vel) for s in self.scenarios)
        self.max_speed = max_speed
        if kinematics == "unicycle":
            self._action_box = spaces.Box(low=np.array([0.0, -self.max_angular_speed], dtype=np.float32),
                                          high=np.array([max_speed, self.max_angular_speed], dtype=np.float32),
                                          dtype=np.float32)
        else:
            self._action_box = spaces.Box(low=-max_speed, high=max_speed, shape=(2,), dtype=np.float32)
        self.action_space = self._action_box
        k, cells = self.obs_config.pedestrians, self.obs_config.patch_cells
        big = np.float32(POSITION_LIMIT)
        self.observation_space = spaces.Dict({
            "robot": spaces.Box(-big, big, shape=(7,), dtype=np.float32),
            "goal": spaces.Box(-big, big, shape=(3,), dtype=np.float32),
            "waypoint": spaces.Box(-big, big, shape=(3,), dtype=np.float32),
            "pedestrians": spaces.Box(-big, big, shape=(k, len(PEDESTRIAN_COLUMNS)), dtype=np.float32),
            "occupancy": spaces.Box(0, 1, shape=(cells, cells), dtype=np.uint8),
        })
        self._cursor = 0
        self.current: LoadedScenario | None = None  # the episode's scenario, from reset() on
        self.sim: Simulation | None = None
        self.episode_actions: list[tuple[float, float]] = []

    # ---- episode -------------------------------------------------------------------------------

    @property
    def loaded(self) -> LoadedScenario:
        """The running episode's scenario; GymResetNeeded before the first reset()."""
        if self.current is None:
            raise GymResetNeeded("no episode before reset()", hint="call reset() first")
        return self.current

    # Gymnasium's API: options and info are free-form dicts; an action is whatever the policy gives (checked).
    def reset(self, *, seed: int | None = None,
              options: dict[str, Any] | None = None,  # Any: Gymnasium's free-form reset options
              ) -> tuple[Observation, Info]:
        """Load the next scenario (options={"scenario": i} picks one), place the robot at its start."""
        super().reset(seed=seed)  # gymnasium's own error for a seed that is not a whole number >= 0
        if seed is not None:
            self._cursor = int(seed) % len(self.scenarios)
        index = self._cursor
        if options is not None:
            if not isinstance(options, dict):
                raise GymError(f"reset options must be a dict such as {{'scenario': 0}}, got {type(options).__name__}")
            unknown = [str(key) for key in options if key != "scenario"]
            if unknown:
                raise GymError(f"unknown reset option(s) {', '.join(unknown[:5])}", hint="the one option is 'scenario'")
            if "scenario" in options:
                last = len(self.scenarios) - 1
                index = checked_number(options["scenario"], "options['scenario']", Bound(0, last, whole=True))
        self._cursor = (index + 1) % len(self.scenarios)
        self.scenario_index = index
        self.current = self.scenarios[index]
        robot = self._jittered(self.current.robot) if self.start_jitter > 0 else self.current.robot
        self._release()
        self.sim = self.current.simulation(self.sim_dt, robot=robot, params=self.pedestrian_params)
        self.goal = np.asarray(robot.goal, dtype=np.float64)
        self.robot_radius = float(robot.radius)
        self.robot_max_speed = float(robot.max_vel)
        self.path = np.asarray(robot.path if robot.path else (robot.start, robot.goal), dtype=np.float64)
        # Face along the planned path, as a robot set down at its start would.
        ahead = self.path[1] - self.path[0] if len(self.path) > 1 else self.goal - self.path[0]
        self.heading = math.atan2(ahead[1], ahead[0]) if np.hypot(*ahead) > 1e-9 else 0.0
        # The simulator set the robot down facing +x; the same robot, facing the heading, so recordings
        # and the people's view of the robot start with it (the simulator then takes the yaw from motion).
        self.sim.crowd.set_robot(robot.start, radius=robot.radius, max_speed=robot.max_vel, path=self.path,
                                 yaw=self.heading)
        self.time_limit = self.time_limit_setting if self.time_limit_setting is not None else \
            max(TIME_LIMIT_FLOOR, TIME_LIMIT_FACTOR * _path_length(self.path) / max(self.robot_max_speed, 1e-6)
                + TIME_LIMIT_SLACK)
        self.distance_to_goal = self._goal_distance()
        # path length from each point of the planned path to its end (the goal)
        legs = np.hypot(*np.diff(self.path, axis=0).T) if len(self.path) > 1 else np.zeros(0)
        self._length_after = np.concatenate([np.cumsum(legs[::-1])[::-1], [0.0]])
        self.waypoint_index = 1 if len(self.path) > 1 else 0
        self._refresh_subgoal()
        self.episode_steps = 0
        self.episode_return = 0.0
        self.outcome = ""
        self.episode_actions = []
        # Grown as the episode runs (doubling), never sized for the whole time limit up front.
        self.history = _History(capacity=min(HISTORY_START, int(math.ceil(self.time_limit / self.control_period)) + 2),
                                people=len(self.current.scenario.agents))
        self.history.append(self.sim, self._robot_pose())
        self._metrics: dict[str, float] = {}
        return self._observation(), self._info({})

    def step(self, action: object) -> tuple[Observation, float, bool, bool, Info]:
        if self.sim is None:
            raise GymResetNeeded("step() before reset()", hint="call reset() first")
        if self.outcome:
            raise GymResetNeeded(f"step() after the episode ended ({self.outcome})", hint="call reset() first")
        command = self._command(action)
        self.episode_actions.append((float(command[0]), float(command[1])))
        crowd = self.sim.crowd
        collision = ""
        closest_gap = math.inf
        for _ in range(self.substeps):
            if self.kinematics == "unicycle":
                self.heading = _wrap(self.heading + command[1] * self.sim_dt)
                crowd.command_robot(command[0] * math.cos(self.heading), command[0] * math.sin(self.heading))
            else:
                crowd.command_robot(command[0], command[1])
            self.sim.step()
            gap, collision = self._contact()
            closest_gap = min(closest_gap, gap)
            if collision:
                break
        if self.kinematics == "holonomic":
            self.heading = float(crowd.robot_yaw or 0.0)  # holonomic: the crowd turns the robot's body
        self.episode_steps += 1
        previous = self.distance_to_go
        self.distance_to_goal = self._goal_distance()
        self._refresh_subgoal()
        reached = self.distance_to_goal <= self.goal_tolerance and not collision
        timed_out = self.sim.time >= self.time_limit - 1e-9 and not (reached or collision)
        terms = self._reward_terms(previous, closest_gap, collision, reached, timed_out)
        reward = float(sum(terms.values()))
        self.episode_return += reward
        self.outcome = "collision" if collision else "goal" if reached else "timeout" if timed_out else ""
        terminated = bool(collision or reached)
        truncated = bool(timed_out)
        self.history.append(self.sim, self._robot_pose())
        info = self._info(terms, collision=collision)
        return self._observation(), reward, terminated, truncated, info

    def _command(self, action: object) -> np.ndarray:
        """The action as two float64s, clipped to the action space; GymActionError for anything else
        (a string, a dict, complex or boolean values, an int too large for a float, NaN or infinity)."""
        wanted = "an action must be two finite numbers (an array, list or tuple)"
        if isinstance(action, (str, bytes, dict, set)):
            raise GymActionError(f"{wanted}, got {type(action).__name__}")
        try:
            values = np.asarray(action)
            if values.dtype.kind not in "iuf" or values.size != 2:
                raise GymActionError(f"{wanted}, got {_short(action)}")
            command = values.astype(np.float64).reshape(-1)
        except GymActionError:
            raise
        except (TypeError, ValueError, OverflowError):
            raise GymActionError(f"{wanted}, got {_short(action)}") from None
        if not np.all(np.isfinite(command)):
            raise GymActionError(f"{wanted}, got {_short(action)}")
        return np.clip(command, self._action_box.low, self._action_box.high)

    def close(self) -> None:
        self._release()
        super().close()

    def _release(self) -> None:
        """Close the finished episode's trajectory recorder (long episodes spill it to a temporary file)."""
        if self.sim is not None and getattr(self.sim, "recorder", None) is not None:
            self.sim.recorder.close()
        self.sim = None

    # ---- parts ---------------------------------------------------------------------------------

    def _jittered(self, robot: RobotSpec) -> RobotSpec:
        """The scenario's robot with its start moved up to start_jitter metres (uniform in the disc, drawn
        from the env's seeded np_random) to a free cell of the planning grid; the planned path then
        starts there, so the subgoal logic leads the robot back onto it."""
        radius = self.start_jitter * math.sqrt(self.np_random.uniform())
        angle = self.np_random.uniform(-math.pi, math.pi)
        x = robot.start[0] + radius * math.cos(angle)
        y = robot.start[1] + radius * math.sin(angle)
        free = self.loaded.grid.nearest_free(x, y, max_dist=self.start_jitter + 1.0)
        # a free cell behind a wall (another room) is no start nearby: keep the scenario's
        if free is None or not segment_clear(np.asarray(robot.start, float), np.asarray(free, float),
                                             self.loaded.walls, float(robot.radius), self.loaded.boxes):
            return robot
        start = (float(free[0]), float(free[1]))
        path = (start, *robot.path[1:]) if len(robot.path) > 1 else (start, robot.goal)
        return dataclasses.replace(robot, start=start, path=path)

    @property
    def running(self) -> Simulation:
        """The episode's simulation; GymResetNeeded before the first reset()."""
        if self.sim is None:
            raise GymResetNeeded("no episode before reset()", hint="call reset() first")
        return self.sim

    def _robot_state(self) -> tuple[np.ndarray, np.ndarray]:
        """The robot's position and velocity (x, y): every scenario the env loads has a robot."""
        crowd = self.running.crowd
        pos, vel = crowd.robot_pos, crowd.robot_vel
        if pos is None or vel is None:
            raise GymError(f"{self.loaded.bundle_dir}: the simulation has no robot")
        return pos, vel

    def _robot_pose(self) -> tuple[float, float, float, float, float]:
        pos, vel = self._robot_state()
        return float(pos[0]), float(pos[1]), float(self.heading), float(vel[0]), float(vel[1])

    def _goal_distance(self) -> float:
        pos, _ = self._robot_state()
        return float(math.hypot(self.goal[0] - pos[0], self.goal[1] - pos[1]))

    def observation_frame(self) -> np.ndarray:
        return rotation(self.heading) if self.kinematics == "unicycle" else np.eye(2)

    def _contact(self) -> tuple[float, str]:
        """(smallest gap to a person, "person" | "obstacle" | "") right now."""
        crowd = self.running.crowd
        pos, _ = self._robot_state()
        people = crowd.pos
        active = np.asarray(crowd.active, dtype=bool)
        gap = math.inf
        if people.shape[0] and active.any():
            gaps = np.hypot(people[:, 0] - pos[0], people[:, 1] - pos[1]) - crowd.radius - self.robot_radius
            gap = float(gaps[active].min())
        if gap < COLLISION_GAP:
            return gap, "person"
        if wall_distance(pos, self.loaded.walls, self.robot_radius, self.loaded.boxes) < self.robot_radius:
            return gap, "obstacle"
        return gap, ""

    def _reward_terms(self, previous: float, gap: float, collision: str, reached: bool,
                      timed_out: bool) -> dict[str, float]:
        w = self.weights
        intimate = max(0.0, w.intimate_distance - gap)
        personal = max(0.0, w.personal_distance - max(gap, w.intimate_distance)) if gap < w.personal_distance else 0.0
        return {
            "progress": w.progress * (previous - self.distance_to_go),
            "intimate": -w.intimate * intimate * self.control_period,
            "personal": -w.personal * personal * self.control_period,
            "collision": w.collision if collision else 0.0,
            "success": w.success if reached else 0.0,
            "timeout": w.timeout if timed_out else 0.0,
        }

    def _observation(self) -> Observation:
        sim = self.running
        crowd = sim.crowd
        frame = self.observation_frame()
        pos, robot_vel = self._robot_state()
        vel = frame @ robot_vel
        robot = np.array([vel[0], vel[1], math.cos(self.heading), math.sin(self.heading), self.robot_radius,
                          self.robot_max_speed, max(0.0, 1.0 - sim.time / self.time_limit)], dtype=np.float32)
        goal_xy = frame @ (self.goal - pos)
        goal = np.array([goal_xy[0], goal_xy[1], self.distance_to_goal], dtype=np.float32)
        offset = self.path[self.subgoal_index] - pos
        waypoint_xy = frame @ offset
        waypoint = np.array([waypoint_xy[0], waypoint_xy[1], math.hypot(*offset)], dtype=np.float32)
        cfg = self.obs_config
        people = nearest_pedestrians(pos, self.robot_radius, frame, crowd.pos, crowd.vel, crowd.radius,
                                     np.asarray(crowd.active, dtype=bool), self._one_hot[self.scenario_index],
                                     cfg.pedestrians, cfg.sensor_range)
        patch = occupancy_patch(self.loaded.patch_grid, pos, frame, cfg.patch_cells, cfg.patch_resolution)
        limit = np.float32(POSITION_LIMIT)
        return {"robot": np.clip(robot, -limit, limit), "goal": np.clip(goal, -limit, limit),
                "waypoint": np.clip(waypoint, -limit, limit),
                "pedestrians": np.clip(people, -limit, limit), "occupancy": patch}

    def _refresh_subgoal(self) -> None:
        """Advance along the planned path (see the module docstring), then the subgoal and the distance
        to go: straight to the subgoal, then along the path to the goal."""
        pos, _ = self._robot_state()
        path, walls, boxes = self.path, self.loaded.walls, self.loaded.boxes
        clearance = self.robot_radius
        while self.waypoint_index < len(path) - 1 and (
                math.hypot(*(path[self.waypoint_index] - pos)) <= WAYPOINT_REACHED
                or segment_clear(pos, path[self.waypoint_index + 1], walls, clearance, boxes)):
            self.waypoint_index += 1
        index = self.waypoint_index
        if not segment_clear(pos, path[index], walls, clearance, boxes):
            for earlier in range(index - 1, -1, -1):
                if segment_clear(pos, path[earlier], walls, clearance, boxes):
                    index = earlier
                    break
        self.subgoal_index = index
        self.distance_to_go = float(math.hypot(*(path[index] - pos)) + self._length_after[index])

    def _info(self, terms: dict[str, float], collision: str = "") -> Info:
        done = bool(self.outcome)
        if done or (self.metrics_every and self.episode_steps % self.metrics_every == 0):
            self._metrics = self.episode_metrics()
        return {
            "scenario": str(self.loaded.bundle_dir),
            "time": float(self.running.time),
            "distance_to_goal": float(self.distance_to_goal),
            "distance_to_go": float(self.distance_to_go),
            "collision": collision,
            "reached_goal": self.outcome == "goal",
            "outcome": self.outcome,
            "reward_terms": dict(terms),
            "metrics": dict(self._metrics),
        }

    # ---- metrics and recording --------------------------------------------------------------------

    def episode_metrics(self) -> dict[str, float]:
        """HuNavSim evaluator's robot metrics of the episode so far, one sample per control period."""
        scenario = self.loaded.scenario
        traj = self.history.trajectories([a.id for a in sorted(scenario.agents, key=lambda a: a.id)])
        radii = [a.radius for a in scenario.agents]
        return robot_metrics(traj, robot_radius=self.robot_radius,
                             person_radius=max(radii) if radii else 0.35, goal=tuple(self.goal),
                             groups={a.id: a.group for a in scenario.agents})

    def record_episode(self, out_dir: str | os.PathLike[str], overwrite: bool = False) -> Path:
        """Write the episode so far as a bundle the exports and `grove metrics` read (see recording.py)."""
        from grove_tui.gym.recording import record_episode

        if self.sim is None:
            raise GymError("nothing to record before reset()", hint="run an episode first")
        return record_episode(self, out_dir, overwrite=overwrite)


def _short(value: object) -> str:  # whatever a policy passed, shown in an error
    try:
        text = repr(value)
    except ValueError:  # an int too long to print
        return f"<{type(value).__name__}>"
    return " ".join(text.split())[:80]


def _wrap(angle: float) -> float:
    return (angle + math.pi) % (2 * math.pi) - math.pi


def _path_length(path: np.ndarray) -> float:
    if len(path) < 2:
        return 0.0
    d = np.diff(path, axis=0)
    return float(np.hypot(d[:, 0], d[:, 1]).sum())


class _History:
    """The episode at the control rate, for the metrics: robot pose and velocity, people, in arrays."""

    def __init__(self, capacity: int, people: int) -> None:
        self.t = np.zeros(capacity)
        self.robot = np.full((capacity, 3), np.nan)
        self.robot_vel = np.full((capacity, 2), np.nan)
        self.people = np.full((capacity, people, 2), np.nan)
        self.people_vel = np.full((capacity, people, 2), np.nan)
        self.people_yaw = np.full((capacity, people), np.nan)
        self.groups = np.full(people, -1, dtype=np.int64)
        self.size = 0

    def append(self, sim: Simulation, pose: tuple[float, float, float, float, float]) -> None:
        if self.size == self.t.shape[0]:
            self._grow()
        k = self.size
        crowd = sim.crowd
        n = self.people.shape[1]
        active = np.asarray(crowd.active[:n], dtype=bool)
        self.t[k] = sim.time
        self.robot[k] = pose[:3]
        self.robot_vel[k] = pose[3:]
        self.people[k] = np.where(active[:, None], crowd.pos[:n], np.nan)
        self.people_vel[k] = np.where(active[:, None], crowd.vel[:n], np.nan)
        self.people_yaw[k] = np.where(active, crowd.yaw[:n], np.nan)
        self.groups[:] = crowd.group[:n]
        self.size += 1

    def _grow(self) -> None:
        for name in ("t", "robot", "robot_vel", "people", "people_vel", "people_yaw"):
            old = getattr(self, name)
            new = np.full((old.shape[0] * 2, *old.shape[1:]), np.nan)
            new[: old.shape[0]] = old
            setattr(self, name, new)

    def trajectories(self, ids: list[int]) -> Trajectories:
        k = self.size
        return Trajectories(t=self.t[:k].copy(), ids=np.asarray(ids, dtype=np.int64), people=self.people[:k],
                            people_vel=self.people_vel[:k], people_yaw=self.people_yaw[:k], groups=self.groups.copy(),
                            robot=self.robot[:k], robot_vel=self.robot_vel[:k])


__all__ = ["ENV_ID", "SocialNavEnv", "BEHAVIORS", "GOAL_TOLERANCE"]
