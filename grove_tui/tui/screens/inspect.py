"""Inspect: the generated behavior trees next to the map with spawns, goals, waypoints and fields."""

from __future__ import annotations

import math
from collections import defaultdict
from typing import TYPE_CHECKING

import numpy as np
from rich.text import Text
from textual import on, work
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical
from textual.screen import Screen
from textual.widgets import Static, TextArea, Tree

from grove_tui.errors import describe_error
from grove_tui.tui import messages as msg
from grove_tui.services.session import GeneratedScenario
from grove_tui.services.trees import TreeDocument, parse_point_list, tree_text
from grove_tui.tui.widgets.bt_tree import BTNode, BTTree
from grove_tui.tui.widgets.grounding import GroundingPanel, read_grounding, summary
from grove_tui.tui.widgets.map_raster import Overlay
from grove_tui.tui.widgets.map_legend import FIELD, INSPECT_SYMBOLS, ROBOT_PATH, MapLegend
from grove_tui.tui.widgets.map_view import MapView
from grove_tui.tui.widgets.followup import FollowupBox, FollowupInput
from grove_tui.tui.widgets.footer import Footer

if TYPE_CHECKING:
    from grove_tui.jsontypes import Parsed
    from grove_tui.scenario.model import AgentSpec, Scenario
    from grove_tui.services.domain import World
    from grove_tui.tui.app import GroveApp
    from grove_tui.tui.commands import CommandEntry
    from grove_tui.tui.screens.export import ExportProgressScreen


def agent_tree(generated: GeneratedScenario, agent: AgentSpec) -> TreeDocument | None:
    """The agent's tree document as generation (or the bundle reader) gave it; None if it has none."""
    tree: TreeDocument | None = generated.result.trees.get(agent.tree)
    return tree


def agent_xml(generated: GeneratedScenario, agent: AgentSpec) -> str:
    """The agent's tree as the XML its bundle file holds, for the XML view."""
    document = agent_tree(generated, agent)
    return tree_text(document) if document is not None else ""


def group_key(agent: AgentSpec) -> tuple[int, str]:
    return (agent.group, agent.label or (f"group {agent.group}" if agent.group >= 0 else "ungrouped"))


def base_overlay(generated: GeneratedScenario) -> Overlay:
    scenario = generated.scenario
    agents = scenario.agents
    spawns = np.array([a.start for a in agents], dtype=np.float64).reshape(-1, 2)
    goals = np.array([a.goals[-1] for a in agents if a.goals], dtype=np.float64).reshape(-1, 2)
    waypoints = np.array([g for a in agents for g in a.goals[:-1]], dtype=np.float64).reshape(-1, 2)
    robot_path = np.zeros((0, 2))
    if scenario.robot is not None:
        robot_path = np.array(scenario.robot.path or (scenario.robot.start, scenario.robot.goal), dtype=np.float64)
    fields = tuple(generated.result.fields.values()) if isinstance(generated.result.fields, dict) else ()
    return Overlay(spawns=spawns, goals=goals, waypoints=waypoints, robot_path=robot_path, fields=fields)


def highlight_for(generated: GeneratedScenario, data: BTNode | None, overlay: Overlay) -> Overlay:
    if data is None:
        return overlay
    from dataclasses import replace

    agents = {a.id: a for a in generated.scenario.agents}
    agent = agents.get(data.agent_id)
    if data.kind == "robot" and generated.scenario.robot is not None:
        robot = generated.scenario.robot
        return replace(overlay, highlight_path=overlay.robot_path, highlight_points=np.array([robot.start, robot.goal]))
    if agent is None:
        return overlay
    if data.kind == "node":
        ports = data.ports
        if "waypoints" in ports and ports["waypoints"].strip():
            points = parse_points(ports["waypoints"])
            if len(points):
                return replace(overlay, highlight_path=points, highlight_points=points[-1:])
        if "x" in ports and "y" in ports:
            try:
                point = np.array([[float(ports["x"]), float(ports["y"])]])
            except ValueError:
                point = None
            if point is not None:
                return replace(overlay, highlight_points=point)
    path = np.array([agent.start, *agent.goals], dtype=np.float64)
    return replace(overlay, highlight_path=path, highlight_points=path[:1])


DESTINATION_REACH = 0.75  # metres: a final goal this close to an entity's interaction point is at that entity


