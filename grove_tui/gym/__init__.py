"""A Gymnasium environment over GROVE scenarios (optional extra `gym`: pip install 'grove-tui[gym]').

Importing this package registers `grove/SocialNav-v0`, so `gymnasium.make("grove/SocialNav-v0",
bundles=[...])` works, also inside the worker processes of gymnasium.vector.AsyncVectorEnv.
"""

from __future__ import annotations

from grove_tui.errors import GymError

try:
    import gymnasium
except ImportError:  # the extra is optional; say how to get it instead of a bare ModuleNotFoundError
    raise GymError("grove_tui.gym needs gymnasium",
                   hint="install the extra: pip install 'grove-tui[gym]'") from None

from grove_tui.gym.config import BEHAVIORS, ObservationConfig, RewardWeights  # noqa: E402
from grove_tui.gym.env import ENV_ID, SocialNavEnv  # noqa: E402
from grove_tui.gym.scenarios import generated_scenarios  # noqa: E402

if ENV_ID not in gymnasium.registry:
    # The env truncates at its own time limit, so no TimeLimit wrapper (max_episode_steps) is added.
    gymnasium.register(id=ENV_ID, entry_point="grove_tui.gym.env:SocialNavEnv")


def register_rllib(name: str = ENV_ID) -> str:
    """Register the environment with Ray/RLlib under `name` (env_config holds SocialNavEnv's arguments).

    Ray is not a dependency of the extra; GymError with a hint when it is not installed.
    """
    try:
        from ray.tune.registry import register_env
    except ImportError:
        raise GymError("Ray is not installed", hint="pip install 'ray[rllib]' to train with RLlib") from None
    register_env(name, lambda env_config: SocialNavEnv(**dict(env_config)))
    return name


__all__ = ["ENV_ID", "BEHAVIORS", "GymError", "ObservationConfig", "RewardWeights", "SocialNavEnv",
           "generated_scenarios", "register_rllib"]
