"""A dense evacuation of the hospital: is everyone either inside or counted? (run by hand, not a test)

    PYTHONPATH=. python bench/evacuation.py [--agents 500] [--seconds 600] [--out DIR]
    PYTHONPATH=. python bench/evacuation.py --plan [--agents 40] [--baseline CHECKOUT]

--plan times only the planning of an evacuation of --agents people spread over each shipped world
(the emergency preset's post-processing, with each person's exit, and its planning stage, with the
groups' velocity fields and the robot), three times in one process: the first pays for loading the
compiled kernels and the world's door graph (from the data dir, or building it), the others are what
the app pays for a new sentence. CPU and wall seconds; issue 32 asks under 1 s. --baseline CHECKOUT
times the same planning with another checkout's code (a subprocess importing its grove_tui), in the
same run, on the worlds both have.

Issue 32, 2026-11-28 11:31, load average 7.5-8.6, `--plan --agents 40 --baseline <checkout of main at
2047930>` at crowd d373350: a new sentence's planning (warm, the worst world) 1.60 s CPU before, 0.22 s
after (airport; hospital 1.09-1.10 -> 0.18 s, wall 2.85-3.19 -> 0.37-0.39 s); the first in a process,
which also loads the kernels and the door graph, 2.06 -> 0.95 s CPU (3.2 s wall at that load).

Spreads --agents people over the hospital's zones (by free area, at least 0.6 m apart, never within
1.2 m of an exit), sends each zone's people to its nearest exit along that exit's velocity field
(the emergency preset's FollowVelocityField), and simulates. Every simulated second it checks the
invariant of issue 17: each person is evacuated (counted) or active inside the building; an active
person outside the zones for more than one behavior tick is a failure. With --out it writes the
trajectories and runs the metrics step on them, reporting its peak memory. Last line: key=value.
"""

from __future__ import annotations

import argparse
import math
import resource
import subprocess
import sys
import time
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import shapely



def _code_root() -> str:
    """The checkout whose grove_tui this run imports: this one, or --code DIR (how --baseline runs another)."""
    if "--code" in sys.argv[:-1]:
        return str(Path(sys.argv[sys.argv.index("--code") + 1]).resolve())
    return str(Path(__file__).resolve().parents[1])


sys.path.insert(0, _code_root())

from grove_tui.navigation.grid import build_grid  # noqa: E402
from grove_tui.navigation.theta_star import ThetaStarPlanner  # noqa: E402
from grove_tui.world import load_world  # noqa: E402

if TYPE_CHECKING:
    from grove_tui.scenario.model import AgentSpec
    from grove_tui.simulation.simulation import Simulation

MEASURE_METRICS = """
import resource, sys
sys.path.insert(0, {repo!r})
from grove_tui.analysis.metrics import compute_metrics_csv
from grove_tui.world import load_world
report = compute_metrics_csv({csv!r}, walls=load_world("hospital").walls())
print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024, report.crowd["agents"])
"""