def destination(agent: AgentSpec, world: World | None) -> str:
    """Where an agent is going: the entity its last goal serves (a counter, a bed), else the zone that
    holds it, else the door nearest to it (an exit), else its coordinates; "" with no goal."""
    if not agent.goals:
        return ""
    x, y = (float(v) for v in agent.goals[-1])
    if world is None:
        return f"({x:.1f}, {y:.1f})"
    near = [(math.dist(e.interaction_point, (x, y)), e.name) for e in world.entities()]
    if near and min(near)[0] <= DESTINATION_REACH:
        return min(near)[1]
    zone = world.zone_at(x, y)
    if zone is not None:
        return str(zone.name)
    doors = [(math.dist(d.position, (x, y)), d.name) for d in world.doors()]
    if doors and min(doors)[0] <= 2 * DESTINATION_REACH:
        return min(doors)[1]
    return f"({x:.1f}, {y:.1f})"


def busiest_goal(scenario: Scenario) -> tuple[float, float] | None:
    """The final goal most agents share (a queue's counter, an exit), to the nearest half metre."""
    goals = [tuple(np.round(np.asarray(a.goals[-1], dtype=np.float64) * 2) / 2) for a in scenario.agents if a.goals]
    if not goals:
        return None
    x, y = max(set(goals), key=goals.count)
    return float(x), float(y)


def parse_points(text: str) -> np.ndarray:
    """A BT.CPP point list ('x,y;x,y;...') as an (N, 2) array; malformed text shows no points."""
    try:
        points = parse_point_list(text)
    except ValueError:
        points = ()
    return np.array(points, dtype=np.float64).reshape(-1, 2)


