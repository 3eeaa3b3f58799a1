"""Simulation: the crowd and the robot on the map, live, with counters and the selected agent's tree."""

from __future__ import annotations

import sys
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

import numpy as np
from textual import on, work
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical
from textual.screen import Screen
from textual.widgets import Static, Tree
from textual.worker import get_current_worker

from grove_tui.errors import GroveError, describe_error
from grove_tui.tui import messages as msg
from grove_tui.services.session import GeneratedScenario
from grove_tui.tui.screens.inspect import base_overlay, busiest_goal
from grove_tui.tui.screens.counters import CountersScreen
from grove_tui.tui.screens.sim_controller import MAX_SPEED, SPEEDS, Counters, RunEnd, Snapshot, SimulationController
from grove_tui.tui.widgets.bt_tree import BTNode, BTTree
from grove_tui.tui.widgets import map_styles as ms
from grove_tui.tui.widgets.map_legend import MapLegend
from grove_tui.tui.widgets.map_raster import rasterise_agents
from grove_tui.tui.widgets.map_view import MapView
from grove_tui.tui.widgets.footer import Footer
from grove_tui.tui.widgets.grounding import GroundingPanel

if TYPE_CHECKING:
    from grove_tui.scenario.events import SimEvent
    from grove_tui.scenario.report import GroundingReport
    from grove_tui.services.domain import Frame, OutcomeChecker, Simulation
    from grove_tui.services.exporting import ExportedFile
    from grove_tui.tui.app import GroveApp
    from grove_tui.tui.commands import CommandEntry
    from grove_tui.tui.screens.export import ExportProgressScreen
    from grove_tui.tui.screens.sim_controller import Command

UI_SWITCH_INTERVAL = 0.001
BEHAVIORS = ("Regular", "Impassive", "Surprised", "Scared", "Curious", "Threatening")
# metrics.json's keys, in the order the panel lists them; a key the run does not have is left out
# (no robot: no robot metrics; no queue: no queue metrics).
LIVE_METRICS = (
    "goal_reach_rate",
    "agent_overlaps",
    "wall_penetrations",
    "queue_members",
    "queue_served",
    "mean_time_in_queue",
    "evacuated",
    "minimum_distance_to_people",
    "robot_on_person_collision",
    "person_on_robot_collision",
)
TREE_MIN_ROWS = 8  # the live tree's panel: six rows of nodes and its border, whatever else the column shows
COUNTERS_KEY = "m"
GROUNDING_INTERVAL = 2.0  # seconds between checks of the grounding report on the run so far
GROUNDING_ROWS_TIMEOUT = 10.0  # seconds to wait for the simulation thread to hand over the new rows


def speed_label(speed: float) -> str:
    return "max" if speed == MAX_SPEED else f"{speed:g}x"


def metric_text(value: float) -> str:
    """A metric as the panel shows it: counts as integers, the rest with two decimals, NaN as a dash."""
    if not np.isfinite(value):
        return "—"
    return f"{int(value)}" if float(value).is_integer() else f"{value:.2f}"


def counter_lines(values: dict[str, float], width: int) -> list[str]:
    """metrics.json's own names and numbers, values right-aligned in `width` columns; a name too long
    to share its line with the value (the narrow layout) gets the value on the next line."""
    width = max(width, 12)
    lines = []
    for key in LIVE_METRICS:
        if key not in values:
            continue
        value = metric_text(values[key])
        if len(key) + 1 + len(value) <= width:
            lines.append(key + value.rjust(width - len(key)))
        else:
            lines.extend([cut(key, width), value.rjust(width)])
    return lines


def counters_line(values: dict[str, float], width: int) -> str:
    """The counters folded into one line ("goal_reach_rate 0.17 · agent_overlaps 0 · …"), cut with "…"."""
    parts = [f"{key} {metric_text(values[key])}" for key in LIVE_METRICS if key in values]
    return cut(" · ".join(parts), width)


def cut(text: str, width: int) -> str:
    """`text` in `width` columns: whole, or cut with "…" as its last character."""
    if len(text) <= width:
        return text
    return text[: max(0, width - 1)] + "…"