def build(agents: int, seed: int) -> tuple[Simulation, list[AgentSpec], list[tuple[float, float]]]:
    # imported here, not at the top: --plan (and its --baseline) needs none of these modules
    from grove_tui.bt.format.xml import parse_tree_text
    from grove_tui.generation.postprocess import FreeSpace
    from grove_tui.navigation.velocity_field import build_velocity_field
    from grove_tui.scenario.model import AgentSpec
    from grove_tui.simulation.simulation import Simulation

    world = load_world("hospital")
    grid = build_grid(world, 0.1)
    planner = ThetaStarPlanner(grid)
    space = FreeSpace(world, grid)
    rng = np.random.default_rng(seed)
    exits = {door.name: world.roi(door.name).point for door in world.exits()}
    zones = [zone for zone in world.zones if space.free_area(zone.name) > 4.0]
    area = np.array([space.free_area(zone.name) for zone in zones])
    counts = np.floor(agents * area / area.sum()).astype(int)
    counts[np.argsort(-area)[: agents - counts.sum()]] += 1
    nearest_exit = {zone.name: min(exits, key=lambda name: math.dist(exits[name], zone.centroid)) for zone in zones}
    fields = {}
    for exit_name in sorted(set(nearest_exit.values())):
        farthest = max((z for z in zones if nearest_exit[z.name] == exit_name),
                       key=lambda z: math.dist(exits[exit_name], z.centroid))
        start = space.sample(farthest.name, 1, rng, 0.1, key="field-start")[0]
        fields[exit_name] = build_velocity_field(grid, planner.plan(start, exits[exit_name]), exits[exit_name],
                                                 planner=planner)
    specs, documents, exit_points = [], [], []
    for zone, count in zip(zones, counts):
        exit_name = nearest_exit[zone.name]
        for start in space.sample(zone.name, int(count), rng, 0.6, key="spawn"):
            agent_id = len(specs) + 1
            exit_points.append(exits[exit_name])
            specs.append(AgentSpec(id=agent_id, group=-1, start=start, goals=(), zone=zone.name,
                                   tree=f"trees/agent_{agent_id}.xml", radius=0.3, max_vel=1.5))
            documents.append(parse_tree_text(
                f'<root BTCPP_format="4" main_tree_to_execute="T"><BehaviorTree ID="T">'
                f'<FollowVelocityField exit="{exit_name}" field="{exit_name}"/></BehaviorTree></root>', f"agent_{agent_id}"))
    sim = Simulation.build(specs, documents, world=world, grid=grid, planner=planner, walls=world.walls(),
                           fields=fields, seed=seed)
    return sim, specs, exit_points


def plan_evacuation(world_name: str, agents: int, seed: int) -> tuple[float, float, int]:
    """(CPU s, wall s, fields) of post-processing and planning an evacuation of `agents` people."""
    from grove_tui.generation.draft import Draft, DraftGroup, DraftNode
    from grove_tui.generation.planning import plan_operational
    from grove_tui.generation.postprocess import postprocess
    from grove_tui.generation.presets import load_preset
    from grove_tui.generation.rois import select_rois
    from grove_tui.language.reading import read_prompt

    world = load_world(world_name)
    preset = load_preset("emergency")
    prompt = f"{agents} people evacuate the building"
    grid = build_grid(world, resolution=preset.planner.resolution, inflation=preset.planner.inflation)
    reading = read_prompt(prompt, world)
    selection = select_rois(world, preset, reading)
    leave = DraftNode("Sequence", {}, (DraftNode("FollowVelocityField", {"exit": world.exits()[0].name}),))
    draft = Draft((DraftGroup("people", agents, None, leave),))
    wall, cpu = time.perf_counter(), time.process_time()
    post = postprocess(world, grid, preset, draft, selection, seed, reading,
                       ("Sequence", "FollowVelocityField", "JoinGroup", "Wait"))
    plan = plan_operational(world, grid, preset, post, seed, planner=ThetaStarPlanner(grid))
    return time.process_time() - cpu, time.perf_counter() - wall, len(plan.fields)


