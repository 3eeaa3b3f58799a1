"""Table tests: every control node and decorator against BehaviorTree.CPP v4 semantics.

Leaves are scripted: `S`/`F` conditions, and stateful actions `A` whose script (per activation)
lists what on_start/on_running return. Each row gives the statuses of successive ticks and, where
it matters, the leaf events in order ("a:start", "a:running", "a:halt", "c:check").
"""

from __future__ import annotations

import pytest

from grove_tui.bt.format.manifest import NODES, NodeSpec, PortSpec
from grove_tui.bt.runtime.blackboard import Blackboard
from grove_tui.bt.runtime.factory import TreeFactory
from grove_tui.bt.runtime.tree_node import (
    FAILURE, IDLE, RUNNING, SKIPPED, SUCCESS, ConditionNode, SimClock, StatefulActionNode, SyncActionNode,
)
from grove_tui.errors import BTError
from grove_tui.bt.format.xml import parse_tree_text

R, S, F, K = RUNNING, SUCCESS, FAILURE, SKIPPED
NAMES = {IDLE: "IDLE", R: "RUNNING", S: "SUCCESS", F: "FAILURE", K: "SKIPPED"}


class Harness:
    """Scripted leaves: <C id="x"/> conditions and <A id="x"/> actions, scripts given per test."""

    def __init__(self, scripts: dict[str, list[int]]):
        self.scripts = {k: list(v) for k, v in scripts.items()}
        self.calls = {k: 0 for k in scripts}
        self.log: list[str] = []

    def next(self, leaf: str) -> int:
        script = self.scripts[leaf]
        value = script[min(self.calls[leaf], len(script) - 1)]
        self.calls[leaf] += 1
        return value


def build(xml_body: str, scripts: dict[str, list[int]], clock: SimClock | None = None, blackboard=None,
          extra_trees: str = ""):
    harness = Harness(scripts)

    class C(ConditionNode):
        __slots__ = ()

        def tick(self):
            leaf = self.get_input("id")
            harness.log.append(f"{leaf}:check")
            return harness.next(leaf)

    class A(StatefulActionNode):
        __slots__ = ()

        def on_start(self):
            leaf = self.get_input("id")
            harness.log.append(f"{leaf}:start")
            return harness.next(leaf)

        def on_running(self):
            leaf = self.get_input("id")
            harness.log.append(f"{leaf}:running")
            return harness.next(leaf)

        def on_halted(self):
            harness.log.append(f"{self.get_input('id')}:halt")

    class Out(SyncActionNode):
        __slots__ = ()

        def tick(self):
            self.set_output("value", self.get_input("text"))
            return SUCCESS

    class Read(ConditionNode):
        __slots__ = ()

        def tick(self):
            harness.log.append(f"read:{self.get_input('number')}")
            return SUCCESS

    nodes = dict(NODES)
    nodes["C"] = NodeSpec("C", "condition", (PortSpec("id", "string"),), "scripted condition", "grove")
    nodes["A"] = NodeSpec("A", "action", (PortSpec("id", "string"),), "scripted action", "grove")
    nodes["Out"] = NodeSpec("Out", "action", (PortSpec("text", "string"), PortSpec("value", "string", direction="out")),
                            "writes its text to the blackboard", "grove")
    nodes["Read"] = NodeSpec("Read", "condition", (PortSpec("number", "float"),), "logs a number", "grove")
    xml = (f'<root BTCPP_format="4" main_tree_to_execute="Main"><BehaviorTree ID="Main">{xml_body}</BehaviorTree>'
           f'{extra_trees}</root>')
    document = parse_tree_text(xml, "<table>", nodes)
    tree = TreeFactory({"C": C, "A": A, "Out": Out, "Read": Read}, nodes).create(document, blackboard, None, clock)
    return tree, harness


def run(tree, harness, ticks: int, clock: SimClock | None = None, dt: float = 0.1):
    statuses, logs = [], []
    for _ in range(ticks):
        del harness.log[:]
        statuses.append(NAMES[tree.tick()])
        logs.append(list(harness.log))
        if clock is not None:
            clock.now += dt
    return statuses, logs


