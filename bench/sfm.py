"""Crowd step benchmark: GROVE's numba SFM against PySocialForce 1.1.2 and JuPedSim 1.4.2 (SocialForceModel).

The same scenario for all three: N pedestrians on a jittered grid (0.5 per m^2) in a walled square
room, each walking to the nearest of four 3 m doors, one in the middle of each side. Agents that
reach their door leave (JuPedSim's exit stages remove them; GROVE deactivates them each second;
PySocialForce has no removal, its agents stop at the goal), so throughput is counted as live
agents times steps. Each simulator runs at its own step: GROVE 0.05 s, JuPedSim 0.01 s (its
default), PySocialForce 0.4 s (the step it really uses: its [scene] config is ignored), so both
agent-steps per second and simulated seconds per wall second are printed.

Run by hand (not a test):  python bench/sfm.py [--sizes 100 1000 10000] [--repeat 1] [--baseline CHECKOUT]
--baseline runs GROVE's crowd from another checkout (a subprocess importing its grove_tui) on the same
scenario right after this one's, size by size: before and after in the same run.
Needs `pip install pysocialforce==1.1.2 jupedsim==1.4.2`; a missing peer is reported and skipped.

Issue 32, before and after in one session (2026-11-28 11:15-11:21, 2 cores, load average 11 from other
engineers' work): `python bench/sfm.py --sizes 1000 10000` in a checkout of main at 2047930 (before, its
own copy of this bench) between two runs at crowd d17ffad (after). Agent-steps per wall second / per
CPU-second; JuPedSim 1.4.2 ran in each run and moved by under 10 %:

    N       GROVE before     GROVE after              JuPedSim            after / JuPedSim per CPU-s
    1,000   141k / 553k      279k-353k / 1.32M-1.40M   92k-97k / 390k-399k  3.3x-3.6x (before 1.4x)
    10,000  176k / 901k      481k-551k / 1.91M-2.19M   112k-119k / 496k-517k 3.8x-4.2x (before 1.8x)

In one run, 11:44-11:46 at load average 7.5-9.1, `python bench/sfm.py --sizes 1000 10000 --no-profile
--baseline <checkout of 2047930>` (crowd at dbaecd8): 1,000 agents 465k / 1.40M after, 203k / 556k before,
JuPedSim 118k / 403k (after 3.5x JuPedSim per CPU-second, before 1.4x); 10,000 agents 614k / 1.98M after,
236k / 920k before, JuPedSim 119k / 489k (4.1x, before 1.9x).

Top three costs after (share of GROVE's CPU time, one thread): the pair search 27-31 %, the pair terms
and sums 20-21 %, the per-agent pass (drive, walls, groups, move) 19 %. The wall-clock goals (2M
agent-steps/s at 10,000 on 2 quiet cores, 1M with one other process busy) could not be measured: the
load average never fell below 6 in the session.

Quiet machine (measured by the lead, 2026-11-28 14:18-14:19 UTC, main at aa7eb2a, load average 0.4-0.7,
`python bench/sfm.py --sizes 1000 10000 --no-profile`): 1,000 agents 1.45M agent-steps/s wall (3.5x
JuPedSim 1.4.2's 416k); 10,000 agents 3.42M wall / 2.09M per CPU-second (6.5x JuPedSim wall, 4.0x per
CPU-second). With one other process busy (a `while True: pass` Python loop), 14:20, load 1.0-1.3: 10,000
agents 2.22M wall (4.4x JuPedSim). Both wall-clock goals hold.

Bodies as wide as the shoulders and the density ahead counting oneself as half a person (issue 32's
0.8 m bottleneck; docs/BENCHMARKS.md), before and after in one run, 14:57-14:58 at load average 4.6,
`python bench/sfm.py --sizes 1000 10000 --no-profile --baseline /work/main` (crowd2 395712f against main
aa7eb2a): per CPU-second 1.42M -> 1.43M at 1,000 agents (3.5x JuPedSim's 412k), 2.13M -> 2.18M at 10,000
(4.2x JuPedSim's 519k). (Wall at that load: 1.21M -> 610k at 1,000, where the other jobs took a core
during the after run, and 1.12M -> 970k at 10,000.) A second such run with --repeat 3 (14:59-15:00, load
3.3-3.4) gave 1.45M -> 1.47M and 2.23M -> 2.01M, so the two were alternated three times each,
`python bench/sfm.py --code CHECKOUT --grove-only N STEPS --repeat 3` (15:01-15:02, load 2.9-3.4), per
CPU-second: 10,000 agents 2.11 / 2.19 / 2.26M after against 2.11 / 2.15 / 2.16M before (+2 % on the mean),
1,000 agents 1.47 / 1.45 / 1.38M against 1.44 / 1.40 / 1.28M (+4 %). No cost: the kernels do the same work.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import logging
import math
import os
import platform
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np



def _code_root() -> str:
    """The checkout whose grove_tui this run imports: this one, or --code DIR (how --baseline runs another)."""
    if "--code" in sys.argv[:-1]:
        return str(Path(sys.argv[sys.argv.index("--code") + 1]).resolve())
    return str(Path(__file__).resolve().parents[1])


sys.path.insert(0, _code_root())

from grove_tui.crowd.crowd import Crowd  # noqa: E402

DENSITY = 0.5          # initial pedestrians per square metre
DOOR_WIDTH = 3.0
SPEED = 1.2            # desired speed, m/s
RADIUS = 0.3
PSF_MAX_AGENTS = 2000  # PySocialForce is all-pairs: beyond this one step takes many seconds


@dataclass
class Scenario:
    n: int
    side: float
    positions: np.ndarray      # (n, 2)
    exit_of: np.ndarray        # (n,) index into doors
    doors: np.ndarray          # (4, 2) door centres on the walls
    outward: np.ndarray        # (4, 2) unit normals pointing out of the room

    def walls(self) -> np.ndarray:
        """Room boundary as segments with the four door openings cut out."""
        s, h = self.side, DOOR_WIDTH / 2
        m = s / 2
        return np.array([
            [0, 0, m - h, 0], [m + h, 0, s, 0],
            [s, 0, s, m - h], [s, m + h, s, s],
            [s, s, m + h, s], [m - h, s, 0, s],
            [0, s, 0, m + h], [0, m - h, 0, 0],
        ], dtype=float)

    def goals(self) -> np.ndarray:
        return self.doors[self.exit_of] + self.outward[self.exit_of] * 1.5


def make_scenario(n: int, seed: int = 0) -> Scenario:
    rng = np.random.default_rng(seed)
    spacing = 1.0 / math.sqrt(DENSITY)
    per_row = math.ceil(math.sqrt(n))
    side = per_row * spacing + 2.0
    cells = np.array([(i % per_row, i // per_row) for i in range(n)], dtype=float)
    positions = 1.0 + (cells + 0.5) * spacing + rng.uniform(-0.25, 0.25, size=(n, 2))
    m = side / 2
    doors = np.array([[m, 0.0], [side, m], [m, side], [0.0, m]])
    outward = np.array([[0.0, -1.0], [1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]])
    exit_of = np.argmin(np.linalg.norm(positions[:, None, :] - doors[None], axis=2), axis=1)
    return Scenario(n, side, positions, exit_of, doors, outward)


@dataclass
class Result:
    name: str
    n: int
    steps: int
    agent_steps: int
    wall_s: float
    sim_s: float
    cpu_s: float

    @property
    def rate(self) -> float:
        return self.agent_steps / self.wall_s

    @property
    def cpu_rate(self) -> float:
        """Agent-steps per CPU-second summed over threads: comparable when other jobs share the cores."""
        return self.agent_steps / self.cpu_s

    @property
    def realtime(self) -> float:
        return self.sim_s / self.wall_s


def run_grove(sc: Scenario, steps: int) -> Result:
    crowd = Crowd(sc.walls(), dt=0.05)
    goals = sc.goals()
    for p, g in zip(sc.positions, goals):
        crowd.add_agent(p, radius=RADIUS, desired_speed=SPEED, goals=[tuple(g)], goal_radius=1.0)
    crowd.step(1)  # compiled already by the warm-up; this touches every page once
    chunk = 20     # one second: arrivals are removed at this rate
    agent_steps = 0
    done = 0
    cpu = time.process_time()
    start = time.perf_counter()
    while done < steps:
        k = min(chunk, steps - done)
        live = int(crowd.active.sum())
        crowd.step(k)
        agent_steps += live * k
        done += k
        arrived = np.hypot(*(crowd.pos - goals).T) <= 1.1
        crowd.active[arrived] = False
    wall = time.perf_counter() - start
    cpu = time.process_time() - cpu
    return Result("grove", sc.n, steps, agent_steps, wall, steps * crowd.dt, cpu)


def profile_grove(sc: Scenario, steps: int) -> dict[str, float]:
    """CPU seconds per phase of GROVE's step (Crowd.profile) over the same window as run_grove."""
    crowd = Crowd(sc.walls(), dt=0.05)
    goals = sc.goals()
    for p, g in zip(sc.positions, goals):
        crowd.add_agent(p, radius=RADIUS, desired_speed=SPEED, goals=[tuple(g)], goal_radius=1.0)
    spent: dict[str, float] = {}
    done = 0
    while done < steps:
        k = min(20, steps - done)
        for phase, seconds in crowd.profile(k).items():
            spent[phase] = spent.get(phase, 0.0) + seconds
        done += k
        crowd.active[np.hypot(*(crowd.pos - goals).T) <= 1.1] = False
    return spent


