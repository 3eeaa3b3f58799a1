"""Per-stage generation time, prompt to bundle, with the bt model warm.

Loads the models and the retriever once, warms them with one generation per preset (JIT, KV prefix,
embedding model), then times `runs` generations per preset over the token benchmark's prompts and
reports the mean seconds per stage (rois, retrieval, synthesis, postprocess, planning), the part of
synthesis spent evaluating the prompt before the first token (prefill), bundle writing, and the total. The machine's load average is printed because the figures scale with it.

    python bench/pipeline.py [--runs 3] [--bt-model PATH] [--presets emergency,normal,queuing]
    python bench/pipeline.py --edits [--bt-model PATH] [--presets ...]

`--edits` times follow-ups instead (issue 34): per preset, scenarios of three groups are generated
through `GroveSession.generate`, then edited through `GroveSession.refine` by follow-ups that touch
one group (one adds a group, one changes what a group does; the model writes the group, except
under the emergency preset, where an evacuating group's tree is the field's); each edit is timed
from the sentence to the written bundle, against the whole scenario's generation with the same model
in the same run. The target: an edit at most half the time of a generation.

The last line holds the headline figures as key=value pairs.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from tokens import PROMPTS  # noqa: E402  (the same prompts as the token table)

STAGES = ("rois", "retrieval", "synthesis", "postprocess", "planning")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3, help="timed generations per preset (after one warm-up)")
    parser.add_argument("--bt-model", default=None)
    parser.add_argument("--presets", default="emergency,normal,queuing")
    parser.add_argument("--edits", action="store_true", help="time follow-ups that touch one group (issue 34)")
    args = parser.parse_args()
    if args.edits:
        return edits(args)

    from grove_tui.scenario.bundle import write_bundle
    from grove_tui.generation.pipeline import GenerationPipeline
    from grove_tui.generation.presets import load_preset
    from grove_tui.generation.retrieval import NodeRetriever
    from grove_tui.world import load_world
    from grove_tui.llm.local import LocalLLM
    from grove_tui.llm.registry import resolve_models

    choice = resolve_models(None, args.bt_model)["bt"]
    t0 = time.perf_counter()
    llm = LocalLLM(choice.path, role="bt", n_ctx=choice.n_ctx)
    llm.start()
    retriever = NodeRetriever()
    retriever.ensure_index()
    load_seconds = time.perf_counter() - t0
    presets = [p.strip() for p in args.presets.split(",") if p.strip()]
    pipelines: dict[tuple[str, str], GenerationPipeline] = {}
    timings: dict[str, list[dict[str, float]]] = {p: [] for p in presets}
    failures = 0
    try:
        with tempfile.TemporaryDirectory(prefix="grove-bench-") as tmp:
            for preset_name in presets:
                preset = load_preset(preset_name)
                cases = PROMPTS[preset_name][: args.runs + 1]
                for index, (world_name, prompt) in enumerate(cases):
                    key = (world_name, preset_name)
                    if key not in pipelines:
                        pipelines[key] = GenerationPipeline(load_world(world_name), preset, None, llm, retriever)
                    started = time.perf_counter()
                    try:
                        result = pipelines[key].run(prompt, seed=index)
                    except Exception as exc:  # a benchmark reports failures and goes on
                        failures += 1
                        print(f"{preset_name:9s} failed: {prompt}: {exc}", file=sys.stderr)
                        continue
                    t_write = time.perf_counter()
                    write_bundle(result, Path(tmp) / f"{preset_name}-{index}")
                    write_seconds = time.perf_counter() - t_write
                    total = time.perf_counter() - started
                    row = {s: result.report["stages"][s]["seconds"] for s in STAGES}
                    row.update(bundle=write_seconds, total=total, prompt_tokens=result.report["prompt_tokens"],
                               completion_tokens=result.report["completion_tokens"],
                               prefill=result.report.get("first_token_seconds") or 0.0)
                    label = "warm-up" if index == 0 else f"run {index}"
                    print(f"{preset_name:9s} {label:7s} " + " ".join(f"{k}={v:.2f}" for k, v in row.items()
                                                                      if k not in ("prompt_tokens", "completion_tokens"))
                          + f" tokens={row['prompt_tokens']}+{row['completion_tokens']}  {prompt}", file=sys.stderr)
                    if index > 0:
                        timings[preset_name].append(row)
    finally:
        llm.close()

    load = os.getloadavg()
    print(f"Generation time per stage, seconds, mean over {args.runs} warm runs per preset "
          f"(model {Path(choice.path).name}, {os.cpu_count()} cores, load average {load[0]:.1f}; "
          f"models + index loaded in {load_seconds:.1f} s)")
    columns = [*STAGES, "prefill", "bundle", "total"]
    print(f"{'preset':10s} " + " ".join(f"{c:>11s}" for c in columns) + f" {'tokens':>11s}")
    headline = []
    for preset_name in presets:
        rows = timings[preset_name]
        if not rows:
            continue
        means = {c: statistics.mean(r[c] for r in rows) for c in columns}
        tokens = (statistics.mean(r["prompt_tokens"] for r in rows), statistics.mean(r["completion_tokens"] for r in rows))
        print(f"{preset_name:10s} " + " ".join(f"{means[c]:11.2f}" for c in columns) + f" {tokens[0]:6.0f}+{tokens[1]:<4.0f}")
        headline.append(f"{preset_name}_total_s={means['total']:.2f} {preset_name}_synthesis_s={means['synthesis']:.2f}")
    print(" ".join(headline + [f"load_average={load[0]:.2f}", f"failures={failures}"]))
    return 0 if failures == 0 else 1


# Scenarios of three groups, and two follow-ups each that touch one group and call the model.
EDIT_CASES: dict[str, list[tuple[str, str, tuple[str, str]]]] = {
    "queuing": [
        ("hospital", "ten patients queue at the pharmacy while four visitors queue at the food counter and two "
                     "nurses walk to ward a", ("add two guards standing at the main entrance",
                                               "the nurses wait in the staff room instead")),
        ("airport", "twelve travellers queue at check-in while six passengers queue at the cafe counter and a "
                    "family of four walks to gate a1", ("also three cleaners sweep the concourse",
                                                         "the family walks to gate b2 instead")),
        ("station", "ten travellers queue at the ticket office while five commuters queue at the newsagent till "
                    "and three tourists walk to platform 1", ("add two guards standing at the gateline",
                                                               "the tourists wait in the waiting room instead")),
    ],
    "normal": [
        ("office", "four colleagues chat in the kitchen while two managers walk to the boardroom and three "
                   "developers walk to the open plan office", ("add a cleaner mopping the main corridor",
                                                                "the managers wait in the reception instead")),
        ("hospital", "three visitors wait in the lobby while two nurses walk to ward a and a cleaner wanders in "
                     "the main corridor", ("plus two porters walking to the pharmacy",
                                           "the visitors walk to the cafeteria instead")),
        ("residential", "two children walk to the kitchen while a parent waits in the living room and two guests "
                        "chat on the balcony", ("add a cleaner vacuuming the hallway",
                                                "the parent walks to the master bedroom instead")),
    ],
    "emergency": [
        ("hospital", "twenty people evacuate from the cafeteria while ten patients evacuate from ward a and five "
                     "nurses evacuate from the nurse station", ("also eight visitors evacuate from the lobby",
                                                                "the nurses leave through the east emergency exit")),
        ("office", "twelve workers evacuate from the open plan office while six visitors evacuate from the "
                   "reception and four staff evacuate from the kitchen", ("add five managers evacuating from the "
                                                                          "boardroom",
                                                                          "the visitors leave through the main "
                                                                          "entrance")),
        ("station", "twenty passengers evacuate from platform 1 while ten commuters evacuate from the concourse "
                    "and five staff evacuate from the staff office", ("also six travellers evacuate from the cafe",
                                                                      "the staff leave through the south "
                                                                      "entrance")),
    ],
}


def edits(args: argparse.Namespace) -> int:
    """Follow-ups that touch one group against whole generations, same model, same run (module doc)."""
    from grove_tui.services.session import GroveSession, ScenarioRequest

    presets = [p.strip() for p in args.presets.split(",") if p.strip()]
    rows: list[tuple[str, str, float, float, float]] = []  # preset, world, generate, add, change
    failures = 0
    with GroveSession(bt_model=args.bt_model) as session, tempfile.TemporaryDirectory(prefix="grove-bench-") as tmp:
        # Warm every path once (models, embedder, reader, numba kernels, KV prefix) with the first case.
        for preset_name in presets:
            world_name, prompt, (add, change) = EDIT_CASES[preset_name][0]
            warm = session.generate(ScenarioRequest(world_name, preset_name, prompt, 99), Path(tmp) / f"warm-{preset_name}")
            session.refine(warm, add, Path(tmp) / f"warm-{preset_name}-add")
        for preset_name in presets:
            for index, (world_name, prompt, (add, change)) in enumerate(EDIT_CASES[preset_name]):
                out = Path(tmp) / f"{preset_name}-{index}"
                try:
                    started = time.perf_counter()
                    generated = session.generate(ScenarioRequest(world_name, preset_name, prompt, index), out / "0")
                    generate_s = time.perf_counter() - started
                    started = time.perf_counter()
                    added = session.refine(generated, add, out / "1")
                    add_s = time.perf_counter() - started
                    started = time.perf_counter()
                    session.refine(added, change, out / "2")
                    change_s = time.perf_counter() - started
                except Exception as exc:  # a benchmark reports failures and goes on
                    failures += 1
                    print(f"{preset_name:9s} failed: {prompt}: {exc}", file=sys.stderr)
                    continue
                rows.append((preset_name, world_name, generate_s, add_s, change_s))
                print(f"{preset_name:9s} {world_name:11s} generate={generate_s:.2f}s add={add_s:.2f}s "
                      f"change={change_s:.2f}s ({add!r}; {change!r})", file=sys.stderr)
    load = os.getloadavg()
    print(f"Follow-ups touching one group against whole generations, seconds (sentence to written bundle; "
          f"{os.cpu_count()} cores, load average {load[0]:.1f}, bt model {session.model_choices()['bt'].path.name})")
    print(f"{'preset':10s} {'generate':>9s} {'add':>7s} {'change':>7s} {'edit/gen':>9s}")
    headline = []
    for preset_name in presets:
        mine = [r for r in rows if r[0] == preset_name]
        if not mine:
            continue
        gen = statistics.mean(r[2] for r in mine)
        add_m = statistics.mean(r[3] for r in mine)
        change_m = statistics.mean(r[4] for r in mine)
        ratio = statistics.mean([r[3] / r[2] for r in mine] + [r[4] / r[2] for r in mine])
        print(f"{preset_name:10s} {gen:9.2f} {add_m:7.2f} {change_m:7.2f} {ratio:9.2f}")
        headline.append(f"{preset_name}_edit_ratio={ratio:.2f}")
    overall = statistics.mean([r[3] / r[2] for r in rows] + [r[4] / r[2] for r in rows]) if rows else float("nan")
    worst = max([r[3] / r[2] for r in rows] + [r[4] / r[2] for r in rows], default=float("nan"))
    print(" ".join(headline + [f"edit_ratio={overall:.2f}", f"worst_edit_ratio={worst:.2f}",
                               f"load_average={load[0]:.2f}", f"failures={failures}"]))
    return 0 if failures == 0 and overall <= 0.5 else 1


if __name__ == "__main__":
    sys.exit(main())
