"""BehaviorTree.CPP 4 (behaviortreepy) with exactly HuNavSim 2.0's node IDs registered, as stubs.

behaviortreepy 0.1.4 registers Python leaves without a port list, so the ports of HuNavSim's nodes are
checked by grove_tui.bt.format.hunav_compat.hunav_loading_problems (the same check BT.CPP makes against a
registered manifest) and stripped for the load itself; BT.CPP built-ins keep theirs and BT.CPP checks them.

The stubs behave like HuNavSim's nodes as far as control flow goes: stateful actions run one tick
then succeed, the robot is never visible, everything else succeeds. `ticks` counts leaf ticks per ID.
"""

from __future__ import annotations

from collections import Counter

import behaviortreepy as bt
from lxml import etree

from grove_tui.bt.format.hunav_compat import HUNAV_NODES, hunav_loading_problems

STATEFUL = {"GoTo", "StopAndWaitTimerAction", "ConversationFormation", "ApproachAgent", "FollowAgent",
            "ApproachRobot", "BlockRobot", "AvoidRobot", "BlockAgent", "SetGroupWalk", "LookAtPoint",
            "LookAtAgent", "LookAtRobot"}
NEVER_TRUE = {"IsRobotVisible", "IsRobotClose", "IsRobotFacingAgent"}


class HunavSimFactory:
    def __init__(self) -> None:
        self.ticks: Counter[str] = Counter()
        self.factory = bt.BehaviorTreeFactory()
        for name, node in HUNAV_NODES.items():
            if node.category == "decorator":
                continue  # TimeDelay: a C++ decorator; the trees GROVE writes never use it
            if name in STATEFUL:
                self.factory.register_simple_stateful_action(name, self._start(name), self._running(name))
            elif node.category == "condition":
                self.factory.register_simple_condition(name, self._simple(name))
            else:
                self.factory.register_simple_action(name, self._simple(name))

    def _simple(self, name):
        def tick(node):
            self.ticks[name] += 1
            return bt.NodeStatus.FAILURE if name in NEVER_TRUE else bt.NodeStatus.SUCCESS
        return tick

    def _start(self, name):
        def start(node):
            self.ticks[name] += 1
            return bt.NodeStatus.RUNNING
        return start

    def _running(self, name):
        def running(node):
            return bt.NodeStatus.SUCCESS
        return running

    def load(self, xml: str):
        problems = hunav_loading_problems(xml)
        assert not problems, problems
        root = etree.fromstring(xml.encode())
        for el in root.iter():
            if isinstance(el.tag, str) and el.tag in HUNAV_NODES:
                for attribute in list(el.attrib):
                    if attribute != "name":
                        del el.attrib[attribute]
        for model in root.findall("TreeNodesModel"):
            root.remove(model)
        return self.factory.create_tree_from_text(etree.tostring(root, encoding="unicode"))
