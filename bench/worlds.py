"""World loading and grid building benchmark (run by hand, not a test).

    PYTHONPATH=. python bench/worlds.py [--repeats 5]

For every shipped world: parsing and validating the YAML (`parse_world`) against PyYAML's own safe
load of the same text with its fastest loader (the floor any loader pays), and rasterising the occupancy grid at
0.1 m and 0.05 m (inflation 0.35 m) against the obvious shapely way: shrink the walkable area by the
inflation radius and test every cell centre with `shapely.contains_xy`. Best of --repeats runs,
wall clock, in this process. The last line holds the headline figures as key=value pairs.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np
import shapely
import yaml

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from grove_tui.navigation import grid as grid_module  # noqa: E402
from grove_tui.world import list_worlds, parse_world, resolve_world_path  # noqa: E402


FASTEST_SAFE_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)  # libyaml when PyYAML has it


def best_of(repeats: int, function, *args):
    times = []
    result = None
    for _ in range(repeats):
        started = time.perf_counter()
        result = function(*args)
        times.append(time.perf_counter() - started)
    return min(times), result


def shapely_grid(world, resolution: float, inflation: float) -> np.ndarray:
    free_space = world.walkable().buffer(-inflation)
    xmin, ymin, xmax, ymax = world.bounds()
    xs = np.arange(xmin + resolution / 2, xmax, resolution)
    ys = np.arange(ymin + resolution / 2, ymax, resolution)
    gx, gy = np.meshgrid(xs, ys)
    return ~shapely.contains_xy(free_space, gx, gy)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    headline = {}
    print(f"{'world':<12} {'load ms':>8} {'yaml ms':>8} {'ratio':>6}   {'res':>5} {'cells':>9} "
          f"{'grid ms':>8} {'shapely ms':>10} {'speedup':>7}")
    for name in list_worlds():
        text = resolve_world_path(name).read_text()
        parse_world(text, name)  # warm-up
        load, (world, problems) = best_of(args.repeats, parse_world, text, f"{name}.yaml")
        assert not problems, problems
        raw, _ = best_of(args.repeats, yaml.load, text, FASTEST_SAFE_LOADER)
        headline[f"{name}_load_ms"] = load * 1000
        for resolution in (0.1, 0.05):
            ours, grid = best_of(args.repeats, grid_module._rasterize, world, resolution, 0.35)
            naive, _ = best_of(max(1, args.repeats // 2), shapely_grid, world, resolution, 0.35)
            cells = grid.occupied.size
            print(f"{name:<12} {load * 1000:8.1f} {raw * 1000:8.1f} {load / raw:6.1f}   {resolution:5.2f} "
                  f"{cells:9d} {ours * 1000:8.1f} {naive * 1000:10.1f} {naive / ours:7.1f}")
            key = f"{name}_grid{int(round(resolution * 100)):02d}cm"
            headline[f"{key}_ms"] = ours * 1000
            headline[f"{key}_speedup_vs_shapely"] = naive / ours
    print()
    print(" ".join(f"{k}={v:.3g}" for k, v in headline.items() if math.isfinite(v)))


if __name__ == "__main__":
    main()
