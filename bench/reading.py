"""Prompt-reading benchmark (run by hand, not a test): how long `read_prompt` takes.

    PYTHONPATH=. python bench/reading.py [--repeats 5] [--world hospital] [--fresh 3]

Three figures, each with the load average (the machines are shared):

- first reading in a fresh process: a new interpreter imports the reader, loads the world and
  reads one prompt (spaCy loaded on the way; its place vectors from the disk cache when a process
  made them before), timed from the interpreter's start; median of `--fresh` processes, wall and
  CPU seconds. Target <= 2 s.
- warm reading: the median over a set of compound prompts (two and three groups, every count form,
  robot clauses and reactions, places matched by meaning), spaCy loaded, in wall and in this thread's
  CPU milliseconds (the CPU figure is what a reading costs whatever the load). Target <= 20 ms.
- the peer measured in the same run: spaCy parsing the same prompts alone, the floor the reader's
  own passes add to (`ratio` = reading / parse).

The last line holds the figures as key=value pairs.

History (2 cores shared with other engineers): issue 29's reader in passes, with places by meaning
run in numpy: see docs/BENCHMARKS.md.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

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
    "A delivery robot drives from the pharmacy to ward B; two nurses step aside as it passes the nurse station.",
    "Three visitors eat in the dining hall while an orderly wheels a patient to radiology.",
]

_FRESH = """
import sys, time
started = float(sys.argv[1])
from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world
reading = read_prompt(sys.argv[2], load_world(sys.argv[3]))
assert reading.groups
print(time.time() - started, time.process_time(), 'torch' in sys.modules)
"""


def fresh_first_reading(prompt: str, world: str, n: int) -> tuple[float, float, bool]:
    """(median wall seconds, median CPU seconds, torch imported) of a first reading in new processes."""
    walls, cpus, torch = [], [], False
    for _ in range(n):
        out = subprocess.run([sys.executable, "-c", _FRESH, repr(time.time()), prompt, world], capture_output=True,
                             text=True, cwd=ROOT, env={**os.environ, "PYTHONPATH": str(ROOT)}, timeout=300)
        if out.returncode != 0:
            raise SystemExit(out.stderr)
        wall, cpu, imported = out.stdout.split()
        walls.append(float(wall))
        cpus.append(float(cpu))
        torch = torch or imported == "True"
    return statistics.median(walls), statistics.median(cpus), torch


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--world", default="hospital")
    ap.add_argument("--fresh", type=int, default=3, help="fresh processes for the first-reading figure")
    args = ap.parse_args()

    load_before = os.getloadavg()
    # A first run warms the disk cache of the world's place vectors, as any earlier process would.
    fresh_first_reading(PROMPTS[-1], args.world, 1)
    first_wall, first_cpu, torch = fresh_first_reading(PROMPTS[0], args.world, args.fresh)
    meaning_wall, meaning_cpu, _ = fresh_first_reading(PROMPTS[-1], args.world, args.fresh)

    from grove_tui.language import parser
    from grove_tui.language.reading import read_prompt
    from grove_tui.world import load_world

    world = load_world(args.world)
    for prompt in PROMPTS:
        read_prompt(prompt, world)  # warm: the place index, its vectors, first-call caches
    reading_ms: list[float] = []
    reading_cpu_ms: list[float] = []  # this thread's CPU time: what the reading costs, whatever the load
    parse_ms: list[float] = []
    # The parser keeps its last parses: forget them, so each reading and each peer parse starts from the text.
    clear_parses = getattr(parser, "clear_parses", lambda: None)
    for _ in range(args.repeats):
        for k, prompt in enumerate(PROMPTS):
            clear_parses()
            t, c = time.perf_counter(), time.thread_time()
            read_prompt(prompt, world, seed=k + 1)  # a new seed: the reading's own caches do not help
            reading_ms.append((time.perf_counter() - t) * 1000)
            reading_cpu_ms.append((time.thread_time() - c) * 1000)
            clear_parses()
            t = time.perf_counter()
            parser.parse(prompt)
            parse_ms.append((time.perf_counter() - t) * 1000)
    median, worst, floor = statistics.median(reading_ms), max(reading_ms), statistics.median(parse_ms)
    median_cpu = statistics.median(reading_cpu_ms)
    load = os.getloadavg()
    print(f"prompts={len(PROMPTS)} repeats={args.repeats} world={args.world} fresh processes={args.fresh}")
    print(f"first reading in a fresh process: {first_wall:.2f} s wall, {first_cpu:.2f} s CPU "
          f"(target <= 2 s; torch imported: {torch})")
    print(f"first reading that needs meaning in a fresh process: {meaning_wall:.2f} s wall, {meaning_cpu:.2f} s CPU")
    print(f"read_prompt warm: median {median:.1f} ms wall, {median_cpu:.1f} ms CPU, max {worst:.1f} ms wall "
          f"(target <= 20 ms)")
    print(f"peer: spaCy parse alone: median {floor:.1f} ms")
    print(f"load average: before {load_before[0]:.2f}, after {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    print(f"reading_ms={median:.2f} reading_cpu_ms={median_cpu:.2f} reading_max_ms={worst:.2f} parse_ms={floor:.2f} "
          f"ratio={median / floor if floor else float('inf'):.2f} first_s={first_wall:.2f} first_cpu_s={first_cpu:.2f} "
          f"meaning_first_s={meaning_wall:.2f} torch={torch} loadavg={load[0]:.2f} "
          f"within_target={median <= 20.0 and first_wall <= 2.0} "
          f"within_target_cpu={median_cpu <= 20.0 and first_cpu <= 2.0}")


if __name__ == "__main__":
    main()