# ---- control nodes -------------------------------------------------------------------------------

CONTROL_TABLE = [
    # (id, xml, scripts, expected statuses, expected logs or None)
    ("sequence resumes at the running child",
     '<Sequence><C id="c"/><A id="a"/><C id="d"/></Sequence>',
     {"c": [S], "a": [R, R, S], "d": [S]},
     ["RUNNING", "RUNNING", "SUCCESS"],
     [["c:check", "a:start"], ["a:running"], ["a:running", "d:check"]]),
    ("sequence failure resets to the first child",
     '<Sequence><C id="c"/><C id="d"/></Sequence>',
     {"c": [S, S], "d": [F, S]},
     ["FAILURE", "SUCCESS"],
     [["c:check", "d:check"], ["c:check", "d:check"]]),
    ("sequence of skipped children is skipped",
     '<Sequence><RunOnce><C id="c"/></RunOnce></Sequence>',
     {"c": [S]},
     ["SUCCESS", "SKIPPED", "SKIPPED"],
     [["c:check"], [], []]),
    ("sequence with some skipped children succeeds",
     '<Sequence><RunOnce><C id="c"/></RunOnce><C id="d"/></Sequence>',
     {"c": [S], "d": [S]},
     ["SUCCESS", "SUCCESS"],
     [["c:check", "d:check"], ["d:check"]]),
    ("sequence with memory resumes at the failed child",
     '<SequenceWithMemory><A id="a"/><C id="c"/></SequenceWithMemory>',
     {"a": [R, S], "c": [F, S]},
     ["RUNNING", "FAILURE", "SUCCESS"],
     [["a:start"], ["a:running", "c:check"], ["c:check"]]),
    ("sequence with memory yields after a child completed within the tick",
     '<SequenceWithMemory><C id="c"/><C id="d"/></SequenceWithMemory>',
     {"c": [S], "d": [S]},
     ["RUNNING", "SUCCESS"],
     [["c:check"], ["d:check"]]),
    ("fallback tries children until one succeeds",
     '<Fallback><C id="c"/><A id="a"/></Fallback>',
     {"c": [F, F], "a": [R, S]},
     ["RUNNING", "SUCCESS"],
     [["c:check", "a:start"], ["a:running"]]),
    ("fallback fails when all fail, skipped ones included",
     '<Fallback><C id="c"/><RunOnce then_skip="true"><C id="d"/></RunOnce></Fallback>',
     {"c": [F], "d": [F]},
     ["FAILURE", "FAILURE"],
     [["c:check", "d:check"], ["c:check"]]),
    ("fallback of only skipped children is skipped",
     '<Fallback><RunOnce><C id="c"/></RunOnce></Fallback>',
     {"c": [F]},
     ["FAILURE", "SKIPPED"],
     [["c:check"], []]),
    ("reactive sequence halts the running child when a condition fails",
     '<ReactiveSequence><C id="c"/><A id="a"/></ReactiveSequence>',
     {"c": [S, S, F], "a": [R, R]},
     ["RUNNING", "RUNNING", "FAILURE"],
     [["c:check", "a:start"], ["c:check", "a:running"], ["c:check", "a:halt"]]),
    ("reactive fallback halts a running child when an earlier one succeeds",
     '<ReactiveFallback><C id="c"/><A id="a"/></ReactiveFallback>',
     {"c": [F, F, S], "a": [R, R]},
     ["RUNNING", "RUNNING", "SUCCESS"],
     [["c:check", "a:start"], ["c:check", "a:running"], ["c:check", "a:halt"]]),
    ("reactive fallback switches to the earlier running child and halts the later one",
     '<ReactiveFallback><Sequence><C id="c"/><A id="b"/></Sequence><A id="a"/></ReactiveFallback>',
     {"c": [F, S], "a": [R], "b": [R]},
     ["RUNNING", "RUNNING"],
     [["c:check", "a:start"], ["c:check", "b:start", "a:halt"]]),
    ("parallel succeeds at success_count and halts the rest",
     '<Parallel success_count="1" failure_count="2"><A id="a"/><A id="b"/></Parallel>',
     {"a": [R, S], "b": [R, R]},
     ["RUNNING", "SUCCESS"],
     [["a:start", "b:start"], ["a:running", "b:halt"]]),
    ("parallel fails at failure_count",
     '<Parallel success_count="-1" failure_count="1"><A id="a"/><C id="c"/></Parallel>',
     {"a": [R], "c": [F]},
     ["FAILURE"],
     [["a:start", "c:check", "a:halt"]]),
    ("parallel -1 means all; completed children are not ticked again",
     '<Parallel success_count="-1" failure_count="-1"><C id="c"/><A id="a"/></Parallel>',
     {"c": [S], "a": [R, S]},
     ["RUNNING", "SUCCESS"],
     [["c:check", "a:start"], ["a:running"]]),
]


