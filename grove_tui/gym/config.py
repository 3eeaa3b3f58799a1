"""What the environment observes and how it scores a step: plain dataclasses, documented in docs/training.md,
and the bounds every argument, option and action is checked against.

Reward defaults come from CrowdNav (Chen, Liu, Kreiss, Alahi, "Crowd-Robot Interaction", ICRA 2019,
crowd_nav/configs/env.config: success_reward 1, collision_penalty -0.25, discomfort_penalty_factor 0.5,
no reward at timeout). Two of the terms differ from CrowdNav on purpose and say so below.

The environment takes its input like every other front end: numbers must be numbers (a string "0.2" is
refused, not guessed), finite and within the documented bounds below, so that no argument can make a
step run forever (sim_dt 1e-300), allocate gigabytes (time_limit 1e6, 10^9 pedestrians) or fail deep
inside numpy. Bad input raises GymError (a GroveError, exit 2); where gymnasium has an error of its own,
the raised class is also that one (InvalidAction, ResetNeeded), so code catching either works.
"""

from __future__ import annotations

import math
import numbers
import os
from collections.abc import Iterable
from dataclasses import dataclass, fields
from typing import Any

import gymnasium.error

from grove_tui.analysis.metrics import INTIMATE, PERSONAL
from grove_tui.errors import GymError

# HuNavSim's robot reactions (scenario `behavior`), the order of the pedestrians' one-hot columns.
BEHAVIORS = ("Regular", "Impassive", "Surprised", "Scared", "Curious", "Threatening")
KINEMATICS = ("unicycle", "holonomic")


class GymActionError(GymError, gymnasium.error.InvalidAction):
    """An action that is not two finite numbers: GroveError and gymnasium's InvalidAction at once."""


class GymResetNeeded(GymError, gymnasium.error.ResetNeeded):
    """step() before reset() or after the episode ended: GroveError and gymnasium's ResetNeeded at once."""


@dataclass(frozen=True)
class Bound:
    """The range a number must lie in (docs/training.md lists them all)."""

    low: float
    high: float
    unit: str = ""
    whole: bool = False  # an int (bools refused)
    low_open: bool = False  # low itself excluded

    def describe(self) -> str:
        unit = f" {self.unit}" if self.unit else ""
        lower = ">" if self.low_open else ">="
        kind = "a whole number" if self.whole else "a number"
        low, high = (f"{int(self.low):,}", f"{int(self.high):,}") if self.whole else (f"{self.low:g}", f"{self.high:g}")
        return f"{kind} {lower} {low} and <= {high}{unit}"


# The environment's arguments. A step runs control_period / sim_dt simulation steps, at most
# MAX_SUBSTEPS (sim_dt 1e-300 once asked for 10^299); time_limit <= 1 h keeps an episode's history
# (people x control steps, grown as the episode runs) in memory bounds.
ENV_BOUNDS: dict[str, Bound] = {
    "sim_dt": Bound(0.001, 0.5, "s"),
    "control_period": Bound(0.001, 10.0, "s"),
    "time_limit": Bound(1.0, 3600.0, "s"),
    "max_angular_speed": Bound(0.0, 10.0, "rad/s", low_open=True),
    "goal_tolerance": Bound(0.0, 10.0, "m", low_open=True),
    "start_jitter": Bound(0.0, 10.0, "m"),
    "metrics_every": Bound(0, 1_000_000, "steps", whole=True),
}
MAX_SUBSTEPS = 1_000
MAX_SCENARIOS = 10_000  # bundles or seeds of one environment
MAX_SEED = 2**32 - 1
OBSERVATION_BOUNDS: dict[str, Bound] = {
    "pedestrians": Bound(1, 256, whole=True),
    "sensor_range": Bound(0.0, 100.0, "m", low_open=True),
    "patch_cells": Bound(1, 256, whole=True),
    "patch_resolution": Bound(0.01, 2.0, "m"),
}
REWARD_WEIGHT_BOUND = Bound(-1000.0, 1000.0)
REWARD_DISTANCE_BOUND = Bound(0.0, 10.0, "m", low_open=True)


def _short(value: Any) -> str:  # Any: whatever a caller passed, shown in an error
    try:
        text = repr(value)
    except ValueError:  # an int too long to print
        return f"<{type(value).__name__}>"
    return text if len(text) <= 60 else text[:57] + "..."


def checked_number(value: Any, name: str, bound: Bound) -> Any:  # Any: user input in, int or float (bound.whole) out
    """`value` as a float (int when `bound.whole`) inside `bound`; GymError naming `name` otherwise."""
    wanted = f"{name} must be {bound.describe()}"
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        given = f"the string {_short(value)}" if isinstance(value, str) else f"{_short(value)}"
        raise GymError(f"{wanted}, got {given}")
    if bound.whole:
        if not isinstance(value, numbers.Integral):
            raise GymError(f"{wanted}, got {_short(value)}")
        whole = int(value)
        if not bound.low <= whole <= bound.high:
            raise GymError(f"{wanted}, got {_short(value)}")
        return whole
    try:
        number = float(value)
    except (OverflowError, ValueError):
        raise GymError(f"{wanted}, got {_short(value)}") from None
    below = number <= bound.low if bound.low_open else number < bound.low
    if not math.isfinite(number) or below or number > bound.high:
        raise GymError(f"{wanted}, got {_short(value)}")
    return number


