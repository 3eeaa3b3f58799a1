"""The embedded model, for real: 50 varied prompts over the shipped worlds, every answer a valid draft.

One LocalLLM serves all 50 requests (the shared system prompt stays in its KV cache), with small
budgets so the whole run takes about two minutes on one core.
"""

from __future__ import annotations

import random

import pytest

from grove_tui.bt.format.manifest import NODES
from grove_tui.generation.draft import draft_grammar, parse_draft
from grove_tui.world import load_world
from grove_tui.llm.embedded import embedded_model_path
from grove_tui.llm.local import LocalLLM

NODE_SETS = {
    "queuing": ["Sequence", "Fallback", "GoTo", "Queue", "Wait"],
    "normal": ["Sequence", "Fallback", "Parallel", "GoTo", "Wander", "Converse", "Wait", "LookAtRobot", "IsRobotClose", "AvoidRobot"],
    "emergency": ["Sequence", "FollowVelocityField"],
    "social": ["Sequence", "Repeat", "Inverter", "GoTo", "SaySomething", "ApproachRobot", "BlockRobot", "StopAndWaitTimerAction"],
}
PEOPLE = ["patients", "visitors", "nurses", "employees", "children", "students", "guests", "cleaners", "doctors", "tourists"]
VERBS = [
    "{n} {who} walk from the {a} to the {b}",
    "{n} {who} queue at the {b}",
    "{n} {who} evacuate from the {a} through the {b}",
    "a group of {n} {who} chat near the {b}",
    "{n} {who} wander around the {a}",
    "{n} {who} block the robot near the {b} and then leave",
    "{n} {who} wait in the {a} and then go to the {b}",
]
SYSTEM = (
    "You write pedestrian scenarios for a simulator, one line per group: COUNT LABEL from SPAWN: TREE. COUNT is how "
    "many, LABEL who they are, SPAWN where they start and TREE what they do, a behavior tree written "
    "Node(required values, optional port=value, children). Use only the node types and places given."
)


def _cases(count: int = 50) -> list[tuple[str, list[str], list[str], int]]:
    rng = random.Random(7)
    worlds = [load_world(name) for name in ("hospital", "office", "residential", "airport")]
    cases = []
    for index in range(count):
        world = worlds[index % len(worlds)]
        names = [roi.name for roi in world.roi_index()]
        places = rng.sample(names, 5)
        sentence = rng.choice(VERBS).format(n=rng.randint(1, 30), who=rng.choice(PEOPLE), a=places[0], b=places[1])
        nodes = NODE_SETS[list(NODE_SETS)[index % len(NODE_SETS)]]
        cases.append((sentence, places, nodes, 1 + (index % 5 == 0)))
    return cases


def test_node_sets_are_manifest_llm_nodes():
    for nodes in NODE_SETS.values():
        assert all(NODES[name].llm for name in nodes)


@pytest.mark.slow
@pytest.mark.long  # bench/llm.py --compare measures draft validity of the embedded models on 20 prompts per run
@pytest.mark.timeout(1800)  # ~2 min on an idle 2-core machine; shared CI runners can be several times slower
def test_fifty_prompts_all_give_valid_drafts():
    cases = _cases()
    assert len({sentence for sentence, *_ in cases}) == 50
    with LocalLLM(embedded_model_path(), role="bt", n_ctx=2048) as llm:
        for sentence, places, nodes, max_groups in cases:
            grammar = draft_grammar(nodes, places, max_groups=max_groups, max_count=30, max_depth=2,
                                    max_children=2)
            messages = [{"role": "system", "content": SYSTEM},
                        {"role": "user", "content": f"Node types: {', '.join(nodes)}\nPlaces: {', '.join(places)}\n"
                                                    f"Scenario: {sentence}"}]
            result = llm.generate(messages, grammar=grammar, max_tokens=160, seed=0)
            assert result.finish_reason == "stop" and result.prompt_tokens > 50
            # Raises DraftError naming the line and draft path if the answer is not a valid draft for this request.
            parse_draft(result.text, nodes, places, max_groups=max_groups, max_count=30, max_depth=2, max_children=2)