@pytest.mark.parametrize("name,xml,scripts,statuses,logs", CONTROL_TABLE, ids=[row[0] for row in CONTROL_TABLE])
def test_control_nodes(name, xml, scripts, statuses, logs):
    tree, harness = build(xml, scripts)
    got_statuses, got_logs = run(tree, harness, len(statuses))
    assert got_statuses == statuses
    if logs is not None:
        assert got_logs == logs


DECORATOR_TABLE = [
    ("inverter swaps success and failure", '<Inverter><C id="c"/></Inverter>', {"c": [S, F]},
     ["FAILURE", "SUCCESS"], None),
    ("inverter passes running", '<Inverter><A id="a"/></Inverter>', {"a": [R, F]}, ["RUNNING", "SUCCESS"], None),
    ("inverter passes skipped", '<Inverter><RunOnce><C id="c"/></RunOnce></Inverter>', {"c": [S]},
     ["FAILURE", "SKIPPED"], None),
    ("force success", '<ForceSuccess><C id="c"/></ForceSuccess>', {"c": [F]}, ["SUCCESS"], None),
    ("force failure", '<ForceFailure><A id="a"/></ForceFailure>', {"a": [R, S]}, ["RUNNING", "FAILURE"], None),
    ("run once then skip", '<RunOnce><A id="a"/></RunOnce>', {"a": [R, F]},
     ["RUNNING", "FAILURE", "SKIPPED", "SKIPPED"], [["a:start"], ["a:running"], [], []]),
    ("run once then repeat the result", '<RunOnce then_skip="false"><C id="c"/></RunOnce>', {"c": [F, S]},
     ["FAILURE", "FAILURE", "FAILURE"], [["c:check"], [], []]),
    ("repeat hands control back after each synchronous cycle", '<Repeat num_cycles="3"><C id="c"/></Repeat>',
     {"c": [S]}, ["RUNNING", "RUNNING", "SUCCESS"], [["c:check"], ["c:check"], ["c:check"]]),
    ("repeat fails on child failure and restarts its count", '<Repeat num_cycles="2"><C id="c"/></Repeat>',
     {"c": [S, F, S, S]}, ["RUNNING", "FAILURE", "RUNNING", "SUCCESS"], None),
    ("repeat restarts an asynchronous child within the same tick", '<Repeat num_cycles="2"><A id="a"/></Repeat>',
     {"a": [R, S, R, S]}, ["RUNNING", "RUNNING", "SUCCESS"],
     [["a:start"], ["a:running", "a:start"], ["a:running"]]),
    ("retry until successful", '<RetryUntilSuccessful num_attempts="3"><C id="c"/></RetryUntilSuccessful>',
     {"c": [F, F, S]}, ["RUNNING", "RUNNING", "SUCCESS"], None),
    ("retry gives up after num_attempts", '<RetryUntilSuccessful num_attempts="2"><C id="c"/></RetryUntilSuccessful>',
     {"c": [F]}, ["RUNNING", "FAILURE"], None),
    ("keep running until failure", '<KeepRunningUntilFailure><C id="c"/></KeepRunningUntilFailure>',
     {"c": [S, S, F]}, ["RUNNING", "RUNNING", "FAILURE"], None),
]


