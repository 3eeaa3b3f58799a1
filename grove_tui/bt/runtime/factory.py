"""The factory and the tree it builds (BT.CPP's bt_factory.cpp and Tree): a validated TreeDocument
becomes nodes bound to a blackboard, a simulation clock and the agent's context.

BehaviorTree.tick is Tree::tickExactlyOnce: the root is reset to IDLE after it completes. The
differential test (tests/bt/runtime/test_bt_differential.py) compares this runtime with BT.CPP itself through
`behaviortreepy`.
"""

from __future__ import annotations

from collections.abc import Mapping

from grove_tui.bt.runtime.blackboard import Blackboard, BlackboardRef
from grove_tui.bt.runtime.controls import (
    CONTROL_CLASSES, Fallback, Parallel, ReactiveFallback, ReactiveSequence, Sequence, SequenceWithMemory,
)
from grove_tui.bt.runtime.decorators import (
    CLOCKED_DECORATORS, DECORATOR_CLASSES, ForceFailure, ForceSuccess, Inverter, KeepRunningUntilFailure,
    Repeat, RetryUntilSuccessful, RunOnce, SubTreeNode,
)
from grove_tui.bt.format.document import TreeDocument, TreeElement
from grove_tui.bt.format.ports import checked_port, satisfied_by_goal_id
from grove_tui.bt.runtime.leaves import BTCPP_LEAVES
from grove_tui.bt.format.manifest import NODES, SUBTREE, NodeSpec
from grove_tui.bt.format.ports import PortValue, blackboard_pointer, convert_literal
from grove_tui.bt.runtime.tree_node import (
    FAILURE, IDLE, RUNNING, STATUS_NAMES, SUCCESS, ConditionNode, DecoratorNode, LeafNode, SimClock, TreeNode,
)
from grove_tui.bt.format.xml import parse_tree_text
from grove_tui.errors import BTError

# Nodes that, while their (one) running child stays RUNNING, return RUNNING and change nothing else.
_PASS_THROUGH = (Sequence, SequenceWithMemory, Fallback, SubTreeNode, Inverter, ForceSuccess, ForceFailure, RunOnce,
                 Repeat, RetryUntilSuccessful, KeepRunningUntilFailure)


class BehaviorTree:
    """One instantiated tree: tick it once per BT period (Tree::tickExactlyOnce).

    Quiescent ticks are skipped without changing the semantics: when the only running leaf sits below
    pass-through nodes (and reactive nodes whose earlier children are side-effect-free conditions) and
    that leaf's `poll()` says its on_running would just return RUNNING, a full tick would change no
    state at all, so `tick` re-checks the reactive guards, polls the leaf and returns RUNNING.
    tests/simulation/test_simulation_fastpath.py runs scenarios both ways and compares them.
    """

    __slots__ = ("root", "blackboard", "nodes", "source", "clock", "fast", "quiet")

    def __init__(self, root: TreeNode, blackboard: Blackboard, nodes: list[TreeNode], source: str, clock: SimClock):
        self.root = root
        self.blackboard = blackboard
        self.nodes = nodes
        self.source = source
        self.clock = clock
        self.fast = True  # allow quiescent-tick skipping
        self.quiet: tuple[LeafNode, tuple[tuple[TreeNode, int], ...]] | None = None

    def tick(self) -> int:
        quiet = self.quiet
        if quiet is not None:
            leaf, guards = quiet
            for condition, expected in guards:
                if condition.tick() != expected:
                    break
            else:
                if leaf.poll():
                    return RUNNING
        root = self.root
        status = root.execute_tick()
        if status == SUCCESS or status == FAILURE:
            root.status = IDLE
            self.quiet = None
        elif status == RUNNING and self.fast:
            self.quiet = self._quiescent_path()
        else:
            self.quiet = None
        return status

    def _quiescent_path(self) -> tuple[LeafNode, tuple[tuple[TreeNode, int], ...]] | None:
        node = self.root
        guards: list[tuple[TreeNode, int]] = []
        while True:
            if node.status != RUNNING:
                return None
            if isinstance(node, LeafNode):
                return (node, tuple(guards)) if node.polls() else None
            if isinstance(node, _PASS_THROUGH):
                if isinstance(node, DecoratorNode):
                    node = node.child
                else:
                    node = node.kids[node.current]
                continue
            if isinstance(node, (ReactiveFallback, ReactiveSequence)):
                expected = FAILURE if isinstance(node, ReactiveFallback) else SUCCESS
                kids = node.kids
                running = next((i for i, kid in enumerate(kids) if kid.status == RUNNING), -1)
                if running < 0:
                    return None
                for kid in kids[:running]:
                    guard = _pure_guard(kid, expected)
                    if guard is None:
                        return None
                    guards.append(guard)
                node = kids[running]
                continue
            return None

    def halt(self) -> None:
        self.root.halt_node()

    def status_list(self) -> list[tuple[str, str, str]]:
        """(path, name, status) of every node in depth-first order.

        A node reset to IDLE after it completed shows its last result (SUCCESS/FAILURE/SKIPPED), as
        Groot2 does, so a finished tree still tells how it ended; a halted node shows IDLE.
        """
        out = []
        for node in self.nodes:
            shown = node.status if node.status != IDLE or node.last == RUNNING else node.last
            label = node.node_id if node.name == node.node_id else f"{node.node_id} {node.name!r}"
            out.append((node.path, label, STATUS_NAMES[shown]))
        return out

    def leaves(self) -> list[LeafNode]:
        return [n for n in self.nodes if isinstance(n, LeafNode)]