class SimMapView(MapView):
    """The map with agents; arrow keys drive the robot, h j k l pan."""

    HELP = MapView.HELP + """
In the simulation the **arrow keys drive the robot** (hold to keep moving) and **r** puts it back
on its planned path. Agents are braille dots coloured by group (or behavior, **c**), the selected
agent is highlighted, the robot is the red arrow.
"""

    BINDINGS = [
        Binding("up", "drive(0, 1)", "Robot ↑", show=False, id="sim.robot_up"),
        Binding("down", "drive(0, -1)", "Robot ↓", show=False, id="sim.robot_down"),
        Binding("left", "drive(-1, 0)", "Robot ←", show=False, id="sim.robot_left"),
        Binding("right", "drive(1, 0)", "Robot →", show=False, id="sim.robot_right"),
    ]

    def action_drive(self, dx: int, dy: int) -> None:
        screen = self.screen
        if isinstance(screen, SimulationScreen):
            screen.drive(dx, dy)


class SimulationScreen(Screen[None]):
    HELP = """\
## Simulation

The Social Force crowd runs off the UI thread; the map shows every agent and the robot.
**space** play/pause, **n** one step, **[ ]** slower/faster (0.25x to 8x), **f** as fast as
possible, **a**/**A** select the next/previous agent (its tree shows the live status of every
node), arrows drive the robot, **r** back to its path, **c** colour by group or behavior,
**e** exports bundle, trajectories and metrics, **g** shows the grounding report checked on the
run so far (every few seconds; it opens by itself when the run ends or every claim is decided).

The **Counters** are metrics.json's numbers for the run so far (what `grove metrics` gives for the
exported run), under metrics.json's names; their title says the simulated time they are for (a
quarter of a second behind the clock at most while playing, exact when paused). When the column
is short they fold into one line and **m** lists them all. The run pauses by itself once everyone
is out of the building or done ("all 40 out at t = 83 s"); **space** plays on.
"""

    BINDINGS = [
        Binding("space", "toggle_play", "Play", id="sim.play", tooltip="Start or pause the simulation"),
        Binding("n", "step", "Step", show=False, id="sim.step", tooltip="Advance one simulation step"),
        Binding("left_square_bracket", "speed(-1)", "Slower", id="sim.slower", tooltip="Halve the speed"),
        Binding("right_square_bracket", "speed(1)", "Faster", id="sim.faster", tooltip="Double the speed"),
        Binding("f", "max_speed", "Max speed", show=False, id="sim.max_speed", tooltip="Run as fast as possible"),
        Binding("a", "select(1)", "Agent", id="sim.next_agent", tooltip="Select the next agent"),
        Binding("A", "select(-1)", "Prev agent", show=False, id="sim.prev_agent", tooltip="Select the previous agent"),
        Binding("r", "follow_path", "Robot", id="sim.robot_path", tooltip="Robot follows its planned path"),
        Binding("c", "colour_mode", "Colours", show=False, id="sim.colours", tooltip="Colour by group or behavior"),
        Binding("e", "export", "Export", id="sim.export", tooltip="Export bundle, trajectories and metrics"),
        Binding(COUNTERS_KEY, "counters", "Counters", show=False, id="sim.counters",
                tooltip="Every counter of the run so far, with the time it is for"),
        Binding("g", "toggle_grounding", "Grounding", show=False, id="sim.grounding",
                tooltip="The sentence's claims checked on the run so far"),
        Binding("escape", "back", "Back", id="sim.back", tooltip="Back to inspect"),
    ]

    def __init__(self, generated: GeneratedScenario) -> None:
        super().__init__()
        self.generated = generated
        self.controller: SimulationController | None = None
        self._shown_serial = -1
        self._selected_agent = -1
        self._agent_ids = [a.id for a in generated.scenario.agents]
        self._tree_agent = -1
        self.frames_drawn = 0
        self._colour_mode = "group"
        self._colour_table = self._build_colours()
        self._last_snapshot: Snapshot | None = None
        self._status_text = ""
        self._colour_ids: bytes = b""
        self._colour_array = np.zeros(0, dtype=np.int64)
        self._switch_interval = sys.getswitchinterval()
        self.exporting = False
        self._resume_after_export = False
        self._export_progress: ExportProgressScreen | None = None
        self.metrics: dict[str, float] = {}  # the counters shown, metrics.json's flat numbers
        self.metrics_step = -1  # the simulation step the shown counters were measured at
        self.metrics_t: float | None = None  # the simulated time they are for
        self._counters: Counters | None = None
        self._counters_folded = False
        self.run_end: RunEnd | None = None  # set once the run is over (RunEnded posted)
        # The grounding report checked on the run as it plays: one checker fed the new rows each time.
        self._checker: OutcomeChecker | None = None
        self._checker_rows = 0  # recorder rows the checker has seen
        self._grounding_busy = False
        self._grounding_shown_once = False
        self._grounding_step = -1
        self.grounding: GroundingReport | None = None  # the latest checked report

    @property
    def grove(self) -> GroveApp:
        return self.app  # type: ignore[return-value]

    def compose(self) -> ComposeResult:
        scenario = self.generated.scenario
        with Horizontal(id="sim-body"):
            with Vertical(id="sim-map-column"):
                world_map = SimMapView(id="sim-map")
                world_map.border_title = f"{scenario.world} · {len(scenario.agents)} agents"
                world_map.zoom_target = self._zoom_target
                legend = MapLegend("", id="sim-legend")
                world_map.legend = legend
                yield world_map
                yield legend
            with Vertical(id="sim-side"):
                status = Static("loading simulation…", id="sim-status")
                status.border_title = "Simulation"
                yield status
                counters = Static("counted once the run plays", id="counters", markup=False)
                counters.border_title = "Counters"
                counters.border_subtitle = "metrics.json"
                yield counters
                tree = BTTree("agent", id="sim-tree")
                tree.border_title = "Agent tree (a: select)"
                yield tree
                grounding = GroundingPanel(self.generated.result.report, id="sim-grounding")
                grounding.display = False
                yield grounding
        yield Footer(compact=True, show_command_palette=False)

    def on_mount(self) -> None:
        settings = self.grove.settings.simulation
        self._colour_mode = settings.colour_by
        self._colour_table = self._build_colours()
        world_map = self.query_one("#sim-map", SimMapView)
        world_map.set_world(self.generated.world)
        # Spawn and waypoint markers would read as people; the sim shows goals and the robot's path only.
        overlay = base_overlay(self.generated)
        world_map.set_overlay(replace(overlay, spawns=overlay.spawns[:0], waypoints=overlay.waypoints[:0]))
        world_map.focus()
        self._show_legend()
        # The sim thread runs Python (behavior trees) between numba kernels; a shorter GIL switch
        # interval hands the UI thread the GIL sooner, so frames keep their pace under load.
        self._switch_interval = sys.getswitchinterval()
        sys.setswitchinterval(UI_SWITCH_INTERVAL)
        self.start_simulation()
        self.set_interval(1.0 / settings.fps, self.draw_latest, name="sim-frames")
        self.set_interval(GROUNDING_INTERVAL, self.refresh_grounding, name="sim-grounding")

    def command_entries(self) -> list[CommandEntry]:
        return [
            ("Play / pause", "Start or pause the simulation", self.action_toggle_play),
            ("Step", "Advance one simulation step", self.action_step),
            ("Run as fast as possible", "Simulate at maximum speed", self.action_max_speed),
            ("Select next agent", "Show the next agent's live tree", lambda: self.action_select(1)),
            ("Robot follows its path", "Stop driving the robot by hand", self.action_follow_path),
            ("Export", "Bundle, trajectories and metrics", self.action_export),
            ("Counters", "Every counter of the run so far", self.action_counters),
            ("Grounding report", "The sentence's claims checked on the run so far", self.action_toggle_grounding),
        ]

    # the simulation worker --------------------------------------------------------------------------
    @work(thread=True, exclusive=True, group="simulation", exit_on_error=False, description="simulating")
    def start_simulation(self) -> None:
        worker = get_current_worker()
        try:
            simulation = self.grove.session.simulation(self.generated)
            metrics = self.grove.session.live_metrics(self.generated)
        except Exception as exc:
            self.post_message(msg.SimulationFailed(describe_error(exc).text))
            return
        settings = self.grove.settings.simulation
        try:
            run_until = self.grove.session.scenario_run_seconds(self.generated.bundle_dir)
        except (GroveError, OSError, KeyError, TypeError, ValueError):
            run_until = 0.0  # a report that cannot be read: the bundle still plays, ending when its people are done
        controller = SimulationController(simulation, fps=settings.fps, speed=settings.speed, metrics=metrics,
                                          run_until=run_until)
        self.controller = controller
        self.post_message(msg.SimulationReady(simulation))
        controller.run(lambda: worker.is_cancelled)

    def on_simulation_failed(self, message: msg.SimulationFailed) -> None:
        self.query_one("#sim-status", Static).update(f"✗ cannot simulate\n{message.error}")
        self.notify(message.error, title="Simulation", severity="error", timeout=15)

    def on_simulation_ready(self, message: msg.SimulationReady) -> None:
        if self._agent_ids and self._selected_agent < 0:
            self.action_select(1)

    def on_unmount(self) -> None:
        self.workers.cancel_group(self, "simulation")
        sys.setswitchinterval(self._switch_interval)

    # drawing (UI thread, set_interval) --------------------------------------------------------------
    def _colour_names(self) -> list[str]:
        """What each colour index means in the current mode (the legend lists them in this order)."""
        agents = self.generated.scenario.agents
        if self._colour_mode == "behavior":
            return [*BEHAVIORS, "other"]
        return [label or f"group {group}" for group, label in sorted({(a.group, a.label) for a in agents})]

    def _build_colours(self) -> dict[int, int]:
        agents = self.generated.scenario.agents
        if self._colour_mode == "behavior":
            return {a.id: BEHAVIORS.index(a.behavior) if a.behavior in BEHAVIORS else len(BEHAVIORS) for a in agents}
        groups = sorted({(a.group, a.label) for a in agents})
        index = {key: i for i, key in enumerate(groups)}
        return {a.id: index[(a.group, a.label)] for a in agents}

    def _show_legend(self) -> None:
        names = self._colour_names()
        if self._colour_mode == "behavior":
            # Only the behaviors this scenario has: eight names do not fit one line at 80 columns.
            present = {self._colour_table[a.id] for a in self.generated.scenario.agents}
            names = [name if i in present else "" for i, name in enumerate(names)]
        symbols = [("⣿", ms.SELECTED, "selected"), ("◎", ms.GOAL, "goal")]
        if self.generated.scenario.robot is not None:
            symbols.append(("↑", ms.ROBOT, "robot"))
        self.query_one("#sim-legend", MapLegend).show_colours(
            self.query_one("#sim-map", SimMapView), self._colour_mode, names, symbols)

    def _zoom_target(self) -> tuple[float, float] | None:
        """Zoom centres on the selected agent where it is now, else on where most people are going."""
        snapshot = self._last_snapshot
        if snapshot is not None and self._selected_agent >= 0:
            hits = np.flatnonzero(np.asarray(snapshot.frame.ids) == self._selected_agent)
            if len(hits):
                x, y = np.asarray(snapshot.frame.pos)[int(hits[0])]
                return float(x), float(y)
        return busiest_goal(self.generated.scenario)

    def _colours_for(self, ids: np.ndarray) -> np.ndarray:
        """Colour index per agent in `ids` order; rebuilt only when the ids or the colour mode change."""
        key = ids.tobytes()
        if key != self._colour_ids or len(self._colour_array) != len(ids):
            table = self._colour_table
            self._colour_array = np.array([table.get(int(i), 0) for i in ids], dtype=np.int64)
            self._colour_ids = key
        return self._colour_array

    def draw_latest(self) -> None:
        controller = self.controller
        snapshot = None if controller is None else controller.latest
        if snapshot is None or snapshot.serial == self._shown_serial:
            return
        self._shown_serial = snapshot.serial
        self._last_snapshot = snapshot
        frame = snapshot.frame
        world_map = self.query_one("#sim-map", SimMapView)
        raster = world_map.raster
        if raster is None:
            return
        ids = np.asarray(frame.ids, dtype=np.int64)
        colours = self._colours_for(ids)
        selected_index = -1
        if self._selected_agent >= 0:
            hits = np.flatnonzero(ids == self._selected_agent)
            selected_index = int(hits[0]) if len(hits) else -1
        robot = robot_pose(frame)
        world_map.set_agents(rasterise_agents(raster, np.asarray(frame.pos), colours, selected_index, robot))
        self.frames_drawn += 1
        self._show_status(snapshot)
        if snapshot.counters is not self._counters:
            self._show_counters(snapshot.counters)
        if snapshot.ended is not None and self.run_end is None:
            self.run_end = snapshot.ended
            self.post_message(msg.RunEnded(snapshot.ended.t, snapshot.ended.text, snapshot.ended.agents,
                                           snapshot.ended.out))
        if snapshot.selected == self._selected_agent and self._selected_agent >= 0 and snapshot.tree_status:
            tree = self.query_one("#sim-tree", BTTree)
            if self._tree_agent != self._selected_agent:
                tree.clear_all()
                tree.add_runtime_tree(tree.root, self._selected_agent, list(snapshot.tree_status))
                self._tree_agent = self._selected_agent
            tree.set_status(self._selected_agent, list(snapshot.tree_status))

    def _show_status(self, snapshot: Snapshot) -> None:
        frame = snapshot.frame
        state = "⏸ paused for export" if self.exporting else "▶ playing" if snapshot.playing else "⏸ paused"
        speed = speed_label(snapshot.speed)
        if snapshot.playing and snapshot.speed != MAX_SPEED and 0 < snapshot.steps_per_second < 0.9 * snapshot.speed:
            speed += f" ({snapshot.steps_per_second:.1f}x)"  # what the machine keeps up with
        robot = "manual" if snapshot.manual_robot else "path"
        total = len(self._agent_ids)
        lines = [
            f"{state}  {speed}",
            f"t = {float(frame.t):7.2f} s",
            f"agents {len(frame.ids)}/{total} · robot {robot}",
        ]
        in_queue = getattr(frame.counters, "in_queue", 0)
        if in_queue:
            lines.append(f"in queue now {in_queue}")
        if snapshot.ended is not None:
            lines.append(f"■ {snapshot.ended.text}")
        text = "\n".join(lines)
        if text == self._status_text:
            return
        # Lines of new lengths may change the panel's height (count, wrapping); otherwise the text
        # changes in place, and a layout pass of the whole screen every frame (the clock ticks in
        # each one) is wasted work.
        same_shape = [len(line) for line in self._status_text.split("\n")] == [len(line) for line in lines]
        self._status_text = text
        self.query_one("#sim-status", Static).update(text, layout=not same_shape)
        if not same_shape:
            self.call_after_refresh(self._fit_counters)

    # counters: metrics.json's numbers, measured in the simulation thread (sim_controller) ----------------
    def _show_counters(self, counters: Counters | None) -> None:
        self._counters = counters
        panel = self.query_one("#counters", Static)
        if counters is None:
            return
        if counters.error:
            panel.update(cut(f"✗ {counters.error}", 200))
            return
        self.metrics, self.metrics_step, self.metrics_t = counters.values, counters.step, counters.t
        panel.border_title = f"Counters · t = {counters.t:.2f} s"
        width = panel.content_size.width or 26
        if self._counters_folded:
            panel.update(counters_line(counters.values, width), layout=False)
        else:
            panel.update("\n".join(counter_lines(counters.values, width)))
            self.call_after_refresh(self._fit_counters)
        dialog = self.app.screen
        if isinstance(dialog, CountersScreen):
            dialog.show(counters)

    def _fit_counters(self) -> None:
        """All the counters when the column has room for them and the live tree's rows; else one line."""
        counters = self._counters
        if counters is None or counters.error or not self.is_mounted:
            return
        panel = self.query_one("#counters", Static)
        side = self.query_one("#sim-side")
        status = self.query_one("#sim-status", Static)
        width = panel.content_size.width or 26
        lines = counter_lines(counters.values, width)
        room = side.size.height - status.outer_size.height - TREE_MIN_ROWS - 2  # the counters' border
        folded = len(lines) > room
        if folded != self._counters_folded or folded:
            self._counters_folded = folded
            panel.set_class(folded, "-folded")
            panel.border_subtitle = f"{COUNTERS_KEY}: all" if folded else "metrics.json"
            panel.update(counters_line(counters.values, width) if folded else "\n".join(lines))

    def on_resize(self) -> None:
        self.call_after_refresh(self._fit_counters)

    def action_counters(self) -> None:
        self.app.push_screen(CountersScreen(self._counters))

    def on_run_ended(self, message: msg.RunEnded) -> None:
        """Everyone is out or done: the run paused itself; say so, and show the grounding report checked
        on the whole run."""
        self.notify(f"{message.text}. Space plays on; e exports the run.", title="Run over", timeout=8)
        self._grounding_shown_once = False  # the run's last check opens the report
        self._grounding_step = -1
        self.refresh_grounding(final=True)

    # the grounding report checked on the run so far, off the UI thread -----------------------------
    def refresh_grounding(self, final: bool = False) -> None:
        controller = self.controller
        if controller is None or controller.latest is None or self._grounding_busy or self.exporting:
            return
        step = controller.latest.frame.step
        if step == self._grounding_step:
            return  # paused: nothing new to check
        self._grounding_step = step
        self._grounding_busy = True
        self.check_grounding(controller, final)

    @work(thread=True, exclusive=True, group="grounding", exit_on_error=False, description="checking the claims")
    def check_grounding(self, controller: SimulationController, final: bool = False) -> None:
        import threading

        taken = _TakenRows()
        done = threading.Event()

        def take(simulation: Simulation) -> None:
            # In the simulation thread, between steps: the new rows and the events belong to one instant.
            taken.rows = simulation.recorder.rows_from(self._checker_rows)
            taken.events = list(simulation.events)

        def reply(result: object) -> None:
            taken.error = result if isinstance(result, Exception) else None
            done.set()

        try:
            if self._checker is None:
                self._checker = self.grove.session.outcome_checker(self.generated)
            if self._checker is None:
                self.post_message(msg.GroundingChecked(None))
                return
            controller.send("call", take, reply)
            if not done.wait(GROUNDING_ROWS_TIMEOUT) or taken.error is not None:
                raise RuntimeError(f"cannot read the run: {taken.error or 'the simulation did not answer'}")
            self._checker_rows += len(taken.rows)
            report = self.grove.session.check_run_rows(self._checker, taken.rows, taken.events,
                                                       partial=not final)
        except Exception as exc:  # a check bug must show in the panel, not stop the simulation
            self.post_message(msg.GroundingChecked(None, f"{type(exc).__name__}: {exc}"))
            return
        self.post_message(msg.GroundingChecked(report, final=final))

    def on_grounding_checked(self, message: msg.GroundingChecked) -> None:
        self._grounding_busy = False
        panel = self.query_one("#sim-grounding", GroundingPanel)
        if message.report is None:
            if message.error:
                panel.border_title = f"Grounding ✗ {message.error}"
            return
        self.grounding = message.report
        panel.show(message.report)
        decided = all(c.status in ("holds", "fails") for g in message.report.groups for c in g.claims)
        if (message.final or (decided and message.report.groups)) and not self._grounding_shown_once:
            # the run is over, or every claim is decided: the checked report is the run's result
            self._grounding_shown_once = True
            if not panel.display:
                self.action_toggle_grounding()
            self.notify(message.report.summary(), title="Grounding checked", timeout=6)

    def action_toggle_grounding(self) -> None:
        panel = self.query_one("#sim-grounding", GroundingPanel)
        show = not panel.display
        panel.display = show
        self.query_one("#sim-tree", BTTree).display = not show
        self.query_one("#sim-side").set_class(show, "-grounding")
        if show:
            self._grounding_step = -1
            self.refresh_grounding()

    # actions ---------------------------------------------------------------------------------------
    def _send(self, command: Command) -> None:
        if self.controller is not None:
            self.controller.send_command(command)

    def action_toggle_play(self) -> None:
        self._send(("play",))

    def action_step(self) -> None:
        self._send(("step", 1))

    def action_speed(self, direction: int) -> None:
        current = self.controller.speed if self.controller is not None else 1.0
        if current == MAX_SPEED:
            speed = SPEEDS[-1] if direction < 0 else MAX_SPEED
        else:
            index = min(range(len(SPEEDS)), key=lambda i: abs(SPEEDS[i] - current))
            index = max(0, min(len(SPEEDS) - 1, index + direction))
            speed = SPEEDS[index]
        self._send(("speed", speed))
        self.notify(f"speed {speed_label(speed)}", timeout=1)

    def action_max_speed(self) -> None:
        self._send(("speed", MAX_SPEED))

    def action_select(self, step: int) -> None:
        if not self._agent_ids:
            return
        if self._selected_agent in self._agent_ids:
            index = (self._agent_ids.index(self._selected_agent) + step) % len(self._agent_ids)
        else:
            index = 0 if step > 0 else len(self._agent_ids) - 1
        self.select_agent(self._agent_ids[index])

    def select_agent(self, agent_id: int) -> None:
        self._selected_agent = agent_id
        self._send(("select", agent_id))
        agent = next(a for a in self.generated.scenario.agents if a.id == agent_id)
        tree = self.query_one("#sim-tree", BTTree)
        tree.clear_all()
        self._tree_agent = -1
        tree.border_title = f"Agent {agent_id} · {agent.label or agent.behavior}"
        self._shown_serial = -1

    @on(Tree.NodeHighlighted, "#sim-tree")
    def tree_node_highlighted(self, event: Tree.NodeHighlighted[BTNode]) -> None:
        event.stop()

    def drive(self, dx: int, dy: int) -> None:
        speed = self.grove.settings.simulation.robot_speed
        self._send(("drive", dx * speed, dy * speed))

    def action_follow_path(self) -> None:
        self._send(("follow_path",))

    def action_colour_mode(self) -> None:
        self._colour_mode = "behavior" if self._colour_mode == "group" else "group"
        self._colour_table = self._build_colours()
        self._colour_ids = b""
        self._shown_serial = -1
        self._show_legend()
        self.notify(f"colour by {self._colour_mode}", timeout=1)

    def action_back(self) -> None:
        self.app.pop_screen()

    def action_export(self) -> None:
        from grove_tui.tui.screens.export import ExportProgressScreen

        controller = self.controller
        if controller is None:
            self.notify("The simulation is not running yet.", title="Export", severity="warning")
            return
        if self.exporting:
            return
        session = self.grove.session
        generated = self.generated
        root = self.grove.export_root

        def progress(kind: str, index: int, total: int) -> None:
            self.post_message(msg.ExportProgress(kind, index, total))

        def export(simulation: Simulation) -> list[ExportedFile]:
            # In the simulation thread, which is paused: the run cannot change while it is written.
            return session.export_all(generated, simulation, root, on_progress=progress)

        def reply(result: list[ExportedFile] | Exception) -> None:
            if isinstance(result, Exception):
                self.post_message(msg.ExportFailed(describe_error(result).text))
            else:
                self.post_message(msg.ExportFinished(result, result[0].path.parent if result else root))

        # Pause first, visibly: the picture stops and the status says why, instead of "playing"
        # over a frozen map while the export holds the simulation thread.
        self._resume_after_export = controller.playing
        self.exporting = True
        self._send(("play", False))
        self._export_progress = ExportProgressScreen("the run")
        self.app.push_screen(self._export_progress)
        controller.send("call", export, reply)
        if self._last_snapshot is not None:
            self._show_status(self._last_snapshot)

    def on_export_progress(self, message: msg.ExportProgress) -> None:
        dialog = self._export_progress
        if dialog is not None and dialog.is_mounted:
            dialog.advance(message.kind, message.index, message.total)

    def _export_done(self) -> None:
        """Close the progress dialog; the run resumes when the user closes what comes next."""
        dialog, self._export_progress = self._export_progress, None
        if dialog is not None and self.app.screen is dialog:
            self.app.pop_screen()

    def _resume(self, _result: object = None) -> None:
        self.exporting = False
        if self._resume_after_export:
            self._send(("play", True))
        self._resume_after_export = False
        if self._last_snapshot is not None:
            self._show_status(self._last_snapshot)

    def on_export_finished(self, message: msg.ExportFinished) -> None:
        from grove_tui.tui.screens.export import ExportResultScreen
        from grove_tui.tui.screens.inspect import InspectScreen

        for screen in self.app.screen_stack:  # the inspect screen below need not ask before leaving now
            if isinstance(screen, InspectScreen) and screen.generated is self.generated:
                screen.unsaved = False
        self._export_done()
        self.app.push_screen(ExportResultScreen(message.files, message.out_dir), self._resume)

    def on_export_failed(self, message: msg.ExportFailed) -> None:
        self._export_done()
        self._resume()
        self.notify(message.error, title="Export failed", severity="error", timeout=15)


@dataclass
class _TakenRows:
    """What check_grounding takes from the simulation thread: the recorder's new rows and the events
    (or the exception that stopped it)."""

    rows: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))
    events: list[SimEvent] = field(default_factory=list)
    error: Exception | None = None


def robot_pose(frame: Frame) -> tuple[float, float, float] | None:
    robot = getattr(frame, "robot", None)
    if robot is None:
        return None
    values: Sequence[float] = robot if not hasattr(robot, "x") else (robot.x, robot.y, getattr(robot, "yaw", 0.0))
    return (float(values[0]), float(values[1]), float(values[2]) if len(values) > 2 else 0.0)