@pytest.mark.parametrize("name,xml,scripts,statuses,logs", DECORATOR_TABLE, ids=[row[0] for row in DECORATOR_TABLE])
def test_decorators(name, xml, scripts, statuses, logs):
    tree, harness = build(xml, scripts)
    got_statuses, got_logs = run(tree, harness, len(statuses))
    assert got_statuses == statuses
    if logs is not None:
        assert got_logs == logs


def test_timeout_halts_the_child_in_simulation_time():
    clock = SimClock()
    tree, harness = build('<Timeout msec="250"><A id="a"/></Timeout>', {"a": [R]}, clock)
    statuses, logs = run(tree, harness, 5, clock, dt=0.1)
    # ticks at t = 0.0, 0.1, 0.2 run; at t = 0.3 >= 0.25 s the child is halted and Timeout fails
    assert statuses == ["RUNNING", "RUNNING", "RUNNING", "FAILURE", "RUNNING"]
    assert logs[3] == ["a:halt"]
    assert logs[4] == ["a:start"]


def test_timeout_passes_a_result_within_the_limit():
    clock = SimClock()
    tree, harness = build('<Timeout msec="1000"><A id="a"/></Timeout>', {"a": [R, S]}, clock)
    assert run(tree, harness, 2, clock)[0] == ["RUNNING", "SUCCESS"]


def test_delay_waits_simulation_time_before_the_first_tick_of_its_child():
    clock = SimClock()
    tree, harness = build('<Delay delay_msec="300"><C id="c"/></Delay>', {"c": [S]}, clock)
    statuses, logs = run(tree, harness, 5, clock, dt=0.1)
    assert statuses == ["RUNNING", "RUNNING", "RUNNING", "SUCCESS", "RUNNING"]
    assert logs[3] == ["c:check"] and logs[:3] == [[], [], []]


def test_delay_halted_restarts_its_wait():
    clock = SimClock()
    tree, harness = build('<ReactiveSequence><C id="g"/><Delay delay_msec="200"><C id="c"/></Delay></ReactiveSequence>',
                          {"g": [S, F, S, S, S], "c": [S]}, clock)
    statuses, logs = run(tree, harness, 5, clock, dt=0.1)
    # t=0 delay starts; t=0.1 guard fails (delay halted); t=0.2 restarts; fires at t=0.4
    assert statuses == ["RUNNING", "FAILURE", "RUNNING", "RUNNING", "SUCCESS"]


def test_hunavsim_time_delay_fails_until_the_delay_passed():
    clock = SimClock()
    tree, harness = build('<TimeDelay delay="0.2"><C id="c"/></TimeDelay>', {"c": [S]}, clock)
    assert run(tree, harness, 4, clock, dt=0.1)[0] == ["FAILURE", "FAILURE", "SUCCESS", "FAILURE"]


def test_hunavsim_regular_tree_relies_on_run_once_skipped():
    """HuNavSim 2.0's regular tree: goals are set once (RunOnce -> SKIPPED), then navigation forever."""
    xml = ('<Fallback><Sequence><RunOnce><C id="g1"/></RunOnce><Inverter><RunOnce><C id="g2"/></RunOnce></Inverter>'
           '</Sequence><Sequence><Inverter><C id="reached"/></Inverter><C id="nav"/></Sequence><C id="update"/>'
           '</Fallback>')
    tree, harness = build(xml, {"g1": [S], "g2": [S], "reached": [F, F, S], "nav": [S], "update": [S]})
    statuses, logs = run(tree, harness, 4)
    assert statuses == ["SUCCESS", "SUCCESS", "SUCCESS", "SUCCESS"]
    assert logs[0] == ["g1:check", "g2:check", "reached:check", "nav:check"]
    assert logs[1] == ["reached:check", "nav:check"]  # the goal setters are SKIPPED now
    assert logs[2] == ["reached:check", "update:check"]


