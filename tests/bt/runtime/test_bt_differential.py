"""Differential test: our runtime against BehaviorTree.CPP v4 itself (PyPI `behaviortreepy`).

Random trees of every control node and (clock-free) decorator over scripted leaves are ticked in both;
each tick must give the same root status and the same sequence of leaf events (start, running, halt,
condition checks). Timeout and Delay use BT.CPP's wall-clock timers, so they are covered by the table
tests in simulation time instead.
"""

from __future__ import annotations

import random
from dataclasses import dataclass

import pytest

from grove_tui.bt.format.manifest import NODES, NodeSpec
from grove_tui.bt.runtime.factory import TreeFactory
from grove_tui.bt.runtime.tree_node import FAILURE, RUNNING, SKIPPED, SUCCESS, ConditionNode, StatefulActionNode
from grove_tui.bt.format.xml import parse_tree_text

bt = pytest.importorskip("behaviortreepy")

N_TREES = 200
N_TICKS = 14
CONTROLS = ("Sequence", "SequenceWithMemory", "Fallback", "ReactiveSequence", "ReactiveFallback", "Parallel")
DECORATORS = ("Inverter", "RunOnce", "Repeat", "RetryUntilSuccessful", "KeepRunningUntilFailure", "ForceSuccess",
              "ForceFailure")
_BT_STATUS = {RUNNING: "RUNNING", SUCCESS: "SUCCESS", FAILURE: "FAILURE"}


@dataclass
class LeafScript:
    name: str
    kind: str  # "condition" | "action"
    results: tuple[int, ...]  # condition: per check; action: per on_start/on_running call


class RandomTree:
    def __init__(self, rng: random.Random):
        self.rng = rng
        self.leaves: list[LeafScript] = []

    def leaf(self) -> str:
        name = f"L{len(self.leaves)}"
        if self.rng.random() < 0.4:
            results = tuple(self.rng.choice((SUCCESS, FAILURE)) for _ in range(self.rng.randint(1, 4)))
            self.leaves.append(LeafScript(name, "condition", results))
        else:
            results = tuple(self.rng.choice((RUNNING, RUNNING, SUCCESS, FAILURE)) for _ in range(self.rng.randint(1, 5)))
            self.leaves.append(LeafScript(name, "action", results))
        return f'<{name}/>'

    def node(self, depth: int) -> str:
        r = self.rng.random()
        if depth >= 4 or r < 0.3:
            return self.leaf()
        if r < 0.55:
            deco = self.rng.choice(DECORATORS)
            attrs = ""
            if deco == "RunOnce":
                attrs = f' then_skip="{self.rng.choice(["true", "false"])}"'
            elif deco == "Repeat":
                attrs = f' num_cycles="{self.rng.randint(1, 3)}"'
            elif deco == "RetryUntilSuccessful":
                attrs = f' num_attempts="{self.rng.randint(1, 3)}"'
            return f"<{deco}{attrs}>{self.node(depth + 1)}</{deco}>"
        control = self.rng.choice(CONTROLS)
        n = self.rng.randint(1, 4)
        kids = "".join(self.node(depth + 1) for _ in range(n))
        attrs = ""
        if control == "Parallel":
            s = self.rng.choice([-1] + list(range(1, n + 1)))
            f = self.rng.choice([-1] + list(range(1, n + 1)))
            attrs = f' success_count="{s}" failure_count="{f}"'
        return f"<{control}{attrs}>{kids}</{control}>"

    def xml(self) -> str:
        body = self.node(0)
        return f'<root BTCPP_format="4" main_tree_to_execute="Main"><BehaviorTree ID="Main">{body}</BehaviorTree></root>'


