"""Behavior-tree viewer: groups -> agents -> BT.CPP v4 nodes with their ports, live status by node path."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from rich.segment import Segment
from rich.style import Style
from rich.text import Text
from textual.binding import Binding
from textual.strip import Strip
from textual.widgets import Tree
from textual.widgets.tree import TreeNode

from grove_tui.services.trees import TreeDocument, TreeElement, behavior_trees

if TYPE_CHECKING:
    from grove_tui.scenario.model import AgentSpec

STATUS_CLASSES = {
    "RUNNING": "bt--running",
    "SUCCESS": "bt--success",
    "FAILURE": "bt--failure",
    "IDLE": "bt--idle",
    "SKIPPED": "bt--idle",
}
LONG_PORT_CHARS = 18


@dataclass(frozen=True)
class BTNode:
    """What a tree row stands for; `path` is the index path of the node inside its BehaviorTree."""

    kind: str  # "group", "agent", "node", "robot"
    agent_id: int = -1
    name: str = ""
    path: tuple[int, ...] = ()
    ports: dict[str, str] = field(default_factory=dict)


def short_port(value: str) -> str:
    if ";" in value and len(value) > LONG_PORT_CHARS:
        return f"[{value.count(';') + 1} pts]"
    return value if len(value) <= LONG_PORT_CHARS else value[: LONG_PORT_CHARS - 1] + "…"


def node_label(name: str, ports: dict[str, str]) -> Text:
    label = Text(name, style="bold")
    shown = [(k, v) for k, v in ports.items() if k not in ("name", "ID")]
    if shown:
        label.append(" ")
        label.append(" ".join(f"{k}={short_port(v)}" for k, v in shown), style="dim")
    return label


def path_key(path: tuple[int, ...] | str) -> str:
    return path if isinstance(path, str) else "/".join(str(i) for i in path)


class BTTree(Tree[BTNode]):
    HELP = """\
## Behavior trees

