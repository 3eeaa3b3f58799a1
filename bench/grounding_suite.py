"""The grounding suite (eval/grounding/suite.yaml), end to end, with the embedded model (run by hand, not a test).

    PYTHONPATH=. python bench/grounding_suite.py [--suite eval/grounding/suite.yaml] [--out /tmp/grounding]
                                                 [--only ID ...] [--limit N] [--write-results] [--rescore]

Each case is generated through the services layer (the same path as `grove generate`), simulated for
its `seconds` (which writes grounding.json, the report checked on the run), and scored against the
outcomes written by hand in the suite (grove_tui/analysis/grounding_eval.py): a report ✓ whose hand
outcome fails is a false ✓ (the issue's bar: 0), a report ✗ whose hand outcome holds a false ✗ (at most
5 %), and the share of groups whose hand outcome holds (at least 95 %). With --write-results the
figures go to eval/grounding/RESULTS.md and results.json, with the load average.
Last line: key=value.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from grove_tui.analysis.grounding_eval import CaseScore, figures, load_suite, score_bundle  # noqa: E402
from grove_tui.errors import GroveError, describe_error  # noqa: E402
from grove_tui.services.session import GroveSession, ScenarioRequest  # noqa: E402


def run(suite: Path, out: Path, only: list[str], limit: int | None, rescore: bool = False) -> list[CaseScore]:
    cases = load_suite(suite)
    if only:
        cases = [c for c in cases if c.id in only]
    if limit:
        cases = cases[:limit]
    scores: list[CaseScore] = []
    if rescore:  # the bundles of an earlier run of this command, scored again (no generation, no run)
        for index, case in enumerate(cases, start=1):
            try:
                score = score_bundle(case, out / case.id)
            except (GroveError, OSError) as exc:
                score = CaseScore(case, error=str(exc))
            scores.append(score)
            print(line(index, len(cases), score), flush=True)
        return scores
    with GroveSession() as session:
        for index, case in enumerate(cases, start=1):
            started = time.perf_counter()
            bundle = out / case.id
            try:
                made = session.generate(ScenarioRequest(case.world, case.preset, case.prompt, case.seed), bundle,
                                        overwrite=True)
                session.simulate(made.bundle_dir, case.seconds)
                score = score_bundle(case, made.bundle_dir)
            except GroveError as exc:
                score = CaseScore(case, error=describe_error(exc).text)
            score.seconds = time.perf_counter() - started
            scores.append(score)
            print(line(index, len(cases), score), flush=True)
    return scores


def line(index: int, total: int, score: CaseScore) -> str:
    head = f"[{index}/{total}] {score.case.id} ({score.seconds:.1f} s)"
    if score.error:
        return f"{head} FAILED: {score.error}"
    parts = []
    for g in score.groups:
        flag = " FALSE ✓" if g.false_tick else " false ✗" if g.false_cross else ""
        parts.append(f"{g.who}: report {g.report}, outcome {'holds' if g.outcome else 'fails'}{flag}")
    if score.extra_ticks:
        parts.append(f"extra ✓ groups: {', '.join(score.extra_ticks)}")
    return head + "\n    " + "\n    ".join(parts)


def write_results(scores: list[CaseScore], load: tuple[float, float, float], wall: float) -> Path:
    folder = REPO / "eval" / "grounding"
    f = figures(scores)
    (folder / "results.json").write_text(json.dumps([s.to_dict() for s in scores], indent=1, ensure_ascii=False)
                                         + "\n", encoding="utf-8")
    rows = [
        "| world | cases | groups | outcome holds | report ✓ | false ✓ | report ✗ | false ✗ | not checked |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for world in sorted({s.case.world for s in scores}):
        w = figures([s for s in scores if s.case.world == world])
        rows.append(f"| {world} | {w.cases} | {w.groups} | {w.outcomes_held} ({w.held_share:.0%}) | {w.report_ticks} | "
                    f"{w.false_ticks} | {w.report_crosses} | {w.false_crosses} | {w.unchecked} |")
    rows.append(f"| **all** | {f.cases} | {f.groups} | {f.outcomes_held} ({f.held_share:.1%}) | {f.report_ticks} | "
                f"{f.false_ticks} ({f.false_tick_share:.1%}) | {f.report_crosses} | {f.false_crosses} "
                f"({f.false_cross_share:.1%}) | {f.unchecked} |")
    failing = [f"- `{s.case.id}`: " + ("generation failed: " + s.error if s.error else "; ".join(
        f"{g.who}: report {g.report}, " + " / ".join(g.evidence) for g in s.groups if not g.outcome))
        for s in scores if s.error or not all(g.outcome for g in s.groups)]
    text = (RESULTS_HEAD.format(wall=wall / 60, load=" / ".join(f"{x:.1f}" for x in load))
            + "\n".join(rows) + "\n\n## Groups whose outcome does not hold\n\n" + ("\n".join(failing) or "none")
            + "\n")
    path = folder / "RESULTS.md"
    path.write_text(text, encoding="utf-8")
    return path


RESULTS_HEAD = """# Grounding suite results

Made by `PYTHONPATH=. python bench/grounding_suite.py --write-results` (embedded SmolLM2-135M, the
default model; each case generated, simulated for its `seconds` and scored from its bundle; {wall:.0f} min on
2 cores, load average {load} at the end). Per case and group: `results.json`.

- **outcome holds**: the hand-written outcome (eval/grounding/suite.yaml) measured on the run holds.
- **false ✓**: the bundle's checked report says ✓ but the hand outcome fails (groups the report invents
  and marks ✓ count too). Bar: 0.
- **false ✗**: the report says ✗ but the hand outcome holds. Bar: at most 5 % of the ✗.
- **not checked**: the report could not tell in the run's time (or the scenario has no such group).

"""


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--suite", type=Path, default=REPO / "eval" / "grounding" / "suite.yaml")
    parser.add_argument("--out", type=Path, default=Path("/tmp/grounding-suite"))
    parser.add_argument("--only", nargs="*", default=[])
    parser.add_argument("--limit", type=int, default=None)
    parser.add_argument("--write-results", action="store_true")
    parser.add_argument("--rescore", action="store_true", help="score the bundles already in --out again")
    args = parser.parse_args()
    os.environ.setdefault("HF_HUB_OFFLINE", "1")
    args.out.mkdir(parents=True, exist_ok=True)
    started = time.perf_counter()
    scores = run(args.suite, args.out, args.only, args.limit, args.rescore)
    wall = time.perf_counter() - started
    load = os.getloadavg()
    f = figures(scores)
    print(f"\n{f.cases} cases ({f.failed_cases} failed), {f.groups} groups: outcome holds {f.held_share:.1%}; "
          f"report ✓ {f.report_ticks}, false ✓ {f.false_ticks}; report ✗ {f.report_crosses}, false ✗ "
          f"{f.false_crosses} ({f.false_cross_share:.1%}); not checked {f.unchecked}; {wall / 60:.1f} min, "
          f"load {load[0]:.1f}")
    if args.write_results:
        print(f"written {write_results(scores, load, wall)}")
    print(f"cases={f.cases} groups={f.groups} held={f.held_share:.3f} false_ticks={f.false_ticks} "
          f"false_crosses={f.false_crosses} false_cross_share={f.false_cross_share:.3f} unchecked={f.unchecked} "
          f"minutes={wall / 60:.1f} load={load[0]:.1f}")


if __name__ == "__main__":
    main()
