"""Score the reading of every understanding set, and say which cases a change fixed or broke.

    python eval/understanding/score_all.py --out /tmp/u/base                 # every set, two at a time
    python eval/understanding/score_all.py --out /tmp/u/new --base /tmp/u/base
    python eval/understanding/score_all.py --summary /tmp/u/new              # the figures of a scored run
    python eval/understanding/score_all.py --out DIR --skip unseen_fresh70   # leave a held-out set unread

Each set is scored by `grove understanding SET --out DIR/<set>` in its own process, so a run is the
same command a researcher types. A case is right when its row in results.csv has no misses. With
--base, every case that went from wrong to right (FIXED) or from right to wrong (BROKEN) is listed,
and the last line is `fixed=N broken=M`: a reader change is merged only with broken=0.
"""

from __future__ import annotations

import argparse
import csv
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]


def case_sets(skip: list[str]) -> list[Path]:
    return [p for p in sorted(HERE.glob("*.yaml")) if p.stem not in skip]


def score_set(path: Path, out: Path) -> tuple[str, int]:
    env = dict(os.environ, HF_HUB_OFFLINE="1", PYTHONPATH=str(ROOT))
    target = out / path.stem
    done = subprocess.run([sys.executable, "-m", "grove_tui", "understanding", str(path), "--out", str(target)],
                          cwd=ROOT, env=env, capture_output=True, text=True)
    if done.returncode:
        sys.stderr.write(f"{path.name}: exit {done.returncode}\n{done.stderr[-2000:]}\n")
    return path.stem, done.returncode


def read_results(out: Path) -> dict[str, dict[str, str]]:
    """Case key (set/case id) -> its misses ('' when right) and prompt."""
    rows: dict[str, dict[str, str]] = {}
    for results in sorted(out.glob("*/results.csv")):
        with results.open(newline="") as handle:
            for row in csv.DictReader(handle):
                rows[f"{results.parent.name}/{row['case']}"] = {"misses": row["misses"], "prompt": row["prompt"]}
    return rows


def summary(out: Path) -> int:
    rows = read_results(out)
    per_set: dict[str, list[int]] = {}
    for key, row in rows.items():
        tally = per_set.setdefault(key.split("/")[0], [0, 0])
        tally[0] += not row["misses"]
        tally[1] += 1
    for name, (right, total) in sorted(per_set.items()):
        if right < total:
            print(f"{name}: {right}/{total}")
    wrong = sum(total - right for right, total in per_set.values())
    print(f"sets={len(per_set)} cases={len(rows)} wrong={wrong}")
    return wrong


def compare(base: Path, new: Path) -> tuple[int, int]:
    before, after = read_results(base), read_results(new)
    fixed = broken = 0
    for key in sorted(after):
        if key not in before:
            continue
        was, now = not before[key]["misses"], not after[key]["misses"]
        if was != now:
            fixed += now
            broken += was
            print(f"{'FIXED' if now else 'BROKEN'} {key}: {after[key]['prompt']}")
            if was:
                print(f"    {after[key]['misses'][:300]}")
    return fixed, broken


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, help="Directory for each set's results.")
    parser.add_argument("--base", type=Path, help="An earlier --out to compare with, case by case.")
    parser.add_argument("--summary", type=Path, help="Only print the figures of this scored directory.")
    parser.add_argument("--skip", action="append", default=[], help="A set (file stem) to leave unread.")
    parser.add_argument("--only", action="append", default=[], help="Score only this set (file stem).")
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    if args.summary:
        summary(args.summary)
        return 0
    if not args.out:
        parser.error("--out or --summary is required")
    sets = [p for p in case_sets(args.skip) if not args.only or p.stem in args.only]
    args.out.mkdir(parents=True, exist_ok=True)
    with ThreadPoolExecutor(args.jobs) as pool:
        failed = [name for name, code in pool.map(lambda p: score_set(p, args.out), sets) if code]
    summary(args.out)
    if failed:
        print(f"failed sets: {', '.join(failed)}")
    if args.base:
        fixed, broken = compare(args.base, args.out)
        print(f"fixed={fixed} broken={broken}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
