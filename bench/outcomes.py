"""What the outcome checks cost against the simulation they check (run by hand, not a test).

    PYTHONPATH=. python bench/outcomes.py [--seconds 600] [--out /tmp/outcomes-bench]

Builds a 500-person airport scenario from a sentence (the real reader, post-processing and planning;
the draft is the plain one, no model: the checks do not depend on it) with walkers, a queue,
wanderers, waiters, a conversation and people reacting to the robot, simulates it for `--seconds`
(600 by default) and measures, on the recorded run:

- sim: the simulation's wall time (Simulation.run);
- checks: the outcome checks fed the run's frames (OutcomeChecker.add + result), as `grove simulate`
  runs them, on the pass over trajectories.csv that metrics.json makes anyway;
- standalone: `check_bundle`, which reads trajectories.csv again by itself (the CSV parsing included);
- metrics: metrics.json's own pass, for scale.

The issue's bar: checks at most 5 % of sim. Figures are CPU-bound: the load average is printed.
Last line: key=value.
"""

from __future__ import annotations

import argparse
import os
import shutil
import sys
import time
from dataclasses import replace
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
sys.path.insert(0, str(REPO / "tests"))

PROMPT = ("two hundred passengers walk from the check-in hall to gate a1 while eighty travellers wander around the "
          "concourse, a hundred people wait in the baggage claim, forty shoppers queue at the duty free till, "
          "thirty friends chat in the cafe, forty tourists look at the robot in the concourse and ten children "
          "follow the robot")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=600.0)
    parser.add_argument("--out", type=Path, default=Path("/tmp/outcomes-bench"))
    args = parser.parse_args()

    import helpers.hand_bundle as hand
    from helpers.hand_bundle import hand_bundle

    from grove_tui.analysis.bundle_metrics import bundle_metrics
    from grove_tui.analysis.metrics import iter_trajectory_chunks
    from grove_tui.analysis.outcomes import OutcomeChecker, check_bundle, planned_report
    from grove_tui.scenario.bundle import load_report, load_scenario
    from grove_tui.scenario.events import read_events, write_events
    from grove_tui.simulation.simulation import Simulation
    from grove_tui.generation.presets import load_preset
    from grove_tui.world import load_world

    # The normal preset holds a prompt to 6 groups of 40 (a guard on what one sentence asks for); this
    # bench needs 500 people doing everything the checks measure, so its preset allows more.
    def roomy_preset(name: str):  # type: ignore[no-untyped-def]
        preset = load_preset(name)
        return replace(preset, limits=replace(preset.limits, max_groups=8, max_count=200))
    hand.load_preset = roomy_preset
    if args.out.exists():
        shutil.rmtree(args.out)
    result, bundle = hand_bundle(args.out, "airport", "normal", PROMPT, [])
    people = len(result.scenario.agents)
    world = load_world("airport")
    sim = Simulation.from_scenario(result.scenario, bundle, world=world)
    started = time.perf_counter()
    sim.run(args.seconds)
    sim_wall = time.perf_counter() - started
    sim.recorder.write_csv(bundle / "trajectories.csv")
    write_events(bundle / "events.jsonl", sim.events)

    started = time.perf_counter()
    bundle_metrics(bundle)
    metrics_wall = time.perf_counter() - started

    scenario = load_scenario(bundle)
    events = read_events(bundle / "events.jsonl")
    checker = OutcomeChecker(planned_report(load_report(bundle)), scenario, world)
    ids, _groups, chunks = iter_trajectory_chunks(bundle / "trajectories.csv")
    checker.set_ids(ids)
    checks_wall = 0.0
    for chunk in chunks:  # the pass metrics.json makes anyway: only the checks' own work is timed
        t0 = time.perf_counter()
        checker.add(chunk)
        checks_wall += time.perf_counter() - t0
    t0 = time.perf_counter()
    report = checker.result(events)
    checks_wall += time.perf_counter() - t0

    started = time.perf_counter()
    check_bundle(bundle, write=False)
    standalone_wall = time.perf_counter() - started

    load = os.getloadavg()
    print(f"{people} people, {args.seconds:.0f} s simulated, {len(report.groups)} groups, "
          f"{sum(len(g.claims) for g in report.groups)} claims; load average {load[0]:.1f} {load[1]:.1f} {load[2]:.1f}")
    print(f"  sim         {sim_wall:8.1f} s wall")
    print(f"  checks      {checks_wall:8.2f} s  ({100 * checks_wall / sim_wall:.2f} % of sim)")
    print(f"  standalone  {standalone_wall:8.2f} s  ({100 * standalone_wall / sim_wall:.2f} % of sim, CSV read included)")
    print(f"  metrics     {metrics_wall:8.2f} s  ({100 * metrics_wall / sim_wall:.2f} % of sim)")
    print("  " + report.summary())
    print(f"people={people} seconds={args.seconds:.0f} sim_s={sim_wall:.1f} checks_s={checks_wall:.2f} "
          f"checks_pct={100 * checks_wall / sim_wall:.2f} standalone_s={standalone_wall:.2f} "
          f"standalone_pct={100 * standalone_wall / sim_wall:.2f} metrics_s={metrics_wall:.2f} load={load[0]:.1f}")


if __name__ == "__main__":
    main()