def warm_up_grove() -> None:
    small = make_scenario(64)
    run_grove(small, 2)
    big = Crowd(small.walls())
    big.parallel_threshold = 0
    big.add_agent((5.0, 5.0))
    big.step(1)
    if hasattr(big, "profile"):  # a --baseline checkout may predate Crowd.profile
        big.profile(1)


@contextlib.contextmanager
def _quiet_cwd():
    """PySocialForce logs at DEBUG into ./file.log on import; keep that out of the repository."""
    previous = os.getcwd()
    with tempfile.TemporaryDirectory() as tmp:
        os.chdir(tmp)
        try:
            yield
        finally:
            os.chdir(previous)


def run_pysocialforce(sc: Scenario, steps: int) -> Result:
    with _quiet_cwd():
        psf = importlib.import_module("pysocialforce")
        logging.getLogger().setLevel(logging.WARNING)
        goals = sc.goals()
        direction = goals - sc.positions
        direction /= np.linalg.norm(direction, axis=1, keepdims=True)
        # Desired speed is 1.3 x the initial speed: start at SPEED / 1.3 so both cap at SPEED.
        state = np.column_stack([sc.positions, direction * SPEED / 1.3, goals])
        obstacles = [[w[0], w[2], w[1], w[3]] for w in sc.walls()]
        sim = psf.Simulator(state, obstacles=obstacles)
        sim.step(1)  # numba helpers compile on the first call
        cpu = time.process_time()
        start = time.perf_counter()
        sim.step(steps)
        wall = time.perf_counter() - start
        cpu = time.process_time() - cpu
        step_width = float(sim.peds.step_width)
    return Result("pysocialforce", sc.n, steps, sc.n * steps, wall, steps * step_width, cpu)


