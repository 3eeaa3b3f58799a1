"""The public edit-chain set (eval/refine/chains.yaml), run and scored: each chain's first sentence is
generated, every follow-up applied with `GroveSession.refine`, and every step's bundle scored against
the groups written by hand (grove_tui/analysis/refine_chains.py), with the untouched groups checked
byte for byte against the bundle before.

    python bench/refine_chains.py [--chains ID,ID] [--out DIR] [--bt-model PATH] [--results eval/refine]

Prints one line per step, the failures, and writes RESULTS.md and results.csv into --results. The last
line holds the figures as key=value pairs, with the load average.
"""

from __future__ import annotations

import argparse
import csv
import os
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

ROOT = Path(__file__).resolve().parents[1]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--chains", default="", help="comma-separated chain ids (default: all)")
    parser.add_argument("--file", default=str(ROOT / "eval" / "refine" / "chains.yaml"))
    parser.add_argument("--out", default=None, help="where the bundles go (default: a temporary folder)")
    parser.add_argument("--results", default=str(ROOT / "eval" / "refine"), help="folder for RESULTS.md/results.csv")
    parser.add_argument("--bt-model", default=None)
    parser.add_argument("--score", default=None, metavar="DIR",
                        help="score the bundles an earlier run left in DIR (its --out) again, generating nothing")
    args = parser.parse_args()

    from grove_tui.analysis.refine_chains import StepResult, load_chains, read_bundle, score_step, summarize
    from grove_tui.errors import BundleError, GroveError
    from grove_tui.services.session import GroveSession, ScenarioRequest

    chains = load_chains(args.file)
    wanted = {c.strip() for c in args.chains.split(",") if c.strip()}
    if wanted:
        chains = [c for c in chains if c.id in wanted]
    if args.score:
        args.out = args.score
    out = Path(args.out) if args.out else Path(tempfile.mkdtemp(prefix="grove-chains-"))
    results: list[StepResult] = []
    started = time.perf_counter()
    with GroveSession(bt_model=args.bt_model) as session:
        for chain in chains:
            world = session.load_world(chain.world)
            max_vel = session.load_preset(chain.preset).max_vel
            previous = matched = generated = None
            for number, step in enumerate(chain.steps):
                target = out / chain.id / f"step{number}"
                t0 = time.perf_counter()
                try:
                    if args.score:
                        if not (target / "scenario.yaml").is_file():
                            raise BundleError(f"{target}: no bundle (the run stopped before this step)")
                    elif number == 0:
                        generated = session.generate(ScenarioRequest(chain.world, chain.preset, step.say, chain.seed),
                                                     target, overwrite=True)
                    else:
                        generated = session.refine(generated, step.say, target, overwrite=True)
                except GroveError as exc:
                    result = StepResult(chain.id, number, step.say, error=f"{type(exc).__name__}: {exc}")
                    result.seconds = time.perf_counter() - t0
                    results.append(result)
                    print(f"{chain.id:34s} {number} ERROR {step.say!r}: {exc}", flush=True)
                    break
                bundle = read_bundle(target, world, max_vel)
                result, found = score_step(chain, number, bundle, world, previous, matched)
                result.seconds = time.perf_counter() - t0
                results.append(result)
                mark = "ok " if result.ok else "BAD"
                same = f" untouched {result.identical}/{result.untouched}" if number else ""
                print(f"{chain.id:34s} {number} {mark} {result.seconds:5.1f}s{same} {step.say!r}", flush=True)
                for problem in result.problems + result.untouched_problems:
                    print(f"{'':38s}- {problem}", flush=True)
                previous, matched = bundle, found
    summary = summarize(results)
    load = os.getloadavg()[0]
    write_results(Path(args.results), results, summary, load, time.perf_counter() - started, bool(wanted))
    print(f"{summary.line()} seconds={time.perf_counter() - started:.0f} load={load:.2f} bundles={out}")
    return 0 if summary.passes else 1


def write_results(folder: Path, results, summary, load: float, seconds: float, partial: bool) -> None:
    if partial:
        return  # a few chains are a check, not the set's figures
    folder.mkdir(parents=True, exist_ok=True)
    with open(folder / "results.csv", "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["chain", "step", "sentence", "ok", "untouched", "identical", "seconds", "problems"])
        for r in results:
            writer.writerow([r.chain, r.step, r.say, int(r.ok), r.untouched, r.identical, f"{r.seconds:.2f}",
                             "; ".join(([r.error] if r.error else []) + r.problems + r.untouched_problems)])
    lines = ["# Edit chains: results", "",
             f"`python bench/refine_chains.py` on {time.strftime('%Y-%m-%d %H:%M')}, embedded model, "
             f"{seconds / 60:.0f} min, load average {load:.1f}.", "",
             f"- steps right: {summary.right}/{summary.steps} ({100 * summary.rate:.1f} %); follow-ups right: "
             f"{summary.follow_ups_right}/{summary.follow_ups}",
             f"- untouched groups byte-identical: {summary.identical}/{summary.untouched}; chains with every "
             f"untouched group identical: {summary.chains_all_identical}/{summary.chains}",
             f"- steps that failed with an error: {summary.errors}", "", "## Steps that are not right", ""]
    bad = [r for r in results if not r.ok or r.untouched_problems]
    lines += [f"- `{r.chain}` step {r.step} ({r.say}): " + "; ".join(([r.error] if r.error else []) + r.problems +
                                                                    r.untouched_problems) for r in bad] or ["(none)"]
    (folder / "RESULTS.md").write_text("\n".join(lines) + "\n", encoding="utf-8")


if __name__ == "__main__":
    raise SystemExit(main())
