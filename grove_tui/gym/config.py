"""What the environment observes and how it scores a step: plain dataclasses, documented in docs/training.md.

Reward defaults come from CrowdNav (Chen, Liu, Kreiss, Alahi, "Crowd-Robot Interaction", ICRA 2019,
crowd_nav/configs/env.config: success_reward 1, collision_penalty -0.25, discomfort_penalty_factor 0.5,
no reward at timeout). Two of the terms differ from CrowdNav on purpose and say so below.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

from grove_tui.analysis.metrics import INTIMATE, PERSONAL
from grove_tui.errors import GymError

# HuNavSim's robot reactions (scenario `behavior`), the order of the pedestrians' one-hot columns.
BEHAVIORS = ("Regular", "Impassive", "Surprised", "Scared", "Curious", "Threatening")
KINEMATICS = ("unicycle", "holonomic")


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
            value = getattr(self, item.name)
            if not isinstance(value, (int, float)) or not math.isfinite(value):
                raise GymError(f"reward weight {item.name} must be a finite number, got {value!r}")
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
        if isinstance(self.pedestrians, bool) or not isinstance(self.pedestrians, int) or self.pedestrians < 1:
            raise GymError(f"observation pedestrians (K) must be a whole number >= 1, got {self.pedestrians!r}")
        if isinstance(self.patch_cells, bool) or not isinstance(self.patch_cells, int) or self.patch_cells < 1:
            raise GymError(f"observation patch_cells must be a whole number >= 1, got {self.patch_cells!r}")
        if not (self.sensor_range > 0 and math.isfinite(self.sensor_range)):
            raise GymError(f"observation sensor_range must be a positive number of metres, got {self.sensor_range!r}")
        if not (self.patch_resolution > 0 and math.isfinite(self.patch_resolution)):
            raise GymError(f"observation patch_resolution must be a positive number of metres, got "
                           f"{self.patch_resolution!r}")


def coerce(value: object, kind: type, what: str) -> object:
    """A config given as the dataclass, a dict of its fields (what gymnasium.make kwargs carry) or None."""
    if value is None:
        return kind()
    if isinstance(value, kind):
        return value
    if isinstance(value, dict):
        known = {item.name for item in fields(kind)}
        unknown = sorted(set(value) - known)
        if unknown:
            raise GymError(f"unknown {what} field(s) {', '.join(unknown)}",
                           hint=f"known: {', '.join(sorted(known))}")
        return kind(**value)
    raise GymError(f"{what} must be a {kind.__name__} or a dict of its fields, got {type(value).__name__}")