def run_jupedsim(sc: Scenario, iterations: int) -> Result:
    jps = importlib.import_module("jupedsim")
    shapely = importlib.import_module("shapely")
    s, h = sc.side, DOOR_WIDTH / 2
    room = shapely.box(0, 0, s, s)
    corridors, exits = [], []
    for door, out in zip(sc.doors, sc.outward):
        tangent = np.array([-out[1], out[0]])
        a = door - tangent * h
        b = door + tangent * h
        corridors.append(shapely.Polygon([a - out * 0.01, b - out * 0.01, b + out * 3.0, a + out * 3.0]))
        exits.append(shapely.Polygon([a + out * 1.0, b + out * 1.0, b + out * 2.0, a + out * 2.0]))
    geometry = shapely.union_all([room, *corridors])
    sim = jps.Simulation(model=jps.SocialForceModel(), geometry=geometry, dt=0.01)
    journeys = []
    for polygon in exits:
        exit_id = sim.add_exit_stage(polygon)
        journeys.append((sim.add_journey(jps.JourneyDescription([exit_id])), exit_id))
    for p, e in zip(sc.positions, sc.exit_of):
        journey_id, stage_id = journeys[e]
        sim.add_agent(jps.SocialForceModelAgentParameters(
            journey_id=journey_id, stage_id=stage_id, position=(float(p[0]), float(p[1])),
            desired_speed=SPEED, radius=RADIUS))
    chunk = 50
    agent_steps = 0
    done = 0
    cpu_start = time.process_time()
    start = time.perf_counter()
    wall = cpu = 0.0
    while done < iterations:
        k = min(chunk, iterations - done)
        live = sim.agent_count()
        try:
            sim.iterate(k)
        except RuntimeError as exc:
            # JuPedSim's SFM can push an agent out of the walkable area, which ends the run;
            # the throughput up to the last completed chunk still stands.
            print(f"# jupedsim N={sc.n} stopped after {done} iterations: {exc}")
            break
        agent_steps += live * k
        done += k
        wall = time.perf_counter() - start
        cpu = time.process_time() - cpu_start
    if done == 0:
        raise RuntimeError(f"jupedsim failed in its first {chunk} iterations at N={sc.n}")
    return Result("jupedsim", sc.n, done, agent_steps, wall, done * 0.01, cpu)


