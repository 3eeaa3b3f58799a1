"""Retrieval benchmark (run by hand, not a test): first index build, model load, warm query latency.

    PYTHONPATH=. python bench/retrieval.py [--repeats 5] [--k 8]

Runs in a fresh temporary index directory so the first build is a real cold build (the model load
is timed apart: importing torch and reading the weights happen once per process). Warm latency is
the whole `NodeRetriever.retrieve` call (query embedding + Chroma query with the preset filter +
lexical fusion) over every prompt of node_db/eval.yaml, after one warm-up pass, with the query-embedding
cache cleared before each call; median and p95 over all calls. The machine's load average is printed
because on a shared machine it dominates the figures. Also reports Recall@k per preset. The last line holds the headline figures as
key=value pairs.
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

from grove_tui.generation import retrieval  # noqa: E402
from grove_tui.generation.retrieval import NodeRetriever, embedding_model, evaluate, load_eval_set  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5, help="timed passes over the labelled prompts")
    parser.add_argument("--k", type=int, default=8)
    args = parser.parse_args()

    started = time.perf_counter()
    embedding_model()
    model_seconds = time.perf_counter() - started

    cases = load_eval_set()
    with tempfile.TemporaryDirectory(prefix="grove-rag-bench-") as index_dir:
        retriever = NodeRetriever(index_dir=index_dir)
        state = retriever.ensure_index()
        reopen_started = time.perf_counter()
        reopened = NodeRetriever(index_dir=index_dir)
        reopened_state = reopened.ensure_index()
        reopen_seconds = time.perf_counter() - reopen_started
        assert state.built and not reopened_state.built

        for case in cases:  # warm-up: first query pays for lazy Chroma segment loading
            reopened.retrieve(case.prompt, case.preset, args.k)
        timings_ms, cpu_ms, process_cpu_ms = [], [], []
        for _ in range(args.repeats):
            for case in cases:
                retrieval._embed_query_cached.cache_clear()  # time the real query embedding, not the cache
                t0, c0, p0 = time.perf_counter(), time.thread_time(), time.process_time()
                reopened.retrieve(case.prompt, case.preset, args.k)
                cpu_ms.append((time.thread_time() - c0) * 1000.0)
                process_cpu_ms.append((time.process_time() - p0) * 1000.0)
                timings_ms.append((time.perf_counter() - t0) * 1000.0)
        result = evaluate(reopened, cases, args.k)

    timings_ms.sort()
    cpu_median = statistics.median(cpu_ms)
    process_cpu_median = statistics.median(process_cpu_ms)
    median = statistics.median(timings_ms)
    p95 = timings_ms[int(0.95 * (len(timings_ms) - 1))]
    print(f"load average: {' '.join(f'{x:.2f}' for x in os.getloadavg())} on {os.cpu_count()} cpus")
    print(f"model load (torch import + weights): {model_seconds:.2f} s")
    print(f"first index build: {state.seconds:.2f} s ({state.documents} documents, {state.vectors} vectors)")
    print(f"reopen up-to-date index: {reopen_seconds:.2f} s")
    print(f"warm retrieve(): median {median:.2f} ms, p95 {p95:.2f} ms, max {timings_ms[-1]:.2f} ms "
          f"over {len(timings_ms)} calls")
    # CPU time: what an uncontended core needs; the process figure adds Chroma's own worker threads.
    print(f"warm retrieve() CPU time: median {cpu_median:.2f} ms calling thread, {process_cpu_median:.2f} ms whole process")
    for preset in result.presets():
        print(f"recall@{args.k} {preset}: {result.recall(preset):.3f}")
    print(f"recall@{args.k} overall: {result.recall():.3f} ({len(cases)} prompts)")
    print(f"build_s={state.seconds:.2f} model_load_s={model_seconds:.2f} reopen_s={reopen_seconds:.2f} "
          f"warm_median_ms={median:.2f} warm_p95_ms={p95:.2f} warm_cpu_median_ms={cpu_median:.2f} warm_process_cpu_median_ms={process_cpu_median:.2f} recall_at_{args.k}={result.recall():.3f}")


if __name__ == "__main__":
    main()
