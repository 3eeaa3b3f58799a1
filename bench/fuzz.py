"""Fuzz every parser of user files, `grove import hunav` and the Gym environment's config and actions for
minutes each (run by hand; tests/test_fuzz.py is the CI slice).

    PYTHONPATH=. python bench/fuzz.py [--minutes 10] [--only world_text,tree,hunav_import,gym_config]

The targets and strategies are tests/helpers/fuzzing.py's. Hypothesis generates the inputs in
batches with fresh seeds until each target's time is up; an exception other than GroveError (or, for
the Gym targets, gymnasium's own errors) is recorded (type, message, where it was raised, a shortened
input) and the run goes on, so one bug does not hide the others. Per target it prints the inputs run, the refusals (GroveErrors) and the
distinct failures; the last line holds the totals as key=value pairs.
"""

from __future__ import annotations

import argparse
import random
import sys
import time
import traceback
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from hypothesis import HealthCheck, given, seed, settings  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))  # `helpers.` as the suite imports it

from tests.helpers.fuzzing import TARGETS, expected_errors  # noqa: E402

BATCH = 500


def fuzz(name: str, seconds: float) -> tuple[int, int, dict[str, str]]:
    strategy, target = TARGETS[name]
    runs = refusals = 0
    failures: dict[str, str] = {}
    deadline = time.monotonic() + seconds
    expected = expected_errors()

    def one(value) -> None:
        nonlocal runs, refusals
        if time.monotonic() > deadline:
            return
        runs += 1
        try:
            target(value)
        except expected:
            refusals += 1
        except Exception as exc:  # noqa: BLE001 - recording every non-GroveError is the point
            frame = traceback.extract_tb(exc.__traceback__)[-1]
            key = f"{type(exc).__name__} at {Path(frame.filename).name}:{frame.lineno}"
            failures.setdefault(key, f"{str(exc)[:160]!r} on input {repr(value)[:200]}")

    while time.monotonic() < deadline:
        batch = settings(max_examples=BATCH, deadline=None, database=None,
                         suppress_health_check=list(HealthCheck))(given(strategy)(one))
        seed(random.getrandbits(64))(batch)()
    return runs, refusals, failures


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=10.0, help="time per target")
    parser.add_argument("--only", default="", help="comma-separated target names (default: all)")
    args = parser.parse_args()
    names = [n for n in args.only.split(",") if n] or sorted(TARGETS)
    unknown = sorted(set(names) - set(TARGETS))
    if unknown:
        parser.error(f"unknown targets {unknown}; known: {', '.join(sorted(TARGETS))}")
    total_runs = total_failures = 0
    print(f"{'target':<18} {'inputs':>9} {'refused':>9} {'failures':>9}")
    for name in names:
        runs, refusals, failures = fuzz(name, args.minutes * 60.0)
        total_runs += runs
        total_failures += len(failures)
        print(f"{name:<18} {runs:>9} {refusals:>9} {len(failures):>9}", flush=True)
        for key, example in failures.items():
            print(f"    {key}: {example}", flush=True)
    print(f"targets={len(names)} minutes_per_target={args.minutes:g} inputs={total_runs} "
          f"non_grove_exceptions={total_failures}")


if __name__ == "__main__":
    main()
