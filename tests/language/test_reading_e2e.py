"""The reading drives generation, end to end with the embedded model (real llama.cpp).

Compound prompts with a second or third group, a robot reaction, a structured count and an
evacuated zone: every group the sentence describes is in the scenario with its count, nobody has
an idle tree, robot reactions reach the agents' `behavior` and trees, and the grounding report in
generation.json says every group is as asked.
"""

from __future__ import annotations

import json

import pytest

from grove_tui.crowd.leaves.hunav import ROBOT_REACTIONS
from grove_tui.generation.pipeline import GenerationPipeline
from grove_tui.generation.presets import load_preset
from grove_tui.generation.reconcile import ROBOT_ACTIVITIES, ROUTINE_NODES
from grove_tui.language.reading import effective_counts
from grove_tui.scenario.bundle import load_bundle, write_bundle
from grove_tui.scenario.report import GroundingReport
from grove_tui.simulation.simulation import Simulation
from grove_tui.world import load_world

pytestmark = pytest.mark.slow

PROMPTS = {
    "second-group": ("hospital", "Ten patients queue at the pharmacy counter, while a few others stroll around the lobby."),
    "robot-subset": ("hospital", "Twelve visitors walk to the cafeteria and one of them stares at the robot."),
    "families": ("hospital", "Two families of three walk together to the cafeteria while someone avoids the robot "
                             "in the lobby."),
    "office-wait": ("office", "Four colleagues chat in the kitchen and two visitors wait at the front desk for five "
                              "minutes."),
    "evacuate": ("hospital", "Evacuate the pharmacy: eight people leave by the main entrance and one of them "
                             "follows the robot."),
}


@pytest.fixture(scope="module")
def read_and_generated(llm, retriever, tmp_path_factory):
    out = {}
    for key, (world_name, prompt) in PROMPTS.items():
        world = load_world(world_name)
        result = GenerationPipeline(world, load_preset("normal"), None, llm, retriever).run(prompt, seed=0)
        bundle = write_bundle(result, tmp_path_factory.mktemp(key) / "bundle")
        out[key] = (world, result, bundle)
    return out


@pytest.mark.parametrize("key", list(PROMPTS))
def test_every_group_of_the_sentence_is_in_the_scenario(read_and_generated, key):
    _, result, bundle = read_and_generated[key]
    reading = result.inputs.reading
    counts = effective_counts(reading)
    groups = result.report["groups"]
    assert [g["count"] for g in groups] == [counts[i] for i in sorted(counts)]
    assert len(result.scenario.agents) == sum(counts.values())
    grounding = GroundingReport.from_dict(json.loads((bundle / "generation.json").read_text())["grounding"])
    # planned before a run: nothing fails or is left unhonoured (a run checks the claims: analysis/outcomes.py)
    assert grounding.status == "planned" and not grounding.unhonoured, grounding.lines()
    assert len(grounding.groups) == len(counts)


@pytest.mark.parametrize("key", list(PROMPTS))
def test_no_agent_has_an_idle_tree(read_and_generated, key):
    _, result, _ = read_and_generated[key]
    for rel, document in result.trees.items():
        tags = {el.tag for el in document.nodes()}
        assert tags & ROUTINE_NODES, f"{rel} has no action: {sorted(tags)}"


@pytest.mark.parametrize("key,behavior", [("robot-subset", "Surprised"), ("families", "Scared"),
                                          ("evacuate", "Curious")])
def test_robot_reactions_reach_behavior_trees_and_the_simulation(read_and_generated, key, behavior):
    world, result, bundle = read_and_generated[key]
    reacting = [a for a in result.scenario.agents if a.behavior == behavior]
    assert len(reacting) == 1 and all(a.behavior == "Regular" for a in result.scenario.agents if a not in reacting)
    document = result.trees[reacting[0].tree]
    # the reaction wraps their routine, or, when reacting is all they do, is their activity
    reactions = set(ROBOT_REACTIONS) | {node for node, _ in ROBOT_ACTIVITIES.values()}
    assert any(el.tag in reactions for el in document.nodes())
    scenario, *_ = load_bundle(bundle)
    sim = Simulation.from_scenario(scenario, bundle, world=world)
    sim.run(5.0)  # the reaction pattern parses and ticks in the simulation


def test_labels_come_from_the_sentence(read_and_generated):
    _, result, _ = read_and_generated["families"]
    assert [g["label"] for g in result.report["groups"]] == ["family", "person"]
    _, result, _ = read_and_generated["office-wait"]
    assert [g["label"] for g in result.report["groups"]] == ["colleague", "visitor"]
