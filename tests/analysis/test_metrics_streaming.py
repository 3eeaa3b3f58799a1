"""Metrics streamed over trajectories.csv equal the in-memory ones, and memory does not grow with
the run's length."""

from __future__ import annotations

import math
import tracemalloc

import numpy as np
import pytest

from grove_tui.analysis.metrics import Trajectories, compute_metrics, compute_metrics_csv, iter_trajectory_chunks
from grove_tui.errors import MetricsError
from grove_tui.scenario.bundle import load_scenario
from grove_tui.scenario.events import read_events
from grove_tui.world import load_world

SIMULATED_SECONDS = 20.0  # the `simulated` fixture's run (tests/conftest.py)


def options(bundle):
    scenario = load_scenario(bundle)
    world = load_world(scenario.world)
    return dict(walls=world.walls(), robot_goal=scenario.robot.goal, robot_radius=scenario.robot.radius,
                person_radius=0.35, final_goals={a.id: a.goals[-1] for a in scenario.agents if a.goals},
                events=read_events(bundle / "events.jsonl"), walkable_area=float(world.walkable().area),
                groups={a.id: a.group for a in scenario.agents})


@pytest.mark.parametrize("rows_per_block", [7, 37, 1000])
def test_streamed_metrics_equal_the_in_memory_result(simulated, rows_per_block):
    csv = simulated / "trajectories.csv"
    whole = compute_metrics(Trajectories.from_csv(csv), **options(simulated))
    streamed = compute_metrics_csv(csv, rows_per_block=rows_per_block, **options(simulated))
    _, _, chunks = iter_trajectory_chunks(csv, rows_per_block)
    assert sum(1 for _ in chunks) > 1  # frames really were split over blocks
    for part in ("robot", "crowd"):
        expected, got = getattr(whole, part), getattr(streamed, part)
        assert expected.keys() == got.keys()
        for key, value in expected.items():
            # Bit-identical except the two means over people x frames, summed per chunk.
            assert math.isclose(got[key], value, rel_tol=1e-12, abs_tol=1e-12) or (math.isnan(value) and math.isnan(got[key])), key
    assert whole.robot["path_length"] > 0 and whole.crowd["agents"] == 5


def write_run(path, frames: int, agents: int = 100) -> None:
    rng = np.random.default_rng(0)
    with path.open("w") as out:
        out.write("frame,t,id,x,y,vx,vy,yaw,group\n")
        for start in range(0, frames, 500):
            block = []
            for f in range(start, min(frames, start + 500)):
                ids = np.arange(agents + 1)
                xy = rng.uniform(0, 40, (agents + 1, 2))
                v = rng.normal(0, 1, (agents + 1, 2))
                block.append(np.column_stack([np.full(agents + 1, f), np.full(agents + 1, f * 0.05), ids, xy, v,
                                              np.zeros(agents + 1), np.full(agents + 1, -1)]))
            np.savetxt(out, np.concatenate(block), fmt="%d,%.2f,%d,%.3f,%.3f,%.3f,%.3f,%.1f,%d")


def peak_bytes(path) -> int:
    tracemalloc.start()
    compute_metrics_csv(path, rows_per_block=20_000, walls=np.array([[0, 20, 40, 20.0]]), robot_goal=(1.0, 1.0))
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return peak


@pytest.mark.slow
def test_memory_is_flat_in_run_length(tmp_path):
    short, long = tmp_path / "short.csv", tmp_path / "long.csv"
    write_run(short, 600)
    write_run(long, 2400)
    short_peak, long_peak = peak_bytes(short), peak_bytes(long)
    # Four times the frames: the dense arrays would take four times the memory; streamed, only the
    # per-frame scalars (~100 bytes a frame) grow.
    assert long_peak < 1.3 * short_peak, (short_peak, long_peak)


def test_a_nan_row_is_named_by_its_line(tmp_path):
    path = tmp_path / "trajectories.csv"
    path.write_text("frame,t,id,x,y,vx,vy,yaw,group\n0,0,1,1,1,0,0,0,-1\n1,0.05,1,nan,1,0,0,0,-1\n")
    with pytest.raises(MetricsError, match="trajectories.csv:3: a value is missing or not a finite number"):
        compute_metrics_csv(path)
    with pytest.raises(MetricsError, match=":3: a value is missing"):
        Trajectories.from_csv(path)


def test_rows_out_of_frame_order_are_refused_when_streaming(tmp_path):
    path = tmp_path / "trajectories.csv"
    path.write_text("frame,t,id,x,y,vx,vy,yaw,group\n1,0.05,1,1,1,0,0,0,-1\n0,0,1,1,1,0,0,0,-1\n")
    with pytest.raises(MetricsError, match=":3: frame numbers go backwards"):
        compute_metrics_csv(path)
