"""A bundle from a hand-written draft, through the pipeline's own post-processing and planning stages.

The reading is the real reader's (or a hand-built one, to test generation on readings the reader does
not produce yet); only the model's draft is written by hand, as a weak model would write it.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from grove_tui.generation.draft import Draft, DraftGroup, DraftNode
from grove_tui.generation.pipeline import GenerationPipeline, PlanInputs, StageClock
from grove_tui.generation.presets import load_preset
from grove_tui.generation.rois import select_rois
from grove_tui.language.reading import read_prompt
from grove_tui.scenario.bundle import write_bundle
from grove_tui.world import load_world

NODES = ("GoTo", "Queue", "Wait", "Converse", "Wander", "FollowVelocityField", "JoinGroup")


def node(name: str, *children: DraftNode, **ports: Any) -> DraftNode:
    return DraftNode(name, ports, tuple(children))


def group(label: str, count: int, spawn: str, tree: DraftNode) -> DraftGroup:
    return DraftGroup(label, count, spawn, tree)


def hand_result(world: Any, preset_name: str, prompt: str, groups: list[DraftGroup], seed: int = 0,
                reading: Any = None) -> Any:
    world = load_world(world) if isinstance(world, str) else world
    preset = load_preset(preset_name)
    pipeline = GenerationPipeline(world, preset, None, None, None)
    reading = reading or read_prompt(prompt, world, seed=seed)
    selection = select_rois(world, preset, reading)
    inputs = PlanInputs(Draft(tuple(groups)), selection, NODES, reading)
    post, plan = pipeline._plan_stages(inputs, seed, StageClock(lambda event: None, None, {}), None)
    return pipeline._assemble(inputs, seed, {"bt": "hand"}, post, plan, {"stages": {}, "prompt": prompt})


def hand_bundle(out: Path, world: Any, preset_name: str, prompt: str, groups: list[DraftGroup], seed: int = 0,
                reading: Any = None) -> tuple[Any, Path]:
    result = hand_result(world, preset_name, prompt, groups, seed, reading)
    return result, Path(write_bundle(result, out))