One branch per group, one per agent, then the agent's BehaviorTree.CPP nodes with their ports
(long waypoint lists are abbreviated; the panel below shows them all). **←/→** scroll long lines
sideways. Selecting an agent or a node highlights it on the map. During simulation each node shows its live status:
running, success, failure.
"""

    # Labels longer than the panel (ports at 80 columns) scroll sideways; Tree binds neither key itself.
    BINDINGS = [
        Binding("right", "scroll_right", "Scroll right", show=False, id="bt.scroll_right"),
        Binding("left", "scroll_left", "Scroll left", show=False, id="bt.scroll_left"),
    ]

    COMPONENT_CLASSES = {"bt--running", "bt--success", "bt--failure", "bt--idle"}
    DEFAULT_CSS = """
    BTTree > .bt--running { color: $warning; text-style: bold; }
    BTTree > .bt--success { color: $success; }
    BTTree > .bt--failure { color: $error; }
    BTTree > .bt--idle { color: $foreground-muted; }
    """

    def __init__(self, label: str = "Scenario", *, name: str | None = None, id: str | None = None,
                 classes: str | None = None, disabled: bool = False) -> None:
        super().__init__(label, name=name, id=id, classes=classes, disabled=disabled)
        self.show_root = False
        self.guide_depth = 2
        self._status: dict[str, str] = {}
        self._status_agent = -1
        self._nodes_by_path: dict[tuple[int, str], TreeNode[BTNode]] = {}
        self.agent_nodes: dict[int, TreeNode[BTNode]] = {}

    # building ----------------------------------------------------------------------------------------
    def add_agent_tree(self, parent: TreeNode[BTNode], agent_id: int, document: TreeDocument | None,
                       expand: bool = False) -> None:
        if document is None:
            parent.add_leaf(Text("no tree", style="italic"), BTNode("node", agent_id, "error"))
            return
        trees = behavior_trees(document)
        for tree_index, tree in enumerate(trees):
            container = parent if tree_index == 0 else parent.add(
                Text(f"SubTree {tree.get('ID', '')}", style="italic"), BTNode("node", agent_id, tree.get("ID") or ""))
            for child_index, element in enumerate(tree.children):
                self._add_element(container, agent_id, element, (child_index,) if tree_index == 0 else (), expand)

    def _add_element(self, parent: TreeNode[BTNode], agent_id: int, element: TreeElement,
                     path: tuple[int, ...], expand: bool) -> None:
        ports = dict(element.attributes)
        data = BTNode("node", agent_id, element.id, path, ports)
        label = node_label(element.id, ports)
        children = element.children
        if not children:
            node = parent.add_leaf(label, data)
        else:
            node = parent.add(label, data, expand=expand)
            for index, child in enumerate(children):
                self._add_element(node, agent_id, child, path + (index,) if path else (), expand)
        if path:
            self._nodes_by_path[(agent_id, path_key(path))] = node

    def add_agent(self, parent: TreeNode[BTNode], agent: AgentSpec, document: TreeDocument | None, expand: bool = False,
                  destination: str = "") -> TreeNode[BTNode]:
        """An agent's row ("agent 3 Regular → pharmacy_counter": where it is going) and its tree."""
        label = Text(f"agent {agent.id}", style="bold")
        label.append(f" {agent.behavior} → {destination}" if destination else f" {agent.behavior}", style="dim")
        node = parent.add(label, BTNode("agent", agent.id, f"agent {agent.id}"), expand=expand)
        self.agent_nodes[agent.id] = node
        self.add_agent_tree(node, agent.id, document, expand=expand)
        return node

    def add_runtime_tree(self, parent: TreeNode[BTNode], agent_id: int,
                         statuses: list[tuple[str, str, str]]) -> None:
        """The tree as the simulation runs it (reaction wrappers and SubTrees included), from tree_status."""
        nodes: dict[str, TreeNode[BTNode]] = {}
        paths = [path_key(path) for path, _name, _status in statuses]
        has_children = {p.rsplit("/", 1)[0] for p in paths if "/" in p}
        for key, (_path, name, _status) in zip(paths, statuses):
            container = nodes.get(key.rsplit("/", 1)[0], parent) if "/" in key else parent
            data = BTNode("node", agent_id, name, tuple(int(i) for i in key.split("/") if i.isdigit()))
            label = Text(name, style="bold")
            node = container.add(label, data, expand=True) if key in has_children else container.add_leaf(label, data)
            nodes[key] = node
            self._nodes_by_path[(agent_id, key)] = node

    def clear_all(self) -> None:
        self.clear()
        self._nodes_by_path.clear()
        self.agent_nodes.clear()
        self._status.clear()

    # rows cut by the panel's edge ---------------------------------------------------------------------
    def _render_line(self, y: int, x1: int, x2: int, base_style: Style) -> Strip:
        """A row longer than the panel ends with "…" at its right edge (←/→ scroll to read the rest)."""
        strip = super()._render_line(y, x1, x2, base_style)
        lines = self._tree_lines
        if y >= len(lines) or x2 - x1 < 2:
            return strip
        line = lines[y]
        if line._get_guide_width(self.guide_depth, self.show_root) + self.get_label_width(line.node) <= x2:
            return strip
        last = list(strip.crop(x2 - x1 - 1, x2 - x1))
        style = last[-1].style if last else None
        return Strip.join([strip.crop(0, x2 - x1 - 1), Strip([Segment("…", style)], 1)])

    # live status -------------------------------------------------------------------------------------
    def set_status(self, agent_id: int, statuses: list[tuple[str, str, str]]) -> None:
        """Statuses from Simulation.tree_status: (node path, node name, status); repaints changed rows only."""
        new = {path_key(path): str(status).upper() for path, _name, status in statuses}
        if agent_id == self._status_agent and new == self._status:
            return
        changed = set(new.items()) ^ set(self._status.items()) if agent_id == self._status_agent else None
        self._status, self._status_agent = new, agent_id
        if changed is None:
            self.refresh()
            return
        for key in {k for k, _ in changed}:
            node = self._nodes_by_path.get((agent_id, key))
            if node is not None:
                node.refresh()

    def render_label(self, node: TreeNode[BTNode], base_style: Style, style: Style) -> Text:
        label = super().render_label(node, base_style, style)
        data = node.data
        if data is None or data.kind != "node" or data.agent_id != self._status_agent:
            return label
        status = self._status.get(path_key(data.path)) if data.path else None
        if status is None:
            return label
        status_style = self.get_component_rich_style(STATUS_CLASSES.get(status, "bt--idle"), partial=True)
        marker = {"RUNNING": "▶ ", "SUCCESS": "✓ ", "FAILURE": "✗ "}.get(status, "· ")
        return Text.assemble((marker, status_style), label)
