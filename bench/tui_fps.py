"""Frames per second of the simulation screen with 500 agents (goal: >= 15 fps).

    PYTHONPATH=. python bench/tui_fps.py [--agents 500] [--seconds 10] [--fps 30] [--size 120x40]
    PYTHONPATH=. python bench/tui_fps.py --peer CHECKOUT [--rounds 2]   # another checkout, same run, ratios
    PYTHONPATH=. python bench/tui_fps.py --key-latency [--presses 20] [--size 80x24]

Builds a 500-agent scenario in the hospital (every agent walks a Theta*-planned route to a random
place), opens the app's SimulationScreen on it headless, presses play, and counts the frames the
screen drew during the measurement window. A frame counts when the view took a new simulation
snapshot, re-rasterised the agents and the compositor painted it; the terminal encoding of each
painted update is included (Textual skips it when headless, so the bench does it, as a real
terminal would). It also reports the simulation's steps per second and real-time factor, and what a
drawn frame costs on the UI thread: `mean_draw_ms` (rasterising the agents), `mean_render_ms` (the
compositor asking the widgets for their dirty lines: the map's render_line runs there), `mean_encode_ms`
and `map_rows_repainted_per_frame`. Measuring starts once the run has stepped (a fresh checkout
compiles the numba kernels on its first step). `--peer CHECKOUT` (e.g. `git archive <commit> | tar -x
-C DIR`) measures that checkout's grove_tui too, alternating with this one, each in its own interpreter,
and prints medians and ratios.

Figures (2 shared cores, 500 agents, 120x40, --fps 30):
- 2026-11-25, before: 6.0 fps at load average 10.3; a frame cost the UI thread 27 ms (9.8 drawing,
  16.9 encoding).
- 2026-11-25, after (rows repainted only where their agents changed, each row's strip reused, the base
  style cached, no screen-wide layout pass for the status panel), `--peer` = the map before, 2 rounds:
  17.3 fps against 16.9 at load average 5.1 (ratio 1.02: at that load both reach the ceiling, the
  simulation publishing 20 frames/s at 1x); render+encode 24.7 ms per screen update against 31.6
  (ratio 0.78); 20 of the map's ~29 rows repainted per frame.
- 2026-11-25 19:03, blank cells merged into the run before them, counters paced: 14.6 fps at load 6.5;
  --peer (the map before), 2 rounds at load 6-7: 15.0 against 15.9 (machine-bound at that load).

- 2026-11-28 (issue 31), counters on, 1x then 8x, load 9.2-10.1 (metrics then fed every 5 steps): 14.5 fps
  at 120x40 and 15.8 at 80x24;
  at 8x 8.2-8.9 fps at 3.0-3.4x real time (main before: 0.9 fps at 8x, the picture held while a
  400-step backlog ran); counters at most 0.27 s behind at 1x and 0.26 s at 8x. Details in
  docs/BENCHMARKS.md, issue 31. Final (fed every 40 steps), load 5.2-5.3: 16.9 fps at 120x40, 18.3 at 80x24;
  at 8x 11.9-13.4 fps at 5.9x real time; counters at most 0.64 s behind.

Key latency (--key-latency, 120x40; timed from the Key event to the first painted update of its
screen, and main measured with `--tree` in the same hour):
- load 0.7: median 17 / p90 29 ms while the model writes, idle p90 22 ms (main: 29 / 53 ms, idle p90 73 ms).
- load 2-3: median 19 / p90 31 ms while the model writes (main: 34 / 46 ms); full GC pauses 17-32 ms
  (main: 483 and 573 ms, the unfrozen ~800,000-object heap).
- load 11.6: median 296 / p90 522 ms (main: 415 / 1,215 ms, max 7.0 s in a 6.5 s full collection).
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import sys
import tempfile
import time
from pathlib import Path
from types import SimpleNamespace

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def _tree_from_argv() -> Path:
    """The checkout whose grove_tui is measured: --tree PATH (a peer), else this one. Read before any import."""
    if "--tree" in sys.argv:
        return Path(sys.argv[sys.argv.index("--tree") + 1]).resolve()
    return ROOT


sys.path.insert(0, str(_tree_from_argv()))


def build_scenario(n_agents: int, out_dir: Path, seed: int = 0):
    from grove_tui.services.session import GeneratedScenario
    from grove_tui.scenario.bundle import load_bundle  # noqa: F401  (the bundle layout this writes)
    from grove_tui.navigation.grid import build_grid
    from grove_tui.navigation.theta_star import PlanningError, ThetaStarPlanner
    from grove_tui.scenario.model import AgentSpec, RobotSpec, Scenario
    from grove_tui.bt.format.ports import parse_point_list
    from grove_tui.bt.format.xml import read_tree, write_tree
    from grove_tui.generation.waypoints import plan_waypoints
    from grove_tui.world import load_world

    world = load_world("hospital")
    grid = build_grid(world, resolution=0.1, inflation=0.35)
    planner = ThetaStarPlanner(grid)
    rng = np.random.default_rng(seed)
    free = grid.free_cells()
    places = [(e.name, e.interaction_point) for e in world.entities()] + [(z.name, z.centroid) for z in world.zones]
    targets = []
    for name, point in places:
        snapped = grid.nearest_free(float(point[0]), float(point[1]), max_dist=2.0)
        if snapped is not None:
            targets.append((name, snapped))
    (out_dir / "trees").mkdir(parents=True, exist_ok=True)
    agents = []
    trees = {}
    while len(agents) < n_agents:
        row, col = free[rng.integers(len(free))]
        start = grid.cell_to_world(int(row), int(col))
        name, goal = targets[rng.integers(len(targets))]
        agent_id = len(agents) + 1
        xml = (
            '<root BTCPP_format="4" main_tree_to_execute="agent_{id}"><BehaviorTree ID="agent_{id}"><Sequence>'
            '<GoTo target="{name}" x="{x:.2f}" y="{y:.2f}" waypoints="" tolerance="0.3" agent_id="{{id}}" '
            'time_step="{{dt}}" goal_id="{id}"/></Sequence></BehaviorTree></root>'
        ).format(id=agent_id, name=name, x=goal[0], y=goal[1])
        try:
            xml = write_tree(plan_waypoints(read_tree(xml), start, planner))
        except PlanningError:
            continue
        waypoints = []
        import re

        match = re.search(r'waypoints="([^"]*)"', xml)
        if match and match.group(1):
            waypoints = list(parse_point_list(match.group(1)))
        tree_path = f"trees/agent_{agent_id}.xml"
        (out_dir / tree_path).write_text(xml, encoding="utf-8")
        trees[tree_path] = xml
        agents.append(AgentSpec(id=agent_id, group=-1, start=(float(start[0]), float(start[1])),
                                goals=(*[tuple(map(float, p)) for p in waypoints], (float(goal[0]), float(goal[1]))),
                                zone=name, tree=tree_path, label=f"walkers {agent_id % 6}"))
    robot_start, robot_goal = targets[0][1], targets[-1][1]
    robot_path = planner.plan(robot_start, robot_goal)
    robot = RobotSpec(start=tuple(map(float, robot_start)), goal=tuple(map(float, robot_goal)),
                      path=tuple(tuple(map(float, p)) for p in robot_path))
    scenario = Scenario(world="hospital", preset="normal", prompt=f"{n_agents} people walk around", seed=seed,
                        models={}, agents=tuple(agents), robot=robot)
    scenario.save(out_dir / "scenario.yaml")
    grid.save(out_dir / "grid.npz")
    result = SimpleNamespace(scenario=scenario, trees=trees, fields={}, grid=grid, report={})
    return GeneratedScenario(scenario.prompt, "hospital", "normal", seed, world, result, out_dir)


async def measure(generated, seconds: float, fps: int, size: tuple[int, int]) -> dict:
    from grove_tui.tui.app import GroveApp
    from grove_tui.services.session import GroveSession
    from grove_tui.settings import GroveSettings, SimulationSettings, UISettings
    from grove_tui.tui.screens.simulation import SimulationScreen

    from textual._compositor import Compositor

    painted = {"updates": 0, "encode_seconds": 0.0, "render_seconds": 0.0}
    render_update = Compositor.render_update

    def timed_render_update(self, *args, **kwargs):  # noqa: ANN001, ANN202 - Textual's private method
        # The compositor asks every dirty widget for its lines here: the map's render_line runs in it.
        started = time.perf_counter()
        try:
            return render_update(self, *args, **kwargs)
        finally:
            painted["render_seconds"] += time.perf_counter() - started

    Compositor.render_update = timed_render_update  # type: ignore[method-assign]

    class BenchApp(GroveApp):
        def _display(self, screen, renderable) -> None:  # noqa: ANN001 - Textual's private hook
            # Headless Textual skips the terminal encoding; do it so the bench pays what a terminal costs.
            if renderable is not None:
                started = time.perf_counter()
                renderable.render_segments(self.console)
                painted["encode_seconds"] += time.perf_counter() - started
                painted["updates"] += 1
            super()._display(screen, renderable)

    settings = GroveSettings(ui=UISettings(preload_models=False), simulation=SimulationSettings(fps=fps, speed=1.0))
    app = BenchApp(GroveSession.for_app(), settings)
    async with app.run_test(size=size) as pilot:
        await app.push_screen(SimulationScreen(generated))
        screen = app.screen
        assert isinstance(screen, SimulationScreen)
        deadline = time.monotonic() + 300
        while screen.controller is None or screen.controller.latest is None:
            status = str(screen.query_one("#sim-status").render())
            if "cannot simulate" in status or time.monotonic() > deadline:
                raise SystemExit(f"the simulation did not start: {status}")
            await pilot.pause(0.1)
        draw = screen.draw_latest
        draw_cost = []
        # (wall time, simulated time drawn, simulated time of the counters shown) at every drawn frame:
        # the counters' delay is how long ago, in wall time, the run was at the time they are for.
        timeline: list[tuple[float, float, float | None]] = []

        def timed_draw() -> None:
            started = time.perf_counter()
            before = screen.frames_drawn
            draw()
            if screen.frames_drawn > before:
                draw_cost.append(time.perf_counter() - started)
                snapshot = screen.controller.latest if screen.controller is not None else None
                if snapshot is not None:
                    counters = getattr(snapshot, "counters", None)  # a peer checkout may have none
                    timeline.append((time.perf_counter(), float(snapshot.frame.t),
                                     None if counters is None else float(counters.t)))

        screen.draw_latest = timed_draw  # the interval timer looks the method up on each tick
        for timer in screen._timers:
            if getattr(timer, "name", "") == "sim-frames":
                timer._callback = timed_draw
        world_map = screen.query_one("#sim-map")
        set_agents = world_map.set_agents
        repainted = []

        def counted_set_agents(cells):  # noqa: ANN001, ANN202
            rows = set_agents(cells)
            if isinstance(rows, int):  # older map views return nothing
                repainted.append(rows)
            return rows

        world_map.set_agents = counted_set_agents
        await pilot.press("space")
        # Warm-up until the run has really stepped: a fresh checkout compiles the numba kernels on
        # the first step, which takes tens of seconds on a loaded machine.
        step_start = screen.controller.latest.frame.step
        while screen.controller.latest.frame.step < step_start + 20:
            if time.monotonic() > deadline:
                raise SystemExit("the simulation did not play: " + str(screen.query_one("#sim-status").render()))
            await pilot.pause(0.2)
        await pilot.pause(1.0)  # first BT ticks, caches

        async def window(speed_label: str) -> dict:
            frames0, updates0, encode0 = screen.frames_drawn, painted["updates"], painted["encode_seconds"]
            render0 = painted["render_seconds"]
            repainted.clear()
            timeline.clear()
            step0, t0 = screen.controller.latest.frame.step, screen.controller.latest.frame.t
            draw_cost.clear()
            started = time.perf_counter()
            await pilot.pause(seconds)
            elapsed = time.perf_counter() - started
            frames = screen.frames_drawn - frames0
            latest = screen.controller.latest.frame
            updates = painted["updates"] - updates0
            delays = counters_delays(timeline)
            return {
                "speed": speed_label,
                "fps": round(frames / elapsed, 2),
                "screen_updates_per_second": round(updates / elapsed, 2),
                "mean_draw_ms": round(1000 * float(np.mean(draw_cost)), 2) if draw_cost else None,
                "mean_render_ms": round(1000 * (painted["render_seconds"] - render0) / max(1, updates), 2),
                "mean_encode_ms": round(1000 * (painted["encode_seconds"] - encode0) / max(1, updates), 2),
                "map_rows_repainted_per_frame": round(float(np.mean(repainted)), 1) if repainted else None,
                "sim_steps_per_second": round((latest.step - step0) / elapsed, 1),
                "real_time_factor": round((latest.t - t0) / elapsed, 2),
                "counters_delay_max_s": round(max(delays), 2) if delays else None,
                "counters_delay_p95_s": round(float(np.percentile(delays, 95)), 2) if delays else None,
                "measured_seconds": round(elapsed, 2),
                "load_average": round(os.getloadavg()[0], 2),
            }

        at_1x = await window("1x")
        # 8x: ] three times (1x -> 2x -> 4x -> 8x), as a user speeds the run up.
        await pilot.press("right_square_bracket", "right_square_bracket", "right_square_bracket")
        await pilot.pause(1.0)
        at_8x = await window("8x")
        result = {"agents": len(generated.scenario.agents), "terminal": f"{size[0]}x{size[1]}", "target_fps": fps,
                  **{key: value for key, value in at_1x.items() if key != "speed"}}
        for key in ("fps", "real_time_factor", "counters_delay_max_s", "counters_delay_p95_s", "load_average"):
            result[f"{key}_8x"] = at_8x[key]
        return result


def counters_delays(timeline: list[tuple[float, float, float | None]]) -> list[float]:
    """For each drawn frame, the wall seconds since the run was at the simulated time its counters are for."""
    delays = []
    reached: list[tuple[float, float]] = []  # (simulated time, wall time first drawn at or past it)
    for wall, t, counters_t in timeline:
        if not reached or t > reached[-1][0]:
            reached.append((t, wall))
        if counters_t is None:
            continue
        # The first drawn frame at or after the counters' time: when the run got there (as drawn).
        index = int(np.searchsorted([r[0] for r in reached], counters_t - 1e-9))
        if index < len(reached):
            delays.append(max(0.0, wall - reached[index][1]))
    return delays


class GcPauses:
    """Full (oldest generation) collections while it is on: they stop every thread, the UI's too."""

    def __init__(self) -> None:
        import gc

        self._gc = gc
        self._started = 0.0
        self.pauses: list[float] = []

    def _callback(self, phase: str, info: dict) -> None:
        if info.get("generation") != 2:
            return
        if phase == "start":
            self._started = time.perf_counter()
        else:
            self.pauses.append(time.perf_counter() - self._started)

    def __enter__(self) -> "GcPauses":
        self._gc.callbacks.append(self._callback)
        return self

    def __exit__(self, *exc: object) -> None:
        self._gc.callbacks.remove(self._callback)