def plan_only(agents: int, worlds: list[str] | None = None) -> None:
    from grove_tui.world import list_worlds

    import os

    print(f"# {_code_root()}: load average {os.getloadavg()[0]:.1f}; {agents} people spread over each world, "
          f"emergency preset", flush=True)
    worst_warm = 0.0
    for name in worlds or list_worlds():
        runs = [plan_evacuation(name, agents, seed) for seed in range(3)]
        worst_warm = max(worst_warm, *(cpu for cpu, _wall, _f in runs[1:]))
        print(f"{name:<12} fields {runs[0][2]}  first {runs[0][0]:.2f} s CPU / {runs[0][1]:.2f} s wall   "
              + "   ".join(f"then {cpu:.2f} s CPU / {wall:.2f} s wall" for cpu, wall, _f in runs[1:]), flush=True)
    print(f"agents={agents} worst_warm_cpu_s={worst_warm:.2f} load_average={os.getloadavg()[0]:.1f}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--plan", action="store_true", help="time the planning of an evacuation only")
    parser.add_argument("--agents", type=int, default=None, help="people (default 500, or 40 with --plan)")
    parser.add_argument("--seconds", type=float, default=600.0)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", type=Path, default=None, help="folder for trajectories.csv; then measure metrics")
    parser.add_argument("--baseline", type=Path, default=None,
                        help="with --plan: another checkout whose code plans the same evacuations, in the same run")
    parser.add_argument("--code", type=Path, default=None, help=argparse.SUPPRESS)  # read by _code_root
    parser.add_argument("--worlds", nargs="+", default=None, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.plan:
        worlds = args.worlds
        if args.baseline is not None:
            from grove_tui.world import list_worlds

            theirs = subprocess.run([sys.executable, "-c", "import sys; sys.path.insert(0, sys.argv[1]); "
                                     "from grove_tui.world import list_worlds; print(' '.join(list_worlds()))",
                                     str(args.baseline)], capture_output=True, text=True, check=True).stdout.split()
            worlds = [name for name in list_worlds() if name in theirs]
            subprocess.run([sys.executable, __file__, "--plan", "--agents", str(args.agents or 40),
                            "--code", str(args.baseline), "--worlds", *worlds], check=True)
        plan_only(args.agents or 40, worlds)
        return
    from grove_tui.crowd.leaves.grove import EXIT_RADIUS
    args.agents = args.agents or 500
    started = time.perf_counter()
    sim, specs, exit_points = build(args.agents, args.seed)
    n = len(specs)
    building = sim.world.outline()
    shapely.prepare(building)
    print(f"built {n} people in {time.perf_counter() - started:.1f} s", flush=True)
    worst = 0.0
    violations = 0
    everyone_out_at = math.nan
    started = time.perf_counter()
    per_second = max(1, int(round(1.0 / sim.dt)))
    while sim.time < args.seconds:
        for _ in range(per_second):
            sim.step()
        active = np.flatnonzero(sim.crowd.active[:n])
        if len(active):
            distance = shapely.distance(building, shapely.points(sim.crowd.pos[active]))
            worst = max(worst, float(distance.max()))
            violations += int((distance > 0.5).sum())
        evacuated = sum(1 for e in sim.context.events if e[2] == "evacuated")
        if int(sim.time) % 30 == 0:
            print(f"t={sim.time:6.0f} s evacuated={evacuated} inside={len(active)} "
                  f"wall={time.perf_counter() - started:.0f} s", flush=True)
        if not len(active):
            everyone_out_at = sim.time
            break
    wall = time.perf_counter() - started
    kinds = [e[2] for e in sim.context.events]
    evacuated = kinds.count("evacuated")
    inside = int(sim.crowd.active[:n].sum())
    # Evacuees who left the building away from their exit point (pushed past it, or out through
    # another exit): the ones the simulation used to lose. Inactive agents keep their last position.
    pushed_past = sum(1 for e in sim.context.events if e[2] == "evacuated"
                      and math.dist(sim.crowd.pos[e[1] - 1], exit_points[e[1] - 1]) > EXIT_RADIUS + 0.05)
    peak_sim = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    metrics_peak = math.nan
    if args.out is not None:
        args.out.mkdir(parents=True, exist_ok=True)
        csv = args.out / "trajectories.csv"
        sim.recorder.write_csv(csv)
        done = subprocess.run([sys.executable, "-c", MEASURE_METRICS.format(
            repo=str(Path(__file__).resolve().parents[1]), csv=str(csv))], capture_output=True, text=True, check=True)
        metrics_peak = int(done.stdout.split()[0]) / 2**20
    print(f"agents={n} sim_seconds={sim.time:.0f} wall_seconds={wall:.0f} evacuated={evacuated} inside={inside} "
          f"left_building={kinds.count('left_building')} pushed_past_exit_point={pushed_past} accounted={evacuated + inside == n} "
          f"outside_uncounted={violations} worst_outside_m={worst:.2f} everyone_out_s={everyone_out_at:.0f} "
          f"sim_peak_mb={peak_sim / 2**20:.0f} metrics_peak_mb={metrics_peak:.0f}")


if __name__ == "__main__":
    main()
