"""Scenarios for the environment: bundles loaded once, or generated from a sentence once per seed and cached.

An environment resets many thousand times; everything that does not change between episodes of one
scenario (the parsed trees, the world, the grids, the planner) is read here once and kept. Only the
Simulation, which holds the moving state, is built anew at each reset.
"""

from __future__ import annotations

import hashlib
import json
import os
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from grove_tui.bt.format.document import TreeDocument
from grove_tui.bt.format.xml import validate_document
from grove_tui.errors import GroveError, GymError
from grove_tui.gym.observation import wall_boxes
from grove_tui.navigation.grid import OccupancyGrid, build_grid
from grove_tui.navigation.theta_star import ThetaStarPlanner
from grove_tui.settings import cache_dir
from grove_tui.scenario.bundle import is_bundle, load_bundle, load_bundle_world
from grove_tui.crowd.sfm import SFMParams
from grove_tui.navigation.velocity_field import VelocityField
from grove_tui.scenario.model import RobotSpec, Scenario
from grove_tui.simulation.simulation import Simulation
from grove_tui.world.model import World

if TYPE_CHECKING:
    from grove_tui.services.session import GroveSession


@dataclass
class LoadedScenario:
    """One bundle, read once: what every reset of this scenario needs."""

    bundle_dir: Path
    scenario: Scenario
    documents: list[TreeDocument]  # agents' trees, in agent id order (as Simulation.build wants them)
    world: World
    grid: OccupancyGrid  # the planner's grid, from the bundle
    planner: ThetaStarPlanner
    fields: dict[str, VelocityField]
    walls: np.ndarray  # (M, 4) the world's wall segments
    boxes: np.ndarray  # (M, 4) their bounding boxes (observation.wall_boxes)
    patch_grid: OccupancyGrid  # uninflated, at the observation patch's resolution
    behaviors: tuple[str, ...]  # per agent, in agent id order

    @property
    def robot(self) -> RobotSpec:
        robot = self.scenario.robot
        if robot is None:  # load_scenario refuses such bundles
            raise GymError(f"{self.bundle_dir}: the scenario has no robot")
        return robot

    def simulation(self, dt: float, robot: RobotSpec | None = None, params: SFMParams | None = None) -> Simulation:
        """A fresh Simulation of this scenario, as Simulation.from_scenario builds it (`robot`: another
        RobotSpec in place of the scenario's; `params`: the pedestrian model's SFMParams)."""
        return Simulation.build(self.scenario.agents, self.documents, world=self.world, grid=self.grid,
                                planner=self.planner, walls=self.walls,
                                robot=self.scenario.robot if robot is None else robot,
                                fields=self.fields, seed=self.scenario.seed, dt=dt, bt_rate=10.0,
                                scenario=self.scenario, params=params)


def load_scenario(bundle_dir: str | os.PathLike[str], patch_resolution: float) -> LoadedScenario:
    """Read a bundle for the environment; GymError when it cannot hold a robot episode."""
    root = Path(bundle_dir)
    try:
        scenario, trees, fields, grid = load_bundle(root)  # the trees read once, there
        world = load_bundle_world(root, scenario)
        documents = [validate_document(trees[agent.tree]) for agent in sorted(scenario.agents, key=lambda a: a.id)]
    except GroveError as exc:
        raise GymError(f"{root}: cannot load the bundle: {exc}",
                       hint="pass a folder `grove generate` wrote") from None
    if scenario.robot is None:
        raise GymError(f"{root}: the scenario has no robot",
                       hint="generate it with a robot (the default) to train in it")
    walls = np.asarray(world.walls(), dtype=np.float64).reshape(-1, 4)
    return LoadedScenario(
        bundle_dir=root, scenario=scenario, documents=documents, world=world, grid=grid,
        planner=ThetaStarPlanner(grid), fields=fields, walls=walls, boxes=wall_boxes(walls),
        patch_grid=build_grid(world, resolution=patch_resolution, inflation=0.0),
        behaviors=tuple(a.behavior for a in sorted(scenario.agents, key=lambda a: a.id)))


def bundle_list(bundles: str | os.PathLike[str] | Iterable[str | os.PathLike[str]]) -> list[Path]:
    """One bundle or a list of them, as paths; GymError for an empty list or a folder that is no bundle."""
    if isinstance(bundles, (str, os.PathLike)):
        paths = [Path(bundles)]
    else:
        paths = [Path(b) for b in bundles]
    if not paths:
        raise GymError("no scenario bundles given",
                       hint="pass a bundle folder, a list of them, or world/preset/prompt")
    for path in paths:
        if not is_bundle(path):
            raise GymError(f"{path}: not a scenario bundle (no scenario.yaml)",
                           hint="pass a folder `grove generate` wrote")
    return paths


def generation_key(world: str, preset: str, prompt: str, seed: int, models: Sequence[str]) -> str:
    """The cache name of one generated scenario: same inputs and models, same bundle (generation is
    deterministic for them), so it is generated once."""
    text = json.dumps({"world": world, "preset": preset, "prompt": prompt, "seed": int(seed),
                       "models": sorted(models)}, sort_keys=True)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()[:20]


def generated_scenarios(world: str, preset: str, prompt: str, seeds: Iterable[int], *,
                        cache: str | os.PathLike[str] | None = None,
                        session: GroveSession | None = None) -> list[Path]:
    """Bundles of `prompt` in `world` under `preset`, one per seed, generated through the services layer
    the first time and read from the cache after that.

    Call it once in the parent process before starting vectorised environments, so N workers do not
    generate the same scenarios N times; then give the workers the returned bundles. `session`: the
    services session to generate with (default a new one).
    """
    from grove_tui.services.session import GroveSession, ScenarioRequest

    seeds = [int(s) for s in seeds]
    if not seeds:
        raise GymError("no seeds given", hint="pass seeds=[0, 1, ...]: one scenario is generated per seed")
    root = Path(cache) if cache is not None else cache_dir() / "gym"
    engine = session if session is not None else GroveSession()
    models = [status.file for status in engine.model_status()]
    out: list[Path] = []
    for seed in seeds:
        target = root / generation_key(world, preset, prompt, seed, models)
        if not is_bundle(target):
            # Written by the services layer in one atomic swap: a process that cached the same scenario
            # meanwhile wrote an identical bundle, which this one replaces. A failure keeps its own error
            # (bad prompt 2, generation 3, model 4) and hint.
            engine.generate(ScenarioRequest(world, preset, prompt, seed), target)
        out.append(target)
    return out
