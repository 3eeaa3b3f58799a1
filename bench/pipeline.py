"""Per-stage generation time, prompt to bundle, with the bt model warm.

Loads the models and the retriever once, warms them with one generation per preset (JIT, KV prefix,
embedding model), then times `runs` generations per preset over the token benchmark's prompts and
reports the mean seconds per stage (rois, retrieval, synthesis, postprocess, planning), the part of
synthesis spent evaluating the prompt before the first token (prefill), bundle writing, and the total. The machine's load average is printed because the figures scale with it.

    python bench/pipeline.py [--runs 3] [--bt-model PATH] [--presets emergency,normal,queuing]

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
    args = parser.parse_args()

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


if __name__ == "__main__":
    sys.exit(main())