async def key_latency(prompt: str, presses: int, size: tuple[int, int], model_niceness: int | None = None) -> dict:
    """Milliseconds from a key event reaching the app to the first painted update showing its screen.

    F1 on the generation screen opens help (a new screen: compose, layout, paint) and Escape closes
    it. Each key goes in as a terminal's would (the driver posts the Key event to the app from
    outside its loop), and the time stops at the first screen update painted (and encoded for a
    terminal, as the fps bench does) while the screen it opens or closes is the app's screen: what
    a user sees. Pilot's press() is not used to time: it adds two waits for the process to go idle
    (20 ms each at least, up to 1 s while the pipeline thread works), which is test pacing, not
    response. Only presses made while a model stage (RoIs or tree synthesis) was running count.
    `model_niceness` is GroveSession.for_app's (None: the app's default; 0: the model processes keep the
    app's priority). Full garbage collections during the presses are reported too (they stop the UI).
    """
    from textual import events

    from grove_tui.services.session import GroveSession
    from grove_tui.settings import ExportSettings, GenerationSettings, GroveSettings, UISettings
    from grove_tui.tui.app import GroveApp
    from grove_tui.tui.screens.generation import MODEL_STAGES, GenerationScreen
    from grove_tui.tui.screens.help import HelpScreen
    from grove_tui.tui.screens.setup import SetupScreen

    painted: list[tuple[float, object]] = []

    class TimedApp(GroveApp):
        def _display(self, screen, renderable) -> None:  # noqa: ANN001 - Textual's private hook
            if renderable is not None:
                renderable.render_segments(self.console)  # the terminal encoding a real terminal pays
                painted.append((time.perf_counter(), self.screen))
            super()._display(screen, renderable)

    async def until(pilot, condition, timeout: float = 120.0) -> None:
        deadline = time.monotonic() + timeout
        while not condition():
            if time.monotonic() > deadline:
                raise SystemExit("timed out: " + str(pilot.app.screen))
            await asyncio.sleep(0.005)

    async def press(app, key: str, screen_type: type, give_up=lambda: False) -> float | None:
        """Seconds from the key event to the first paint of `screen_type`; None if give_up() came first."""
        seen = len(painted)
        started = time.perf_counter()
        app._driver.send_message(events.Key(key, "\x1b" if key == "escape" else None))
        deadline = started + 120
        while True:
            for when, screen in painted[seen:]:
                if isinstance(screen, screen_type):
                    return when - started
            seen = len(painted)
            if give_up():
                return None
            if time.perf_counter() > deadline:
                raise SystemExit(f"{key}: {screen_type.__name__} never painted")
            await asyncio.sleep(0.001)

    with tempfile.TemporaryDirectory(prefix="grove-keys-") as tmp:
        settings = GroveSettings(ui=UISettings(preload_models=True),
                                 generation=GenerationSettings(world="hospital", preset="queuing"),
                                 export=ExportSettings(directory=Path(tmp) / "exports"))
        extra = {} if model_niceness is None else {"model_niceness": model_niceness}
        app = TimedApp(GroveSession.for_app(runs_dir=Path(tmp) / "runs", **extra), settings)
        latencies: list[float] = []
        async with app.run_test(size=size) as pilot:
            await until(pilot, lambda: isinstance(app.screen, SetupScreen))
            setup = app.screen
            await until(pilot, lambda: "ready to generate" in str(setup.query_one("#models").render()), 600)
            await pilot.pause(0.5)
            # The same presses with nothing generating: what this machine's load alone costs.
            idle: list[float] = []
            with GcPauses() as idle_gc:
                for _ in range(max(4, presses // 4)):
                    for key, screen_type in (("f1", HelpScreen), ("escape", SetupScreen)):
                        idle.append(await press(app, key, screen_type))
                        await asyncio.sleep(0.05)
            await pilot.press(*prompt, "enter")
            await until(pilot, lambda: isinstance(app.screen, GenerationScreen))
            generation = app.screen
            attempts = 0
            with GcPauses() as busy_gc:
                while len(latencies) < presses and attempts < presses * 40:
                    attempts += 1
                    if not generation._generating:
                        break
                    if generation._stage not in MODEL_STAGES:
                        await asyncio.sleep(0.05)
                        continue
                    for key, screen_type in (("f1", HelpScreen), ("escape", GenerationScreen)):
                        # The generation may end while help is open: Escape then lands on the inspect
                        # screen, and that press was not made while the model wrote.
                        took = await press(app, key, screen_type, give_up=lambda: not generation._generating)
                        if took is None or not generation._generating:
                            break
                        latencies.append(took)
                        await asyncio.sleep(0.05)
                    if not generation._generating:
                        break
                    await asyncio.sleep(0.1)
            if isinstance(app.screen, GenerationScreen) and generation._generating:
                generation.action_cancel()
            frozen = getattr(app, "frozen_heap", None)  # a peer checkout may not freeze
        if not latencies:
            raise SystemExit("the model finished before any key could be timed; use a longer prompt")
        ms = np.array(latencies) * 1000
        idle_ms = np.array(idle) * 1000
        return {"key_presses": len(ms), "median_ms": round(float(np.median(ms)), 1),
                "p90_ms": round(float(np.percentile(ms, 90)), 1), "max_ms": round(float(ms.max()), 1),
                "idle_median_ms": round(float(np.median(idle_ms)), 1),
                "idle_p90_ms": round(float(np.percentile(idle_ms, 90)), 1),
                "full_gc_pauses_ms": [round(p * 1000) for p in idle_gc.pauses + busy_gc.pauses],
                "frozen_objects": None if frozen is None else frozen.frozen,
                "load_average": round(os.getloadavg()[0], 2), "terminal": f"{size[0]}x{size[1]}"}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--agents", type=int, default=500)
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--fps", type=int, default=30, help="the view's frame timer (config simulation.fps)")
    parser.add_argument("--size", default="120x40", help="terminal size, COLSxROWS")
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument("--key-latency", action="store_true",
                        help="instead: key response (F1/Escape) while the embedded model generates")
    parser.add_argument("--presses", type=int, default=20)
    parser.add_argument("--tree", type=Path, default=None,
                        help="measure the grove_tui of this checkout instead of the bench's own")
    parser.add_argument("--peer", type=Path, default=None,
                        help="also measure this checkout (e.g. an earlier commit's `git archive`) in the same "
                             "run, alternating with this one, and print ratios")
    parser.add_argument("--rounds", type=int, default=2, help="with --peer: measurements of each, alternating")
    args = parser.parse_args()
    cols, rows = (int(v) for v in args.size.lower().split("x"))
    if args.key_latency:
        prompt = ("ten patients queue at the pharmacy counter while two nurses talk in the waiting area and a "
                  "family walks to the exit")
        # The peer, measured in the same run: the model processes at the app's own priority (as before
        # issue 21), then the app's default (they give way to it).
        same = asyncio.run(key_latency(prompt, args.presses, (cols, rows), model_niceness=0))
        result = asyncio.run(key_latency(prompt, args.presses, (cols, rows)))
        result["same_priority_median_ms"] = same["median_ms"]
        result["same_priority_p90_ms"] = same["p90_ms"]
        result["same_priority_load_average"] = same["load_average"]
        result["p90_ratio_vs_same_priority"] = round(result["p90_ms"] / max(same["p90_ms"], 1e-9), 2)
        if args.json:
            print(json.dumps(result))
        else:
            print("\n".join(f"{k:<28}{v}" for k, v in result.items()))
            print(f"{'meets' if result['p90_ms'] < 100 else 'MISSES'} the 100 ms goal (p90)")
        print(f"key_p90_ms={result['p90_ms']} key_median_ms={result['median_ms']} "
              f"same_priority_p90_ms={same['p90_ms']} ratio={result['p90_ratio_vs_same_priority']} "
              f"idle_p90_ms={result['idle_p90_ms']} load={result['load_average']}")
        return 0
    if args.peer is not None:
        return compare_with_peer(args)
    with tempfile.TemporaryDirectory(prefix="grove-fps-") as tmp:
        started = time.perf_counter()
        generated = build_scenario(args.agents, Path(tmp))
        setup = time.perf_counter() - started
        result = asyncio.run(measure(generated, args.seconds, args.fps, (cols, rows)))
    result["scenario_setup_seconds"] = round(setup, 1)
    if args.json:
        print(json.dumps(result))
    else:
        for key, value in result.items():
            print(f"{key:<30}{value}")
        verdict = "meets" if result["fps"] >= 15 else "MISSES"
        print(f"{verdict} the 15 fps goal with {result['agents']} agents (ratio fps/goal {result['fps'] / 15:.2f}; "
              f"--peer CHECKOUT compares with another checkout in the same run)")
        delays = (result["counters_delay_max_s"], result["counters_delay_max_s_8x"])
        met = all(d is not None and d <= 1.0 for d in delays)
        print(f"{'meets' if met else 'MISSES'} the counters' 1 s goal (max delay {delays[0]} s at 1x, {delays[1]} s at 8x)")
    print(f"fps={result['fps']} agents={result['agents']} terminal={result['terminal']} "
          f"real_time_factor={result['real_time_factor']} counters_delay_1x={result['counters_delay_max_s']} "
          f"counters_delay_8x={result['counters_delay_max_s_8x']} fps_8x={result['fps_8x']} "
          f"real_time_factor_8x={result['real_time_factor_8x']} load={round(os.getloadavg()[0], 2)}")
    return 0


def _measure_in_subprocess(tree: Path, args: argparse.Namespace) -> dict:
    """One measurement of `tree`'s grove_tui in a fresh interpreter (imports cannot be swapped in one)."""
    import subprocess

    command = [sys.executable, str(Path(__file__).resolve()), "--json", "--tree", str(tree),
               "--agents", str(args.agents), "--seconds", str(args.seconds), "--fps", str(args.fps),
               "--size", args.size]
    done = subprocess.run(command, capture_output=True, text=True, cwd=str(tree))
    lines = [line for line in done.stdout.splitlines() if line.startswith("{")]
    if done.returncode != 0 or not lines:
        raise SystemExit(f"measuring {tree} failed (exit {done.returncode}): {done.stderr.strip()[-400:]}")
    return json.loads(lines[-1])


def compare_with_peer(args: argparse.Namespace) -> int:
    """This checkout against a peer checkout, alternating, so both see the same machine load."""
    this_tree = (args.tree or ROOT).resolve()
    peer_tree = args.peer.resolve()
    runs: dict[str, list[dict]] = {"this": [], "peer": []}
    for _ in range(max(1, args.rounds)):
        runs["peer"].append(_measure_in_subprocess(peer_tree, args))
        runs["this"].append(_measure_in_subprocess(this_tree, args))

    def median(name: str, key: str) -> float:
        values = [r[key] for r in runs[name] if r.get(key) is not None]
        return float(np.median(values)) if values else float("nan")

    keys = ("fps", "mean_draw_ms", "mean_render_ms", "mean_encode_ms", "map_rows_repainted_per_frame",
            "real_time_factor", "load_average")
    print(f"{'median of ' + str(args.rounds):<30}{'this':>10}{'peer':>10}")
    for key in keys:
        print(f"{key:<30}{median('this', key):>10.2f}{median('peer', key):>10.2f}")
    for name in ("this", "peer"):
        fps_list = [r["fps"] for r in runs[name]]
        print(f"{name} fps per round: {fps_list} at load {[r['load_average'] for r in runs[name]]}")
    fps_ratio = median("this", "fps") / max(median("peer", "fps"), 1e-9)
    ui_this = median("this", "mean_render_ms") + median("this", "mean_encode_ms")
    ui_peer = median("peer", "mean_render_ms") + median("peer", "mean_encode_ms")
    print(f"ratio fps this/peer {fps_ratio:.2f}")
    print(f"ratio render+encode ms per update this/peer {ui_this / max(ui_peer, 1e-9):.2f}")
    print(f"fps={median('this', 'fps')} peer_fps={median('peer', 'fps')} ratio={fps_ratio:.2f} "
          f"agents={args.agents} terminal={args.size} load={round(os.getloadavg()[0], 2)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
