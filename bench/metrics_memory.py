"""Peak memory of the metrics step against the run's length (run by hand, not a test).

    PYTHONPATH=. python bench/metrics_memory.py [--agents 500] [--seconds 120 480] [--in-memory]

For each length it writes a synthetic hospital trajectories.csv (agents walking at 20 fps with a
robot, positions as the simulator records them) and measures, in a fresh subprocess, the peak
resident memory (ru_maxrss) of `compute_metrics_csv` with the hospital's walls, which is what
`grove metrics` and `grove simulate` run. With --in-memory it also measures the old path (the whole
CSV in dense frames x people arrays) for comparison. Last line: key=value per length.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]

MEASURE = """
import resource, sys, time
sys.path.insert(0, {repo!r})
from grove_tui.analysis.metrics import Trajectories, compute_metrics, compute_metrics_csv
from grove_tui.world import load_world
walls = load_world("hospital").walls()
started = time.perf_counter()
if {in_memory}:
    report = compute_metrics(Trajectories.from_csv({csv!r}), walls=walls, robot_goal=(45.0, 5.0))
else:
    report = compute_metrics_csv({csv!r}, walls=walls, robot_goal=(45.0, 5.0))
print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024, time.perf_counter() - started,
      report.crowd["agents"])
"""


def write_run(path: Path, agents: int, seconds: float, fps: float = 20.0) -> int:
    """Agents on smooth random walks inside the hospital's bounds; the robot crosses the lobby."""
    rng = np.random.default_rng(0)
    frames = int(seconds * fps)
    position = rng.uniform((2, 2), (62, 42), (agents, 2))
    heading = rng.uniform(-np.pi, np.pi, agents)
    rows = 0
    with path.open("w") as out:
        out.write("frame,t,id,x,y,vx,vy,yaw,group\n")
        for start in range(0, frames, 200):
            block = []
            for f in range(start, min(frames, start + 200)):
                heading += rng.normal(0, 0.1, agents)
                velocity = np.column_stack([np.cos(heading), np.sin(heading)])
                position = np.clip(position + velocity / fps, (1, 1), (63, 43))
                robot = np.array([[f, f / fps, 0, 28 + 17 * f / frames, 4.0, 0.5, 0, 0, -1]])
                people = np.column_stack([np.full(agents, f), np.full(agents, f / fps), np.arange(1, agents + 1),
                                          position, velocity, heading, np.full(agents, -1)])
                block += [robot, people]
            table = np.concatenate(block)
            rows += table.shape[0]
            np.savetxt(out, table, fmt="%d,%.4f,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%d")
    return rows


def measure(csv: Path, in_memory: bool) -> tuple[int, float]:
    code = MEASURE.format(repo=str(REPO), csv=str(csv), in_memory=in_memory)
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    peak, seconds, _ = done.stdout.split()
    return int(peak), float(seconds)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--agents", type=int, default=500)
    parser.add_argument("--seconds", type=float, nargs="+", default=[120.0, 480.0])
    parser.add_argument("--in-memory", action="store_true", help="also measure the whole-CSV path")
    args = parser.parse_args()
    summary = []
    print(f"{'seconds':>8} {'rows':>11} {'csv MB':>7} {'streamed peak MB':>17} {'s':>7}"
          + (f" {'in-memory peak MB':>18} {'s':>7}" if args.in_memory else ""))
    with tempfile.TemporaryDirectory(prefix="grove-metrics-") as folder:
        for seconds in args.seconds:
            csv = Path(folder) / f"run_{seconds:g}.csv"
            rows = write_run(csv, args.agents, seconds)
            peak, took = measure(csv, in_memory=False)
            line = f"{seconds:>8g} {rows:>11,} {csv.stat().st_size / 2**20:>7.0f} {peak / 2**20:>17.0f} {took:>7.1f}"
            summary.append(f"streamed_peak_mb_{seconds:g}s={peak / 2**20:.0f}")
            if args.in_memory:
                whole_peak, whole_took = measure(csv, in_memory=True)
                line += f" {whole_peak / 2**20:>18.0f} {whole_took:>7.1f}"
                summary.append(f"in_memory_peak_mb_{seconds:g}s={whole_peak / 2**20:.0f}")
            print(line, flush=True)
            csv.unlink()
    print(f"agents={args.agents} " + " ".join(summary))


if __name__ == "__main__":
    main()