def test_halt_resets_every_node_to_idle():
    tree, harness = build('<Sequence><C id="c"/><A id="a"/></Sequence>', {"c": [S], "a": [R]})
    assert tree.tick() == RUNNING
    tree.halt()
    assert harness.log[-1] == "a:halt"
    assert all(node.status == IDLE for node in tree.nodes)


def test_status_list_paths_and_skipped_display():
    tree, harness = build('<ReactiveSequence><RunOnce><C id="c"/></RunOnce><A id="a"/></ReactiveSequence>',
                          {"c": [S], "a": [R]})
    tree.tick()
    tree.tick()  # the reactive parent ticks RunOnce again: SKIPPED, while its stored status stays IDLE
    statuses = tree.status_list()
    assert [p for p, _, _ in statuses] == ["0", "0/0", "0/0/0", "0/1"]
    assert statuses[1][2] == "SKIPPED" and statuses[3][2] == "RUNNING"


# ---- blackboard and SubTree ----------------------------------------------------------------------

def test_blackboard_pointer_is_read_at_tick_time_and_converted_to_the_port_type():
    bb = Blackboard(values={"n": "2.5"})
    tree, harness = build('<Read number="{n}"/>', {}, blackboard=bb)
    tree.tick()
    bb.set("n", 4)
    tree.tick()
    assert harness.log == ["read:2.5", "read:4.0"]


def test_output_port_writes_the_blackboard_and_a_later_node_reads_it():
    tree, harness = build('<Sequence><Out text="7.25" value="{shared}"/><Read number="{shared}"/></Sequence>', {})
    assert tree.tick() == SUCCESS
    assert harness.log == ["read:7.25"]


def test_missing_blackboard_entry_is_an_error_naming_the_key():
    tree, _ = build('<Read number="{nowhere}"/>', {})
    with pytest.raises(BTError, match=r"\{nowhere\}"):
        tree.tick()


def test_subtree_port_remapping_and_literals():
    sub = ('<BehaviorTree ID="Sub"><Sequence><Out text="{greeting}" value="{result}"/><Read number="{k}"/>'
           '</Sequence></BehaviorTree>')
    bb = Blackboard(values={"parent_text": "3.5"})
    tree, harness = build('<SubTree ID="Sub" greeting="{parent_text}" result="{parent_result}" k="9"/>', {},
                          blackboard=bb, extra_trees=sub)
    assert tree.tick() == SUCCESS
    assert bb.get("parent_result") == "3.5"
    assert harness.log == ["read:9.0"]
    assert "k" not in bb and "result" not in bb  # the subtree's own entries stay private


def test_subtree_autoremap_shares_every_key_with_the_parent():
    sub = '<BehaviorTree ID="Sub"><Sequence><Out text="1.5" value="{x}"/><Read number="{y}"/></Sequence></BehaviorTree>'
    bb = Blackboard(values={"y": 2})
    tree, harness = build('<SubTree ID="Sub" _autoremap="true"/>', {}, blackboard=bb, extra_trees=sub)
    assert tree.tick() == SUCCESS
    assert bb.get("x") == "1.5"
    assert harness.log == ["read:2.0"]


def test_subtree_without_autoremap_does_not_see_parent_keys():
    sub = '<BehaviorTree ID="Sub"><Read number="{y}"/></BehaviorTree>'
    tree, _ = build('<SubTree ID="Sub"/>', {}, blackboard=Blackboard(values={"y": 2}), extra_trees=sub)
    with pytest.raises(BTError, match=r"\{y\}"):
        tree.tick()


def test_ports_of_different_types_on_one_entry_are_rejected():
    with pytest.raises(BTError, match="used as"):
        build('<Sequence><Repeat num_cycles="{v}"><C id="c"/></Repeat><Read number="{v}"/></Sequence>', {"c": [S]})


def test_parallel_threshold_larger_than_children_is_an_error():
    tree, _ = build('<Parallel success_count="3"><C id="c"/><C id="d"/></Parallel>', {"c": [S], "d": [S]})
    with pytest.raises(BTError, match="never succeed"):
        tree.tick()
