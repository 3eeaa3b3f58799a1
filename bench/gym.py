"""Environment steps per second of grove/SocialNav-v0 with 20 and 100 pedestrians, one env and vectorised.

Two hospital scenarios are generated from sentences (embedded model, through the services layer, once;
later runs read them from the gym cache). Each env step is one 0.2 s control period: four 0.05 s SFM
steps, the behavior trees ticked twice, the observation, the reward and (by default) the HuNavSim
metrics of the episode so far in `info`. Actions are uniform random, seeded; an ended episode resets
at once (the reset, which rebuilds the simulation, is part of the measured time).

Measured, for each scenario:
    single env, metrics in info every step (the default) and only at the episode's end (metrics_every=0)
    gymnasium.vector.AsyncVectorEnv of N worker processes (default 4), metrics every step; the
    workers' start-up (imports, loading the scenario once) is timed apart from stepping.

Run by hand (not a test):  python bench/gym.py [--steps 400] [--envs 4]
The machine's load average is printed before and after: the workers share its cores with whatever
else runs. Last line: key=value.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

PROMPTS = {
    20: "twenty visitors walk from the entrance lobby to the cafeteria",
    100: ("forty visitors walk from the entrance lobby to the cafeteria, forty patients walk from ward a to the "
          "pharmacy and twenty nurses walk from the cafeteria to ward b"),
}


def make_env(bundle: str, metrics_every: int = 1):
    import grove_tui.gym  # noqa: F401  (registers the id in a fresh worker process)
    import gymnasium

    return gymnasium.make("grove/SocialNav-v0", bundles=[bundle], metrics_every=metrics_every)


def single(bundle: Path, steps: int, metrics_every: int) -> tuple[float, int]:
    """(env steps per second, episodes) of one in-process env driven by seeded random actions."""
    from grove_tui.gym import SocialNavEnv

    env = SocialNavEnv(bundle, metrics_every=metrics_every)
    env.action_space.seed(0)
    env.reset(seed=0)
    env.step(env.action_space.sample())  # first step outside the clock: numba's cache loads on first use
    episodes = 1
    started = time.perf_counter()
    for _ in range(steps):
        _, _, terminated, truncated, _ = env.step(env.action_space.sample())
        if terminated or truncated:
            env.reset()
            episodes += 1
    return steps / (time.perf_counter() - started), episodes


def vectorised(bundle: Path, steps: int, n: int) -> tuple[float, float, int]:
    """(env steps per second summed over the workers, start-up seconds, episodes) of AsyncVectorEnv."""
    import gymnasium
    from functools import partial

    started = time.perf_counter()
    envs = gymnasium.vector.AsyncVectorEnv([partial(make_env, str(bundle))] * n)
    try:
        envs.reset(seed=list(range(n)))
        envs.action_space.seed(0)
        envs.step(envs.action_space.sample())
        startup = time.perf_counter() - started
        episodes = n
        started = time.perf_counter()
        for _ in range(steps):
            _, _, terminated, truncated, _ = envs.step(envs.action_space.sample())
            episodes += int(np.sum(terminated | truncated))
        rate = n * steps / (time.perf_counter() - started)
    finally:
        envs.close()
    return rate, startup, episodes


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=400, help="env steps per measurement (per worker when vectorised)")
    parser.add_argument("--envs", type=int, default=4, help="worker processes of the vectorised run")
    parser.add_argument("--cache", type=Path, default=None, help="gym scenario cache (default: GROVE's cache dir)")
    args = parser.parse_args()

    from grove_tui.gym import generated_scenarios
    from grove_tui.scenario.model import Scenario

    print(f"load average at start: {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")
    keys = []
    for people, prompt in PROMPTS.items():
        started = time.perf_counter()
        bundle = generated_scenarios("hospital", "normal", prompt, [0], cache=args.cache)[0]
        scenario = Scenario.load(bundle / "scenario.yaml")
        print(f"\n{people} pedestrians requested, {len(scenario.agents)} in the scenario "
              f"({time.perf_counter() - started:.1f} s to generate or read from the cache): {bundle}")
        rate, episodes = single(bundle, args.steps, metrics_every=1)
        print(f"  single env, metrics every step   {rate:8.1f} steps/s  ({episodes} episodes, "
              f"{rate * 0.2:.1f} simulated s per wall s)")
        quiet_rate, quiet_episodes = single(bundle, args.steps, metrics_every=0)
        print(f"  single env, metrics at the end   {quiet_rate:8.1f} steps/s  ({quiet_episodes} episodes)")
        vec_rate, startup, vec_episodes = vectorised(bundle, args.steps, args.envs)
        print(f"  AsyncVectorEnv x{args.envs}, metrics every step {vec_rate:8.1f} steps/s in all "
              f"({vec_rate / rate:.2f}x one env; start-up {startup:.1f} s; {vec_episodes} episodes)")
        n = len(scenario.agents)
        keys += [f"single_{n}={rate:.0f}", f"single_quiet_{n}={quiet_rate:.0f}", f"vec{args.envs}_{n}={vec_rate:.0f}"]
    load = os.getloadavg()
    print(f"\nload average at end: {' '.join(f'{v:.2f}' for v in load)}")
    print(" ".join(keys) + f" load={load[0]:.2f}")


if __name__ == "__main__":
    main()