def window_seconds(n: int) -> float:
    """Simulated seconds measured at size n: 10 s, shortened for big crowds to keep the run short."""
    return 10.0 if n <= 2000 else 4.0


def available(module: str) -> bool:
    try:
        with _quiet_cwd():
            importlib.import_module(module)
        logging.getLogger().setLevel(logging.WARNING)
        return True
    except ImportError:
        return False


def run_baseline(checkout: Path, n: int, steps: int, repeat: int) -> Result:
    """GROVE's crowd from another checkout on the same scenario, in a subprocess importing its grove_tui."""
    import subprocess

    done = subprocess.run([sys.executable, __file__, "--code", str(checkout), "--grove-only", str(n), str(steps),
                           "--repeat", str(repeat)], capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"the baseline {checkout} failed at N={n}:\n{done.stderr[-2000:]}")
    values = dict(item.split("=") for item in done.stdout.split()[-5:])
    return Result("baseline", n, int(values["steps"]), int(values["agent_steps"]), float(values["wall_s"]),
                  float(values["sim_s"]), float(values["cpu_s"]))


def best_of(repeat: int, fn, *args) -> Result:
    results = [fn(*args) for _ in range(repeat)]
    return max(results, key=lambda r: r.rate)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[100, 1000, 10000])
    parser.add_argument("--repeat", type=int, default=1, help="runs per measurement; the best is kept")
    parser.add_argument("--no-profile", action="store_true", help="skip naming GROVE's top three costs")
    parser.add_argument("--baseline", type=Path, default=None,
                        help="another checkout whose crowd runs the same scenarios in the same run (before/after)")
    parser.add_argument("--code", type=Path, default=None, help=argparse.SUPPRESS)  # read by _code_root
    parser.add_argument("--grove-only", type=int, nargs=2, default=None, help=argparse.SUPPRESS)  # N steps
    args = parser.parse_args(argv)
    if args.grove_only:
        warm_up_grove()
        n, steps = args.grove_only
        r = best_of(args.repeat, run_grove, make_scenario(n), steps)
        print(f"steps={r.steps} agent_steps={r.agent_steps} wall_s={r.wall_s} sim_s={r.sim_s} cpu_s={r.cpu_s}")
        return 0

    import numba

    print(f"# {platform.processor() or platform.machine()}, {os.cpu_count()} cpus, Python {platform.python_version()}, "
          f"numba {numba.__version__} ({numba.config.NUMBA_NUM_THREADS} threads), numpy {np.__version__}")
    print(f"# load average before the run: {os.getloadavg()[0]:.1f} (other jobs on these cores lower every wall figure)")
    if args.baseline is not None:
        print(f"# baseline: GROVE's crowd from {args.baseline.resolve()}, right after this checkout's at each size")
    print(f"# scenario: square room, 4 doors of {DOOR_WIDTH} m, {DENSITY} agents/m^2, v0 {SPEED} m/s, r {RADIUS} m; "
          f"GROVE and JuPedSim simulate the same window (10 s, 4 s above 2,000 agents)")
    have_psf = available("pysocialforce")
    have_jps = available("jupedsim")
    if not have_psf:
        print("# pysocialforce not installed: skipped (pip install pysocialforce==1.1.2)")
    if not have_jps:
        print("# jupedsim not installed: skipped (pip install jupedsim==1.4.2)")
    warm_up_grove()

    header = (f"{'simulator':<14}{'N':>7}{'dt':>6}{'steps':>7}{'wall s':>9}{'agent-steps/s':>15}"
              f"{'sim s/wall s':>14}{'per CPU-s':>13}")
    print(header)
    table: dict[tuple[str, int], Result] = {}
    for n in args.sizes:
        sc = make_scenario(n)
        # The same simulated window for GROVE and JuPedSim: the crowd (and the cost of a step)
        # changes as the doors jam, so equal windows compare equal work.
        window = window_seconds(n)
        runs = [("grove", run_grove, round(window / 0.05), 0.05)]
        if have_jps:
            runs.append(("jupedsim", run_jupedsim, round(window / 0.01), 0.01))
        if have_psf and n <= PSF_MAX_AGENTS:
            # PySocialForce takes seconds per step at 1,000 agents: as many steps as fit the window or ~4 s.
            psf_steps = max(2, min(round(window / 0.4), 4_000 // max(n, 1)))
            runs.append(("pysocialforce", run_pysocialforce, psf_steps, 0.4))
        if args.baseline is not None:
            runs.insert(1, ("baseline", None, round(window / 0.05), 0.05))
        for name, fn, steps, dt in runs:
            result = (run_baseline(args.baseline, n, steps, args.repeat) if fn is None
                      else best_of(args.repeat, fn, sc, steps))
            table[(name, n)] = result
            print(f"{name:<14}{n:>7}{dt:>6}{result.steps:>7}{result.wall_s:>9.2f}{result.rate:>15,.0f}"
                  f"{result.realtime:>14.1f}{result.cpu_rate:>13,.0f}", flush=True)
        grove = table[("grove", n)]
        for peer in ("baseline", "jupedsim", "pysocialforce"):
            if (peer, n) in table:
                other = table[(peer, n)]
                print(f"  grove / {peer} at N={n}: {grove.cpu_rate / other.cpu_rate:.1f}x agent-steps per CPU-second, "
                      f"{grove.rate / other.rate:.1f}x agent-steps per wall second, "
                      f"{grove.realtime / other.realtime:.1f}x simulated time")
        if not args.no_profile:
            spent = profile_grove(sc, round(window / 0.05))
            total = sum(spent.values()) or 1.0
            top = sorted(spent.items(), key=lambda kv: -kv[1])[:3]
            print(f"  grove's top three costs at N={n} (share of its CPU time, one thread): "
                  + "; ".join(f"{name} {100 * seconds / total:.0f}%" for name, seconds in top))

    headline = {}
    for (name, n), result in sorted(table.items(), key=lambda kv: (kv[0][1], kv[0][0])):
        headline[f"{name}_{n}_agent_steps_per_s"] = f"{result.rate:.0f}"
        headline[f"{name}_{n}_sim_s_per_wall_s"] = f"{result.realtime:.2f}"
        headline[f"{name}_{n}_agent_steps_per_cpu_s"] = f"{result.cpu_rate:.0f}"
        if name != "grove" and ("grove", n) in table:
            headline[f"ratio_vs_{name}_{n}"] = f"{table[('grove', n)].rate / result.rate:.2f}"
            headline[f"cpu_ratio_vs_{name}_{n}"] = f"{table[('grove', n)].cpu_rate / result.cpu_rate:.2f}"
    headline["load_average"] = f"{os.getloadavg()[0]:.1f}"
    print(" ".join(f"{k}={v}" for k, v in headline.items()))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
