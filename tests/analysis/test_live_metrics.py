"""The live counters' metrics (fed as the run goes) equal `grove metrics` of the same run's files."""

from __future__ import annotations

import math

import pytest
from helpers.handmade import build_hospital_bundle

from grove_tui.analysis.bundle_metrics import bundle_metrics, scenario_metrics
from grove_tui.analysis.live_metrics import LiveMetrics, rows_table
from grove_tui.analysis.metrics import Trajectories
from grove_tui.scenario.bundle import load_scenario
from grove_tui.scenario.events import write_events
from grove_tui.simulation.simulation import Simulation
from grove_tui.world import load_world


def same(a: float, b: float) -> bool:
    # Bit-identical but for the means over people x frames, which are summed chunk by chunk.
    return math.isclose(a, b, rel_tol=1e-12, abs_tol=1e-12) or (math.isnan(a) and math.isnan(b))


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    bundle = build_hospital_bundle(tmp_path_factory.mktemp("live") / "bundle")
    scenario = load_scenario(bundle)
    world = load_world(scenario.world)
    sim = Simulation.from_scenario(scenario, bundle, world=world)
    live = LiveMetrics(scenario, world)
    looked = []
    for step in range(1, 801):  # 40 s: the pair converses, the queue is served
        sim.step()
        if step % 7 == 0 or step == 1:
            assert live.update(sim.recorder)
            looked.append((live.t, live.values(sim.events)))
    live.update(sim.recorder)
    assert not live.update(sim.recorder), "nothing new was recorded"
    return bundle, scenario, world, sim, live, looked


def test_live_values_equal_grove_metrics_of_the_written_run(run):
    bundle, scenario, world, sim, live, _ = run
    sim.recorder.write_csv(bundle / "trajectories.csv")
    write_events(bundle / "events.jsonl", sim.events)
    files, _ = bundle_metrics(bundle, write=False)
    expected = {**files.robot, **files.crowd}
    got = live.values(sim.events)
    assert got.keys() == expected.keys()
    assert [key for key in expected if not same(got[key], expected[key])] == []
    assert got["queue_served"] >= 1 and got["path_length"] > 0 and live.t == pytest.approx(40.0)


def test_each_look_is_the_run_up_to_its_own_time(run):
    _, scenario, world, sim, _, looked = run
    rows = sim.recorder.to_array()
    for t, values in looked[1::10]:
        upto = rows[rows["t"] <= t + 1e-9]
        events = [e for e in sim.events if e.t <= t + 1e-9]
        report = scenario_metrics(scenario, world, Trajectories.from_rows(rows_table(upto)), events)
        expected = {**report.robot, **report.crowd}
        assert values.keys() == expected.keys(), t
        assert [key for key in expected if not same(values[key], expected[key])] == [], t
