"""Prompt-reading benchmark (run by hand, not a test): how long `read_prompt` takes for one prompt.

    PYTHONPATH=. python bench/reading.py [--repeats 5] [--world hospital]

Reads a set of compound prompts (two and three groups, every count form, robot reactions) with the
spaCy pipeline warm (loaded once, untimed except as `load_seconds`). As a baseline in the same run
it times the older reading the pipeline used before language/reading.py existed: the word-table
head counts (language/quantities.extract_quantities) plus the RoI matcher's place scan
(generation/rois.RoIMatcher.match), so a slower machine moves both. The target is <= 50 ms warm per
prompt (median); the last line holds the figures as key=value pairs, with the load average.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from grove_tui.generation.rois import RoIMatcher  # noqa: E402
from grove_tui.language import parser  # noqa: E402
from grove_tui.language.quantities import extract_quantities  # noqa: E402
from grove_tui.language.reading import read_prompt  # noqa: E402
from grove_tui.world import load_world  # noqa: E402

PROMPTS = [
    "Two families of three walk together to the cafeteria, while a few others stroll around the lobby.",
    "Ten patients line up at the reception desk to register and a nurse stares at the robot while others pass.",
    "Evacuate the pharmacy: twenty people leave by the main entrance and one of them follows the robot out of "
    "curiosity.",
    "Nobody is here except one guard who waits on the bench for five minutes.",
    "About 20 visitors walk quickly from the lobby to ward a, two doctors talk in the doctor's office and "
    "someone avoids the robot.",
    "Everyone in the cafeteria heads for the terrace door while three visitors block the robot in the corridor.",
    "Ten people in the cafeteria and five in the pharmacy walk to the main exit.",
    "A couple walks slowly past the pharmacy to the cafeteria for coffee.",
]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--world", default="hospital")
    args = ap.parse_args()
    world = load_world(args.world)

    t0 = time.perf_counter()
    parser.load()
    load_seconds = time.perf_counter() - t0
    read_prompt(PROMPTS[0], world)  # warm: the place index and first-call caches

    matcher = RoIMatcher(world)
    reading_ms: list[float] = []
    baseline_ms: list[float] = []
    for _ in range(args.repeats):
        for prompt in PROMPTS:
            t = time.perf_counter()
            read_prompt(prompt, world, seed=1)
            reading_ms.append((time.perf_counter() - t) * 1000)
            t = time.perf_counter()
            extract_quantities(prompt)
            matcher.match(prompt)
            baseline_ms.append((time.perf_counter() - t) * 1000)
    median = statistics.median(reading_ms)
    base = statistics.median(baseline_ms)
    worst = max(reading_ms)
    load = os.getloadavg()
    print(f"prompts={len(PROMPTS)} repeats={args.repeats} world={args.world}")
    print(f"spaCy load: {load_seconds:.2f} s (once per process)")
    print(f"read_prompt warm: median {median:.1f} ms, max {worst:.1f} ms (target <= 50 ms)")
    print(f"baseline (word tables + RoI scan): median {base:.1f} ms")
    print(f"load average: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    print(f"reading_ms={median:.2f} reading_max_ms={worst:.2f} baseline_ms={base:.2f} "
          f"ratio={median / base if base else float('inf'):.2f} load_seconds={load_seconds:.2f} "
          f"loadavg={load[0]:.2f} within_target={median <= 50.0}")


if __name__ == "__main__":
    main()