class InspectScreen(Screen[None]):
    HELP = """\
## Inspect

Left: the behavior trees, by group and agent, with each node's ports. Right: the map with spawns
`○`, goals `◎`, injected waypoints `·`, the robot's path and any velocity-field arrows. Move through
the tree to highlight an agent's route or a node's target on the map. **x** shows the selected
agent's XML, **a** shows the grounding report (per group: what the sentence asked beside what
the scenario does, ✓ or ✗ with the reason), **p** plays the simulation, **g** regenerates with the next seed (asking whether to
keep your count edits), **c** edits each group's head count and re-plans (same trees, no model
call), **e** exports the bundle. **f** types a follow-up that edits the scenario ("add a cleaner
mopping the corridor", "make the queue twice as long", "remove the cleaner", "no robot"): what it
would change is shown first, and only the groups it names change. **ctrl+z** undoes an edit (a
follow-up or counts), **ctrl+y** redoes it. **Escape** goes back to setup; it asks first when the
scenario has not been exported (it stays in the recent runs, **ctrl+o** on setup).
"""

    BINDINGS = [
        Binding("p", "simulate", "Play", id="inspect.simulate", tooltip="Simulate this scenario"),
        Binding("x", "toggle_xml", "XML", id="inspect.xml", tooltip="Show the selected agent's BT XML"),
        Binding("a", "toggle_grounding", "Grounding", id="inspect.grounding",
                tooltip="What the sentence asked beside what the scenario does, per group", show=False),
        # Not in the footer: at 80 columns it would push out quit and help; the trees' border shows
        # the verdict with the key ("2/3 groups ✓ · a"), and F1 lists it.
        Binding("g", "regenerate", "Regenerate", id="inspect.regenerate", tooltip="Generate again with the next seed"),
        Binding("c", "edit_counts", "Counts", id="inspect.counts",
                tooltip="Edit each group's head count and re-plan, without the model"),
        Binding("e", "export", "Export", id="inspect.export", tooltip="Export the bundle"),
        Binding("f", "followup", "Follow-up", id="inspect.followup",
                tooltip="Type a sentence that edits the scenario (add, change, remove a group; the robot)",
                show=False),  # not in the footer at 80 columns: the box itself says "f: follow-up"
        Binding("ctrl+z", "undo", "Undo", id="inspect.undo", tooltip="Undo the last edit (follow-up or counts)",
                show=False),
        Binding("ctrl+y", "redo", "Redo", id="inspect.redo", tooltip="Redo the edit undone last", show=False),
        Binding("m", "focus_map", "Map", id="inspect.map", tooltip="Focus the map to zoom and pan"),
        Binding("t", "focus_tree", "Trees", id="inspect.tree", tooltip="Focus the behavior trees", show=False),
        Binding("escape", "back", "Back", id="inspect.back", tooltip="Back to setup"),
    ]

    def __init__(self, generated: GeneratedScenario, *, reopened: bool = False,
                 count_edits: dict[str, int] | None = None) -> None:
        super().__init__()
        self.generated = generated
        # A reopened run is already where the user found it; a new one asks before Escape leaves it.
        self.unsaved = not reopened
        # Head counts the user set, by group label, offered again when regenerating with a new seed.
        self.count_edits: dict[str, int] = dict(count_edits or {})
        self._overlay = base_overlay(generated)
        self._selected_node: BTNode | None = None
        self._export_progress: ExportProgressScreen | None = None
        # Scenarios before each edit (follow-ups, counts) and after each undo: every one keeps its bundle.
        self.undo_stack: list[GeneratedScenario] = []
        self.redo_stack: list[GeneratedScenario] = []

    @property
    def grove(self) -> GroveApp:
        return self.app  # type: ignore[return-value]

    def compose(self) -> ComposeResult:
        scenario = self.generated.scenario
        with Horizontal(id="inspect-body"):
            with Vertical(id="inspect-side"):
                tree = BTTree("Scenario", id="bt-tree")
                tree.border_title = f"Trees · {len(scenario.agents)} agents"
                yield tree
                # Soft wrap: at 80 columns a node's ports run far past the panel, and a read-only view has
                # no reason to make the user scroll sideways to read them.
                xml = TextArea("", id="xml", read_only=True, show_line_numbers=False, soft_wrap=True)
                xml.border_title = "XML"
                xml.display = False
                yield xml
                grounding = GroundingPanel(self.generated.result.report, id="grounding")
                grounding.display = False
                yield grounding
                yield Static("", id="node-detail", markup=False)
            with Vertical(id="inspect-map-column"):
                world_map = MapView(id="inspect-map")
                world_map.border_title = f"{scenario.world} · {scenario.preset}"
                world_map.border_subtitle = self.generated.prompt[:70]
                world_map.zoom_target = self._zoom_target
                legend = MapLegend("", id="inspect-legend")
                world_map.legend = legend
                yield world_map
                yield legend
        yield FollowupBox(id="followup")
        yield Footer(compact=True, show_command_palette=False)

    def on_mount(self) -> None:
        self.query_one("#inspect-map", MapView).set_world(self.generated.world)
        self._show_generated()

    def _show_generated(self) -> None:
        """Trees, map overlay and titles of `self.generated`, the first agent selected."""
        self._overlay = base_overlay(self.generated)
        self._selected_node = None
        self._build_tree()
        world_map = self.query_one("#inspect-map", MapView)
        world_map.set_overlay(self._overlay)
        world_map.border_subtitle = self.generated.prompt[:70]
        symbols = list(INSPECT_SYMBOLS)
        if len(self._overlay.robot_path):
            symbols.append(ROBOT_PATH)
        if self._overlay.fields:
            symbols.append(FIELD)
        self.query_one("#inspect-legend", MapLegend).show_symbols(world_map, symbols)
        tree = self.query_one("#bt-tree", BTTree)
        tree.border_title = f"Trees · {len(self.generated.scenario.agents)} agents"
        # The verdict shows on the trees' border, so a ✗ is seen without opening the report.
        counted = summary(read_grounding(self.generated.result.report))
        tree.border_subtitle = f"{counted} · a: report" if counted else ""
        self.query_one("#grounding", GroundingPanel).show(self.generated.result.report)
        self.query_one("#node-detail", Static).update("")
        self._show_side("tree")
        if tree.agent_nodes:
            # Start on the first agent so its route is highlighted straight away.
            self.call_after_refresh(self._select_first_agent)

    def _zoom_target(self) -> tuple[float, float] | None:
        """Zoom centres on the selection's point on the map, else on where most people are going."""
        shown = highlight_for(self.generated, self._selected_node, self._overlay)
        if len(shown.highlight_points):
            return float(shown.highlight_points[0][0]), float(shown.highlight_points[0][1])
        return busiest_goal(self.generated.scenario)

    def _select_first_agent(self) -> None:
        tree = self.query_one("#bt-tree", BTTree)
        if not tree.agent_nodes:
            return
        first_agent = tree.agent_nodes[min(tree.agent_nodes)]
        tree.move_cursor(first_agent)
        if self._selected_node is None:
            # A rebuilt tree whose cursor was already on that line posts no NodeHighlighted.
            self._select(first_agent.data)

    def _build_tree(self) -> None:
        tree = self.query_one("#bt-tree", BTTree)
        tree.clear_all()
        scenario = self.generated.scenario
        groups: dict[tuple[int, str], list[AgentSpec]] = defaultdict(list)
        for agent in scenario.agents:
            groups[group_key(agent)].append(agent)
        for index, ((_group, label), agents) in enumerate(sorted(groups.items(), key=lambda kv: kv[1][0].id)):
            group_label = Text(label, style="bold")
            group_label.append(f" ×{len(agents)}", style="dim")
            group_node = tree.root.add(group_label, BTNode("group", agents[0].id, label), expand=index == 0)
            for agent_index, agent in enumerate(agents):
                tree.add_agent(group_node, agent, agent_tree(self.generated, agent), expand=index == 0 and agent_index == 0,
                               destination=destination(agent, self.generated.world))
        if scenario.robot is not None:
            robot = scenario.robot
            tree.root.add_leaf(
                Text.assemble(("robot", "bold"), (f" {len(robot.path)} path points, {robot.max_vel} m/s", "dim")),
                BTNode("robot", 0, "robot"))
        tree.root.expand()

    def command_entries(self) -> list[CommandEntry]:
        return [
            ("Play simulation", "Simulate this scenario", self.action_simulate),
            ("Toggle XML view", "Show the selected agent's BehaviorTree.CPP XML", self.action_toggle_xml),
            ("Toggle grounding report", "Per group: what the sentence asked beside what the scenario does",
             self.action_toggle_grounding),
            ("Regenerate", "Generate again with the same prompt and the next seed", self.action_regenerate),
            ("Edit counts and re-plan", "Change each group's head count; the trees are kept, the model is not called",
             self.action_edit_counts),
            ("Export bundle", "Write the scenario bundle to the export folder", self.action_export),
        ]

    # selection ---------------------------------------------------------------------------------------
    @on(Tree.NodeHighlighted, "#bt-tree")
    def node_highlighted(self, event: Tree.NodeHighlighted[BTNode]) -> None:
        self._select(event.node.data)

    def _select(self, data: BTNode | None) -> None:
        self._selected_node = data
        self.query_one("#inspect-map", MapView).set_overlay(highlight_for(self.generated, self._selected_node, self._overlay))
        self.query_one("#node-detail", Static).update(self._detail(self._selected_node))
        if self.query_one("#xml", TextArea).display:
            self._show_xml()

    def _detail(self, data: BTNode | None) -> str:
        if data is None:
            return ""
        agents = {a.id: a for a in self.generated.scenario.agents}
        if data.kind == "node":
            ports = "\n".join(f"{k} = {v}" for k, v in data.ports.items())
            return f"{data.name} (agent {data.agent_id})\n{ports}"
        if data.kind == "robot" and self.generated.scenario.robot is not None:
            robot = self.generated.scenario.robot
            return f"robot start {robot.start} goal {robot.goal}\nradius {robot.radius} m, {robot.max_vel} m/s"
        agent = agents.get(data.agent_id)
        if agent is None:
            return ""
        start = f"({agent.start[0]:.1f}, {agent.start[1]:.1f})"
        prefix = f"group {data.name}: first agent\n" if data.kind == "group" else ""
        going = destination(agent, self.generated.world)
        return (f"{prefix}agent {agent.id} · {agent.label or 'no label'} · {agent.behavior}\n"
                f"from {start}" + (f"\n→ {going}" if going else "") + f"\n{len(agent.goals)} goals · {agent.max_vel} m/s")

    def _show_xml(self) -> None:
        agents = {a.id: a for a in self.generated.scenario.agents}
        data = self._selected_node
        agent = agents.get(data.agent_id) if data is not None else None
        if agent is None and agents:
            agent = next(iter(agents.values()))
        xml = self.query_one("#xml", TextArea)
        xml.text = agent_xml(self.generated, agent) if agent is not None else ""
        xml.border_title = f"XML · agent {agent.id}" if agent is not None else "XML"

    # actions -----------------------------------------------------------------------------------------
    def _show_side(self, which: str) -> None:
        """Show one of the side column's views (tree, xml, grounding) and focus it."""
        views = {"tree": self.query_one("#bt-tree", BTTree), "xml": self.query_one("#xml", TextArea),
                 "grounding": self.query_one("#grounding", GroundingPanel)}
        for name, widget in views.items():
            widget.display = name == which
        self.query_one("#inspect-side").set_class(which == "grounding", "-grounding")
        if which == "xml":
            self._show_xml()
        views[which].focus()

    def action_toggle_xml(self) -> None:
        self._show_side("tree" if self.query_one("#xml", TextArea).display else "xml")

    def action_toggle_grounding(self) -> None:
        self._show_side("tree" if self.query_one("#grounding", GroundingPanel).display else "grounding")

    def action_focus_map(self) -> None:
        self.query_one("#inspect-map", MapView).focus()

    def action_focus_tree(self) -> None:
        xml = self.query_one("#xml", TextArea)
        grounding = self.query_one("#grounding", GroundingPanel)
        (xml if xml.display else grounding if grounding.display else self.query_one("#bt-tree", BTTree)).focus()

    def action_simulate(self) -> None:
        from grove_tui.tui.screens.simulation import SimulationScreen

        self.app.push_screen(SimulationScreen(self.generated))

    def action_regenerate(self) -> None:
        from grove_tui.tui.screens.choice import Choice, ChoiceScreen

        seed = self.generated.seed + 1
        if not self.count_edits:
            self._regenerate(seed, keep_counts=False)
            return
        edits = ", ".join(f"{label} {count}" for label, count in self.count_edits.items())
        question = ChoiceScreen(
            f"Regenerate with seed {seed}",
            f"You changed the head counts ({edits}). Keep them in the new scenario? Groups are matched by label.",
            [Choice("y", "Keep my counts", "keep"), Choice("n", "Model's counts", "drop")])

        def answered(answer: str | None) -> None:
            if answer:
                self._regenerate(seed, keep_counts=answer == "keep")

        self.app.push_screen(question, answered)

    def _regenerate(self, seed: int, keep_counts: bool) -> None:
        from grove_tui.tui.screens.generation import GenerationRequest, GenerationScreen

        g = self.generated
        counts = tuple(self.count_edits.items()) if keep_counts else ()
        # Over this screen, not instead of it: Escape (or a failure) during the generation comes back to
        # the scenario you had; a new one replaces it here (show_scenario).
        self.app.push_screen(GenerationScreen(GenerationRequest(g.prompt, g.world_name, g.preset, seed, counts),
                                              back_to=self))

    def show_scenario(self, generated: GeneratedScenario, count_edits: dict[str, int]) -> None:
        """A regenerated scenario in place of the one shown (it is new, so Escape asks before leaving it)."""
        self.generated = generated
        self.grove.generated = generated
        self.count_edits = dict(count_edits)
        self.unsaved = True
        self._show_generated()

    def action_edit_counts(self) -> None:
        from grove_tui.tui.screens.counts import CountsScreen

        self.app.push_screen(CountsScreen(self.generated), self._counts_edited)

    def _counts_edited(self, generated: GeneratedScenario | None) -> None:
        if generated is None:
            return
        before = list(self.generated.result.report.get("groups", ()))
        after = list(generated.result.report.get("groups", ()))
        for old, new in zip(before, after):
            if int(old.get("count", 0)) != int(new.get("count", 0)):
                self.count_edits[str(new.get("label", ""))] = int(new.get("count", 0))
        self._replace(generated)
        history = generated.result.report.get("history") or []
        note = (history[-1]["sentence"] if history and generated.result.inputs is None
                else generated.result.report.get("notes", [""])[0])
        self.notify(f"{note}\n{len(generated.scenario.agents)} agents · bundle {generated.bundle_dir.name}",
                    title="Re-planned", timeout=6)

    # follow-ups, undo and redo ----------------------------------------------------------------------------
    def _replace(self, generated: GeneratedScenario, *, undoable: bool = True) -> None:
        """Show an edited scenario; the one shown before goes on the undo stack."""
        if undoable:
            self.undo_stack.append(self.generated)
            self.redo_stack.clear()
        self.unsaved = True
        self.generated = generated
        self.grove.generated = generated
        self._show_generated()

    def action_followup(self) -> None:
        self.query_one(FollowupBox).focus_input()

    @on(FollowupInput.Left)
    def followup_left(self) -> None:
        self.query_one("#bt-tree", BTTree).focus()

    @on(FollowupBox.Submitted)
    def followup_submitted(self, message: FollowupBox.Submitted) -> None:
        from grove_tui.tui.screens.refine import RefineScreen

        self.app.push_screen(RefineScreen(self.generated, message.sentence), self._refined)

    def _refined(self, generated: GeneratedScenario | None) -> None:
        if generated is None:
            return
        box = self.query_one(FollowupBox)
        box.clear()
        self._replace(generated)
        self.call_after_refresh(box.focus_input)  # ready for the next follow-up; ctrl+z still reaches the screen
        step = (generated.result.report.get("history") or [{}])[-1]
        diff = step.get("diff") or {}
        lines = [line for line in _diff_lines(diff) if not line.startswith("=")]
        self.notify("\n".join(lines[:4]) or step.get("sentence", ""), title=f"Follow-up {step.get('number', '')} applied"
                    " · ctrl+z undoes", timeout=6)

    def action_undo(self) -> None:
        if not self.undo_stack:
            self.notify("Nothing to undo.", title="Undo", timeout=3)
            return
        self.redo_stack.append(self.generated)
        undone = _last_sentence(self.generated)
        self._replace(self.undo_stack.pop(), undoable=False)
        self.notify(f"Undid: {undone}" if undone else "Undid the last edit.", title="Undo · ctrl+y redoes", timeout=8)

    def action_redo(self) -> None:
        if not self.redo_stack:
            self.notify("Nothing to redo.", title="Redo", timeout=3)
            return
        self.undo_stack.append(self.generated)
        self._replace(self.redo_stack.pop(), undoable=False)
        redone = _last_sentence(self.generated)
        self.notify(f"Redid: {redone}" if redone else "Redid the edit.", title="Redo", timeout=8)

    def action_back(self) -> None:
        from grove_tui.tui.screens.choice import Choice, ChoiceScreen

        if not self.unsaved:
            self.app.pop_screen()
            return
        question = ChoiceScreen(
            "Leave this scenario?",
            f"It has not been exported. It stays saved in the recent runs (ctrl+o on setup) as "
            f"{self.generated.bundle_dir.name}.",
            [Choice("y", "Leave", "leave"), Choice("e", "Export first", "export"), Choice("n", "Stay", "stay")])
        self.app.push_screen(question, self._back_answered)

    def _back_answered(self, answer: str | None) -> None:
        if answer == "leave":
            self.app.pop_screen()
        elif answer == "export":
            self.action_export()

    def action_export(self) -> None:
        from grove_tui.tui.screens.export import ExportProgressScreen

        self._export_progress = ExportProgressScreen("the scenario")
        self.app.push_screen(self._export_progress)
        self.run_export()

    @work(thread=True, exclusive=True, group="export", exit_on_error=False, description="exporting")
    def run_export(self) -> None:
        root = self.grove.export_root

        def progress(kind: str, index: int, total: int) -> None:
            self.post_message(msg.ExportProgress(kind, index, total))

        try:
            files = self.grove.session.export_all(self.generated, None, root, on_progress=progress)
        except Exception as exc:
            self.post_message(msg.ExportFailed(describe_error(exc).text))
            return
        self.post_message(msg.ExportFinished(files, files[0].path.parent if files else root))

    def on_export_progress(self, message: msg.ExportProgress) -> None:
        dialog = getattr(self, "_export_progress", None)
        if dialog is not None and dialog.is_mounted:
            dialog.advance(message.kind, message.index, message.total)

    def _close_export_progress(self) -> None:
        dialog = getattr(self, "_export_progress", None)
        self._export_progress = None
        if dialog is not None and self.app.screen is dialog:
            self.app.pop_screen()

    def on_export_finished(self, message: msg.ExportFinished) -> None:
        from grove_tui.tui.screens.export import ExportResultScreen

        self.unsaved = False
        self._close_export_progress()
        self.app.push_screen(ExportResultScreen(message.files, message.out_dir))

    def on_export_failed(self, message: msg.ExportFailed) -> None:
        self._close_export_progress()
        self.notify(message.error, title="Export failed", severity="error", timeout=15)


def _last_sentence(generated: GeneratedScenario) -> str:
    history = generated.result.report.get("history") or []
    return str(history[-1].get("sentence", "")) if history else ""


def _diff_lines(diff: Parsed) -> list[str]:
    from grove_tui.scenario.history import RefineDiff

    return RefineDiff.from_dict(diff).lines() if diff else []
