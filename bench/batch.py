"""Batch throughput benchmark (run by hand, not a test): scenarios per hour, one process against Ray
with N workers on this machine, for the same jobs in the same run.

    PYTHONPATH=. python bench/batch.py [--variations 3] [--workers 2] [--simulate 0] [--ray-return]
                                       [--out /tmp/grove-bench-batch]

The jobs are the prompts below, each with --variations seeds, on the embedded model. Both runs go
through services.batch.run_batch, the code `grove batch` and `grove batch --ray` run; the Ray run
starts a private local Ray (its start-up and the workers' model loads are counted: they are part of
what a user waits for). The bundles of both runs are compared file by file (generation.json aside:
it holds stage timings). With --ray-return a third run has the Ray workers send every job's files back
to the driver, which writes them (what workers without a shared file system do). The 1-minute load average is printed before and after each run: on a shared
machine it says how much of the cores the runs really had. The last line holds the headline figures.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from grove_tui.services.batch import run_batch  # noqa: E402
from grove_tui.services.jobs import read_jobs  # noqa: E402
from grove_tui.services.session import GroveSession  # noqa: E402

PROMPTS = [
    ("hospital", "normal", "a few visitors walk to the cafeteria"),
    ("residential", "normal", "Two children walk to the kitchen"),
    ("hospital", "queuing", "Six patients queue at the pharmacy counter"),
    ("office", "normal", "some employees walk to the meeting room"),
]


def _files(bundle: Path) -> dict[str, bytes]:
    return {str(p.relative_to(bundle)): p.read_bytes() for p in sorted(bundle.rglob("*"))
            if p.is_file() and p.name != "generation.json"}


def _run(jobs_file: Path, out: Path, ray_address: str | None, workers: int | None,
         ray_return: bool = False) -> tuple[float, int, int]:
    jobs, problems = read_jobs(jobs_file)
    assert not problems, problems
    load_before = os.getloadavg()[0]
    started = time.perf_counter()
    with GroveSession() as session:
        result = run_batch(session, jobs, out, ray_address=ray_address, workers=workers, ray_return=ray_return)
    wall = time.perf_counter() - started
    print(f"  load average (1 min) before {load_before:.2f}, after {os.getloadavg()[0]:.2f}")
    return wall, len(result.records) - result.failures, result.failures


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--variations", type=int, default=3)
    parser.add_argument("--prompts", type=int, default=len(PROMPTS), help=f"how many of the {len(PROMPTS)} prompts")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--simulate", type=float, default=0.0, help="simulated seconds per scenario (0: none)")
    parser.add_argument("--ray-return", action="store_true",
                        help="also a Ray run whose workers send the files back to the driver")
    parser.add_argument("--out", type=Path, default=Path("/tmp/grove-bench-batch"))
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    jobs_file = args.out / "jobs.jsonl"
    lines = []
    prompts = PROMPTS[:max(1, args.prompts)]
    for index, (world, preset, prompt) in enumerate(prompts):
        job = {"world": world, "preset": preset, "prompt": prompt, "seed": index, "name": f"p{index}",
               "variations": args.variations}
        if args.simulate > 0:
            job["simulate"] = args.simulate
        lines.append(json.dumps(job))
    jobs_file.write_text("\n".join(lines) + "\n", encoding="utf-8")
    cpus = os.cpu_count() or 1
    print(f"{len(prompts) * args.variations} jobs, {cpus} cores, load average {os.getloadavg()}")

    figures = {}
    runs = [("single", None, None, False), ("ray", "local", args.workers, False)]
    if args.ray_return:
        runs.append(("ray_return", "local", args.workers, True))
    for label, address, workers, ray_return in runs:
        out = args.out / label
        if out.exists():
            import shutil

            shutil.rmtree(out)
        print(f"{label}:")
        wall, ok, failed = _run(jobs_file, out, address, workers, ray_return)
        per_hour = ok / wall * 3600
        figures[label] = per_hour
        print(f"  {ok} ok, {failed} failed in {wall:.1f} s -> {per_hour:.0f} scenarios/hour")

    names = sorted(p.name for p in (args.out / "single").iterdir() if (p / "scenario.yaml").is_file())
    others = [label for label, *_ in runs if label != "single"]
    same = all(_files(args.out / "single" / n) == _files(args.out / label / n) for n in names for label in others)
    print(f"bundles identical: {same} ({len(names)} compared, single against {', '.join(others)})")
    returned = (f" ray_return_per_hour={figures['ray_return']:.0f} "
                f"return_vs_shared={figures['ray_return'] / figures['ray']:.2f}") if args.ray_return else ""
    print(f"single_per_hour={figures['single']:.0f} ray_per_hour={figures['ray']:.0f} workers={args.workers} "
          f"speedup={figures['ray'] / figures['single']:.2f}{returned} cores={cpus} identical={same}")


if __name__ == "__main__":
    main()