def _run_btcpp(xml: str, leaves: list[LeafScript], ticks: int) -> list[tuple[str, list[str]]]:
    factory = bt.BehaviorTreeFactory()
    log: list[str] = []
    calls = {leaf.name: 0 for leaf in leaves}
    status_of = {SUCCESS: bt.NodeStatus.SUCCESS, FAILURE: bt.NodeStatus.FAILURE, RUNNING: bt.NodeStatus.RUNNING}

    def next_result(name: str) -> int:
        script = scripts[name]
        value = script.results[calls[name] % len(script.results)]
        calls[name] += 1
        return value

    scripts = {leaf.name: leaf for leaf in leaves}
    for leaf in leaves:
        if leaf.kind == "condition":
            def check(node, name=leaf.name):
                log.append(f"{name}:check")
                return status_of[next_result(name)]
            factory.register_simple_condition(leaf.name, check)
        else:
            def on_start(node, name=leaf.name):
                log.append(f"{name}:start")
                return status_of[next_result(name)]

            def on_running(node, name=leaf.name):
                log.append(f"{name}:running")
                return status_of[next_result(name)]

            def on_halted(node, name=leaf.name):
                log.append(f"{name}:halt")
            factory.register_simple_stateful_action(leaf.name, on_start, on_running, on_halted)
    tree = factory.create_tree_from_text(xml)
    out = []
    for _ in range(ticks):
        del log[:]
        status = tree.tick_exactly_once()
        out.append((status.name, list(log)))
    return out


def _run_ours(xml: str, leaves: list[LeafScript], ticks: int) -> list[tuple[str, list[str]]]:
    log: list[str] = []
    calls = {leaf.name: 0 for leaf in leaves}
    scripts = {leaf.name: leaf for leaf in leaves}

    def next_result(name: str) -> int:
        script = scripts[name]
        value = script.results[calls[name] % len(script.results)]
        calls[name] += 1
        return value

    class ScriptedCondition(ConditionNode):
        __slots__ = ()

        def tick(self):
            log.append(f"{self.node_id}:check")
            return next_result(self.node_id)

    class ScriptedAction(StatefulActionNode):
        __slots__ = ()

        def on_start(self):
            log.append(f"{self.node_id}:start")
            return next_result(self.node_id)

        def on_running(self):
            log.append(f"{self.node_id}:running")
            return next_result(self.node_id)

        def on_halted(self):
            log.append(f"{self.node_id}:halt")

    nodes = dict(NODES)
    classes = {}
    for leaf in leaves:
        nodes[leaf.name] = NodeSpec(leaf.name, leaf.kind, (), "scripted test leaf", "grove")
        classes[leaf.name] = ScriptedCondition if leaf.kind == "condition" else ScriptedAction
    document = parse_tree_text(xml, "<random>", nodes)
    tree = TreeFactory(classes, nodes).create(document)
    names = {RUNNING: "RUNNING", SUCCESS: "SUCCESS", FAILURE: "FAILURE", SKIPPED: "SKIPPED"}
    out = []
    for _ in range(ticks):
        del log[:]
        status = tree.tick()
        out.append((names[status], list(log)))
    return out


def _random_cases(count: int, seed: int):
    rng = random.Random(seed)
    for i in range(count):
        gen = RandomTree(rng)
        yield i, gen.xml(), gen.leaves


def test_random_trees_tick_like_behaviortree_cpp():
    mismatches = []
    compared_events = 0
    for i, xml, leaves in _random_cases(N_TREES, seed=20260521):
        expected = _run_btcpp(xml, leaves, N_TICKS)
        actual = _run_ours(xml, leaves, N_TICKS)
        compared_events += sum(len(events) for _, events in expected)
        if expected != actual:
            for tick, (e, a) in enumerate(zip(expected, actual)):
                if e != a:
                    mismatches.append(f"tree {i} tick {tick}: BT.CPP {e} vs ours {a}\n{xml}")
                    break
    assert not mismatches, f"{len(mismatches)} of {N_TREES} trees differ; first:\n" + "\n".join(mismatches[:3])
    assert compared_events > N_TREES * 5  # the leaves really were exercised


def test_generator_covers_every_control_node_and_decorator():
    seen = set()
    for _, xml, _ in _random_cases(N_TREES, seed=20260521):
        seen.update(name for name in CONTROLS + DECORATORS if f"<{name}" in xml)
    assert seen == set(CONTROLS + DECORATORS)