def checked_text(value: Any, name: str) -> str:  # Any: user input before validation
    if not isinstance(value, str) or not value.strip():
        raise GymError(f"{name} must be a non-empty string, got {_short(value)}")
    return value


def checked_seeds(seeds: Any) -> list[int]:  # Any: user input before validation
    """Seeds for generated scenarios: an iterable of whole numbers in 0..2**32-1, at most MAX_SCENARIOS."""
    if isinstance(seeds, (str, bytes, dict)) or not isinstance(seeds, Iterable):
        raise GymError(f"seeds must be a list of whole numbers (one scenario each), got {_short(seeds)}")
    out: list[int] = []
    for seed in seeds:
        if len(out) >= MAX_SCENARIOS:
            raise GymError(f"seeds: at most {MAX_SCENARIOS:,} scenarios per environment")
        out.append(checked_number(seed, "each seed", Bound(0, MAX_SEED, whole=True)))
    return out


def checked_paths(bundles: Any) -> list[str | os.PathLike[str]]:  # Any: user input before validation
    """One bundle folder or an iterable of them (strings or paths), at most MAX_SCENARIOS."""
    if isinstance(bundles, (str, os.PathLike)):
        return [bundles]
    if isinstance(bundles, (bytes, dict)) or not isinstance(bundles, Iterable):
        raise GymError(f"bundles must be a bundle folder or a list of them, got {_short(bundles)}")
    out: list[str | os.PathLike[str]] = []
    for item in bundles:
        if not isinstance(item, (str, os.PathLike)):
            raise GymError(f"each bundle must be a folder path, got {_short(item)}")
        if len(out) >= MAX_SCENARIOS:
            raise GymError(f"bundles: at most {MAX_SCENARIOS:,} per environment")
        out.append(item)
    return out


@dataclass(frozen=True)
class RewardWeights:
    """Weights of the reward terms; each step's reward is their sum (info["reward_terms"] has each one).

    - success: once, when the robot reaches its goal (CrowdNav success_reward).
    - collision: once, when the robot touches a person or an obstacle (CrowdNav collision_penalty).
    - progress: per metre the robot's distance to go shrank during the step, the distance to go being
      straight to its subgoal and then along the planned path to the goal (so going round a wall is
      progress, where the straight-line distance would punish it). Potential-based shaping (Ng, Harada,
      Russell, ICML 1999) leaves the optimal policy unchanged; CrowdNav has no such term (its open
      square needs none), so 0.1 is our choice: a 10 m route earns as much as arriving.
    - intimate: per metre of intrusion into a person's intimate space (gap below INTIMATE, 0.45 m, the
      band HuNavSim's evaluator counts) per second, CrowdNav's discomfort_penalty_factor 0.5. CrowdNav
      applies it below 0.2 m; the band here is HuNavSim's so reward and metrics speak of the same space.
    - personal: the same in the personal band (0.45 to 1.2 m). CrowdNav has no such term: 0 by default.
    - timeout: once, when the episode is cut at the time limit (CrowdNav gives 0).
    """

    success: float = 1.0
    collision: float = -0.25
    progress: float = 0.1
    intimate: float = 0.5
    personal: float = 0.0
    timeout: float = 0.0
    intimate_distance: float = INTIMATE
    personal_distance: float = PERSONAL

    def __post_init__(self) -> None:
        for item in fields(self):
            bound = REWARD_DISTANCE_BOUND if item.name.endswith("_distance") else REWARD_WEIGHT_BOUND
            object.__setattr__(self, item.name, checked_number(getattr(self, item.name), f"reward {item.name}", bound))
        if not 0 < self.intimate_distance <= self.personal_distance:
            raise GymError(f"reward bands must satisfy 0 < intimate_distance <= personal_distance, got "
                           f"{self.intimate_distance} and {self.personal_distance}")


@dataclass(frozen=True)
class ObservationConfig:
    """Sizes of the observation (see SocialNavEnv for the layout of each part).

    pedestrians: K, how many of the nearest people are listed; sensor_range: people farther than this
    (centre to centre, metres) are not seen; patch_cells and patch_resolution: the occupancy patch is
    patch_cells x patch_cells cells of patch_resolution metres centred on the robot.
    """

    pedestrians: int = 8
    sensor_range: float = 8.0
    patch_cells: int = 32
    patch_resolution: float = 0.2

    def __post_init__(self) -> None:
        for name, bound in OBSERVATION_BOUNDS.items():
            object.__setattr__(self, name, checked_number(getattr(self, name), f"observation {name}", bound))


def coerce(value: object, kind: type, what: str) -> object:
    """A config given as the dataclass, a dict of its fields (what gymnasium.make kwargs carry) or None."""
    if value is None:
        return kind()
    if isinstance(value, kind):
        return value
    if isinstance(value, dict):
        known = {item.name for item in fields(kind)}
        unknown = sorted(_short(key) if not isinstance(key, str) else key for key in value if key not in known)
        if unknown:
            raise GymError(f"unknown {what} field(s) {', '.join(unknown[:5])}",
                           hint=f"known: {', '.join(sorted(known))}")
        return kind(**value)
    raise GymError(f"{what} must be a {kind.__name__} or a dict of its fields, got {type(value).__name__}")