def _pure_guard(node: TreeNode, expected: int) -> tuple[TreeNode, int] | None:
    """(condition, status) whose side-effect-free tick decides what re-ticking `node` returns, if any."""
    if isinstance(node, ConditionNode):
        return (node, expected) if getattr(node, "PURE", False) else None
    if isinstance(node, Inverter) and expected in (SUCCESS, FAILURE):
        return _pure_guard(node.child, SUCCESS if expected == FAILURE else FAILURE)
    if expected == FAILURE and node.status == IDLE and (
            isinstance(node, ReactiveSequence) or (isinstance(node, Sequence) and node.current == 0)):
        return _pure_guard(node.kids[0], FAILURE)  # a sequence whose first child fails fails at once
    return None


LeafClasses = Mapping[str, type[LeafNode]]


class TreeFactory:
    """Instantiates parsed TreeDocuments with the leaf classes of a node set."""

    def __init__(self, leaf_classes: LeafClasses, nodes: Mapping[str, NodeSpec] = NODES):
        self.leaf_classes = dict(BTCPP_LEAVES)
        self.leaf_classes.update(leaf_classes)
        self.nodes = nodes

    def create(self, document: TreeDocument, blackboard: Blackboard | None = None, ctx: object = None,
               clock: SimClock | None = None) -> BehaviorTree:
        blackboard = blackboard if blackboard is not None else Blackboard()
        clock = clock if clock is not None else SimClock()
        slots: list[TreeNode | None] = []
        root = self._build(document, document.main, blackboard, ctx, clock, slots, "0", (document.main_tree_id,))
        nodes = [node for node in slots if node is not None]  # every slot is filled once its subtree is built
        return BehaviorTree(root, blackboard, nodes, document.source, clock)

    def _inputs(self, spec: NodeSpec, element: TreeElement, blackboard: Blackboard,
                where: str) -> tuple[dict[str, PortValue | BlackboardRef], dict[str, str]]:
        inputs: dict[str, PortValue | BlackboardRef] = {}
        outputs: dict[str, str] = {}
        written = element.ports
        for port in spec.ports:
            text = written.get(port.name)
            if port.direction == "out":
                if text is not None:
                    key = blackboard_pointer(text)
                    if key is None:
                        raise BTError(f"{where}: output port {port.name!r} must be a {{key}}")
                    blackboard.declare(key, port.type, where)
                    outputs[port.name] = key
                continue
            if text is None:
                default = port.default
                key = blackboard_pointer(default) if isinstance(default, str) else None
                if key is not None:
                    inputs[port.name] = BlackboardRef(blackboard, key, port, where)
                elif default is not None:
                    inputs[port.name] = default
                elif port.required and not satisfied_by_goal_id(port, written):
                    raise BTError(f"{where}: missing required port {port.name!r}")
                continue
            key = blackboard_pointer(text)
            if key is not None:
                blackboard.declare(key, port.type, where)
                inputs[port.name] = BlackboardRef(blackboard, key, checked_port(spec, port), where)
            else:
                try:
                    inputs[port.name] = convert_literal(checked_port(spec, port), text)
                except ValueError as exc:
                    raise BTError(f"{where}: port {port.name!r}: {exc}") from None
        return inputs, outputs

    def _build(self, document: TreeDocument, element: TreeElement, blackboard: Blackboard, ctx: object,
               clock: SimClock, nodes: list[TreeNode | None], path: str, call_chain: tuple[str, ...]) -> TreeNode:
        where = f"{document.source}:{element.line}" if element.line else document.source
        index = len(nodes)
        nodes.append(None)  # reserve the depth-first slot before the children
        if element.id == SUBTREE:
            tree_id = element.subtree_id
            if tree_id in call_chain:
                raise BTError(f"{where}: SubTree recursion through {tree_id!r}")
            if tree_id not in document.trees:
                raise BTError(f"{where}: SubTree refers to unknown BehaviorTree {tree_id!r}")
            child_bb = Blackboard(parent=blackboard, autoremap=element.autoremap)
            for port_name, value in element.ports.items():
                key = blackboard_pointer(value)
                if key is not None:
                    child_bb.add_remapping(port_name, key)
                else:
                    child_bb.set(port_name, value)
            child = self._build(document, document.root_of(tree_id), child_bb, ctx, clock, nodes, path + "/0",
                                call_chain + (tree_id,))
            node: TreeNode = SubTreeNode(element.name, child, tree_id)
        else:
            spec = self.nodes.get(element.id)
            if spec is None:
                raise BTError(f"{where}: unknown node {element.id!r}")
            inputs, outputs = self._inputs(spec, element, blackboard, where)
            if spec.category == "control":
                kids = [self._build(document, c, blackboard, ctx, clock, nodes, f"{path}/{i}", call_chain)
                        for i, c in enumerate(element.children)]
                control = CONTROL_CLASSES.get(element.id)
                if control is None:
                    raise BTError(f"{where}: no implementation for control node {element.id!r}")
                if control is Parallel:
                    success, failure = inputs.get("success_count", -1), inputs.get("failure_count", 1)
                    if not isinstance(success, (int, BlackboardRef)) or not isinstance(failure, (int, BlackboardRef)):
                        raise BTError(f"{where}: Parallel's success_count and failure_count are whole numbers")
                    node = Parallel(element.name, kids, success, failure)
                else:
                    node = control(element.name, kids)
            elif spec.category == "decorator":
                if len(element.children) != 1:
                    raise BTError(f"{where}: {element.id} needs exactly one child")
                child = self._build(document, element.children[0], blackboard, ctx, clock, nodes, path + "/0",
                                    call_chain)
                decorator = DECORATOR_CLASSES.get(element.id)
                if decorator is None:
                    raise BTError(f"{where}: no implementation for decorator {element.id!r}")
                args = [inputs[p.name] for p in spec.ports if p.name in inputs]
                if element.id in CLOCKED_DECORATORS:
                    node = decorator(element.name, child, *args, clock=clock)
                else:
                    node = decorator(element.name, child, *args)
            else:
                leaf = self.leaf_classes.get(element.id)
                if leaf is None:
                    raise BTError(f"{where}: no implementation for node {element.id!r} in this runtime")
                node = leaf(element.name, inputs, outputs, blackboard, ctx, element.id)
            node.node_id = element.id
        node.path = path
        node.line = element.line
        nodes[index] = node
        return node


def build_tree_from_text(text: str, leaf_classes: LeafClasses, *, nodes: Mapping[str, NodeSpec] = NODES,
                         blackboard: Blackboard | None = None, ctx: object = None, clock: SimClock | None = None,
                         source: str = "<string>") -> BehaviorTree:
    document = parse_tree_text(text, source, nodes)
    return TreeFactory(leaf_classes, nodes).create(document, blackboard, ctx, clock)
