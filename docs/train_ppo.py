"""The recipe of docs/training.md: a small PPO policy trained on CPU for a few minutes in grove/SocialNav-v0,
evaluated against the scripted path-following velocity-obstacle baseline, and its learning curve drawn.

    pip install -c constraints.txt 'grove-tui[gym-train]'     # gymnasium, stable-baselines3 (CPU torch)
    python docs/train_ppo.py --minutes 4 --out docs/training_curve.png

Scenarios: one sentence in the residential world, generated once per seed through the services layer
(cached); seeds 0-3 train, seeds 4-5 are held out. The robot is holonomic and starts up to 0.5 m from
the scenario's start (start_jitter, seeded), so evaluation episodes differ. Training stops after the
stated wall-clock minutes; evaluation then runs the same seeded episodes for PPO (deterministic
actions) and for the baseline. Last line: key=value.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

WORLD = "residential"
PRESET = "normal"
PROMPT = "four people walk from the living room to the kitchen"
TRAIN_SEEDS = (0, 1, 2, 3)
HELD_OUT_SEEDS = (4, 5)
ENV_KWARGS = dict(kinematics="holonomic", metrics_every=0, start_jitter=0.5)


def make_env(bundles: list[Path], metrics_every: int = 0):
    from gymnasium.wrappers import RescaleAction

    from grove_tui.gym import SocialNavEnv

    env = SocialNavEnv(bundles, **{**ENV_KWARGS, "metrics_every": metrics_every})
    # PPO's Gaussian policy works in [-1, 1]; the wrapper maps that onto the env's m/s bounds.
    unit = np.ones(2, dtype=np.float32)
    return RescaleAction(env, min_action=-unit, max_action=unit)


def evaluate(env, act, episodes: int, first_seed: int) -> dict[str, float]:
    """Success, collision and timeout rates, mean return, time to goal and intimate-space share."""
    outcomes, returns, times, intimate = [], [], [], []
    for k in range(episodes):
        obs, _ = env.reset(seed=first_seed + k)
        total = 0.0
        while True:
            obs, reward, terminated, truncated, info = env.step(act(obs))
            total += reward
            if terminated or truncated:
                break
        outcomes.append(info["outcome"])
        returns.append(total)
        if info["outcome"] == "goal":
            times.append(info["time"])
        intimate.append(info["metrics"].get("intimate_space_intrusions", 0.0))
    n = float(episodes)
    return {"episodes": episodes, "success": outcomes.count("goal") / n, "collision": outcomes.count("collision") / n,
            "timeout": outcomes.count("timeout") / n, "mean_return": float(np.mean(returns)),
            "mean_time_to_goal": float(np.mean(times)) if times else float("nan"),
            "intimate_space_intrusions_pct": float(np.mean(intimate))}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=4.0, help="wall-clock training budget")
    parser.add_argument("--episodes", type=int, default=30, help="evaluation episodes per policy and scenario set")
    parser.add_argument("--out", type=Path, default=Path("docs/training_curve.png"))
    parser.add_argument("--results", type=Path, default=None, help="also write the numbers as JSON here")
    parser.add_argument("--cache", type=Path, default=None, help="gym scenario cache (default: GROVE's cache dir)")
    args = parser.parse_args()

    import torch
    from stable_baselines3 import PPO
    from stable_baselines3.common.callbacks import BaseCallback
    from stable_baselines3.common.monitor import Monitor
    from stable_baselines3.common.vec_env import DummyVecEnv, VecNormalize

    from grove_tui.gym import generated_scenarios
    from grove_tui.gym.baseline import PathFollowingVOPolicy

    torch.set_num_threads(1)  # a small MLP: one thread is as fast, and leaves the other cores alone
    print(f"load average at start: {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")
    started = time.perf_counter()
    train = generated_scenarios(WORLD, PRESET, PROMPT, TRAIN_SEEDS, cache=args.cache)
    held_out = generated_scenarios(WORLD, PRESET, PROMPT, HELD_OUT_SEEDS, cache=args.cache)
    print(f"scenarios ready in {time.perf_counter() - started:.1f} s: {len(train)} to train, {len(held_out)} held out")

    curve: list[tuple[int, float, float]] = []  # (timesteps, episode return, 1 if goal)

    class Budget(BaseCallback):
        """Stops training after the wall-clock budget; keeps every finished episode for the curve."""

        def __init__(self, seconds: float) -> None:
            super().__init__()
            self.seconds = seconds

        def _on_training_start(self) -> None:
            self.started = time.perf_counter()

        def _on_step(self) -> bool:
            info = self.locals["infos"][0]
            if "episode" in info:  # Monitor's record of a finished episode, in raw (unnormalised) reward
                curve.append((self.num_timesteps, float(info["episode"]["r"]),
                              1.0 if info.get("outcome") == "goal" else 0.0))
            return time.perf_counter() - self.started < self.seconds

    # Observations and rewards normalised by running statistics (SB3's VecNormalize), as usual for PPO.
    env = VecNormalize(DummyVecEnv([lambda: Monitor(make_env(train))]), norm_obs=True, norm_reward=True,
                       clip_obs=10.0)
    # log_std_init -1: first actions spread about a third of the speed range, not all of it; the robot
    # starts some 0.35 m from a wall, and wider random steps end most early episodes against it.
    model = PPO("MultiInputPolicy", env, n_steps=512, batch_size=128, n_epochs=5, learning_rate=3e-4,
                gamma=0.99, ent_coef=0.0, policy_kwargs=dict(net_arch=[64, 64], log_std_init=-1.0), seed=0,
                device="cpu", verbose=0)
    started = time.perf_counter()
    model.learn(total_timesteps=10_000_000, callback=Budget(args.minutes * 60.0))
    train_seconds = time.perf_counter() - started
    steps = model.num_timesteps
    print(f"PPO trained {steps} env steps ({len(curve)} episodes) in {train_seconds / 60:.1f} min "
          f"({steps / train_seconds:.0f} steps/s with updates)")

    env.training = False  # evaluation reads the statistics, no longer updates them

    def ppo_action(obs: dict) -> np.ndarray:
        return model.predict(env.normalize_obs(obs), deterministic=True)[0]

    results: dict[str, dict[str, dict[str, float]]] = {}
    for name, bundles, first_seed in (("train scenarios", train, 10_000), ("held-out scenarios", held_out, 20_000)):
        eval_env = make_env(bundles, metrics_every=0)
        ppo = evaluate(eval_env, ppo_action, args.episodes, first_seed)
        base_env = make_env(bundles, metrics_every=0)
        policy = PathFollowingVOPolicy(base_env)
        # the baseline speaks m/s; the wrapper expects [-1, 1]: scale back through the wrapper's bounds
        low, high = base_env.unwrapped.action_space.low, base_env.unwrapped.action_space.high
        baseline = evaluate(base_env, lambda obs: 2.0 * (policy.act(obs) - low) / (high - low) - 1.0,
                            args.episodes, first_seed)
        results[name] = {"ppo": ppo, "baseline": baseline}
        for who, r in (("PPO", ppo), ("baseline", baseline)):
            print(f"{name:<19} {who:<9} success {r['success']:.2f} collision {r['collision']:.2f} "
                  f"timeout {r['timeout']:.2f} return {r['mean_return']:+.2f} time to goal "
                  f"{r['mean_time_to_goal']:.1f} s intimate {r['intimate_space_intrusions_pct']:.1f} %")

    draw_curve(curve, results["train scenarios"]["baseline"], args.out, args.minutes)
    load = os.getloadavg()
    print(f"curve: {args.out}; load average at end: {' '.join(f'{v:.2f}' for v in load)}")
    if args.results is not None:
        args.results.write_text(json.dumps({"timesteps": steps, "train_minutes": train_seconds / 60,
                                            "episodes_trained": len(curve), "results": results}, indent=1) + "\n")
    tr, ho = results["train scenarios"], results["held-out scenarios"]
    print(f"timesteps={steps} train_min={train_seconds / 60:.1f} ppo_success={tr['ppo']['success']:.2f} "
          f"baseline_success={tr['baseline']['success']:.2f} ppo_collision={tr['ppo']['collision']:.2f} "
          f"baseline_collision={tr['baseline']['collision']:.2f} ppo_heldout_success={ho['ppo']['success']:.2f} "
          f"baseline_heldout_success={ho['baseline']['success']:.2f} load={load[0]:.2f}")


def draw_curve(curve: list[tuple[int, float, float]], baseline: dict[str, float], out: Path, minutes: float) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    data = np.asarray(curve, dtype=float).reshape(-1, 3)
    window = max(1, min(25, len(data) // 5))
    kernel = np.ones(window) / window
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True)
    if len(data) >= window:
        x = data[window - 1:, 0]
        top.plot(x, np.convolve(data[:, 1], kernel, mode="valid"), label=f"PPO (mean of {window} episodes)")
        bottom.plot(x, np.convolve(data[:, 2], kernel, mode="valid"), label="PPO")
    top.scatter(data[:, 0], data[:, 1], s=4, alpha=0.25, color="tab:blue")
    top.axhline(baseline["mean_return"], color="tab:orange", linestyle="--", label="baseline (evaluation)")
    bottom.axhline(baseline["success"], color="tab:orange", linestyle="--", label="baseline (evaluation)")
    top.set_ylabel("episode return")
    bottom.set_ylabel("success rate")
    bottom.set_xlabel("environment steps")
    bottom.set_ylim(-0.05, 1.05)
    top.legend(loc="lower right", fontsize=8)
    bottom.legend(loc="upper left", fontsize=8)
    fig.suptitle(f"grove/SocialNav-v0, {WORLD}: PPO on CPU for {minutes:g} min", fontsize=10)
    fig.tight_layout()
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
