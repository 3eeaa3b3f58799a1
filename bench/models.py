"""Real model sizes at their real cost: Qwen3-shaped random-weight GGUFs against the embedded model, same run.

llama.cpp's cost per token depends on a model's shape (layers, widths, heads, vocabulary) and its
quantisation, not on its weight values, so a GGUF with Qwen3's exact shape and random weights times
what a user of Qwen3 sees. The files are built once (tests/helpers/tiny_qwen3.build_qwen3_shaped, a
real English BPE: the embedded SmolLM2's tokens and merges padded to Qwen3's 151,936) and cached
under GROVE_CACHE_DIR/bench-models. Quantisations, as users run them and gguf-py can write them:
0.6B Q8_0 (Qwen's own GGUF), 1.7B Q8_0, 4B Q4_0 (the tied output matrix Q8_0 where llama-quantize
would write Q6_K; gguf-py cannot write K-quants, so Q4_K_M is not offered).

Per model, thread count and preset, through the product's own path (GroveSession.generate, the bt
role; the roi role stays on its default, the embedded model):
- load: the model's worker process up and the weights in memory (GroveSession.load_models);
- first: the first scenario after the load (the embedder already warm in this process), warm: the
  next scenario, a different prompt of the same preset; stage by stage;
- prompt and output tokens of the warm synthesis, prefill tok/s (tokens not served from the live KV
  cache / time to first token), decode tok/s (output tokens after the first / the rest of the call);
- grammar ms/token: the warm synthesis prompt decoded again with and without its grammar (the
  prompt is then in the KV cache, so both are decode), the difference per token.
Scaling: --threads 1,2 (default 1 and this machine's llama.cpp budget) prints warm total and decode
speed per thread count. --first-scenario also runs the app's start with the default (embedded) model
in fresh processes: cold (nothing warmed), and GroveSession.warm_up then the first scenario, each
against a warm repeat of the same request (another prompt in between, so only the shared prefix is cached).

    python bench/models.py [--sizes 0.6b,1.7b,4b] [--threads 1,2] [--presets normal,queuing] [--first-scenario]

The last line holds the headline figures as key=value pairs.

Measured 2026-11-25 on 2 cores shared with seven other sessions, one thread, queuing (README "Model speed"):
  --first-scenario, load average 10.7:  model            load  first   warm  prompt+out  prefill  decode  grammar
                                        embedded         2.7s  94.2s  25.0s  1363+53     51 t/s  14.9    9.7 ms/t
                                        qwen3-0.6b-q8_0  3.9s 116.1s 185.1s  1356+250    13 t/s   2.4    110 ms/t
  first scenario (embedded): cold x1.63 of warm; after warm_up (40.9 s) x1.78 (the rest: the first prefill)
  --rates, load average 13.0:           embedded 24.0 t/s prefill, 7.15 t/s decode, grammar 46 ms/t
                                        qwen3-0.6b-q8_0 10.0 / 1.59 / 234;  qwen3-4b-q4_0 2.2 / 1.33 / 169
  --rates --threads 1,2, load average 10.7: decode 14.64 -> 0.55 t/s (embedded), 3.12 -> 0.40 (0.6b)
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))
sys.path.insert(0, str(ROOT / "bench"))
# --baseline runs each row in a child whose grove_tui is another checkout's (the code "before").
CODE = Path(os.environ.get("GROVE_BENCH_CODE") or ROOT)
sys.path.insert(0, str(CODE))

from tokens import PROMPTS  # noqa: E402  (the same prompts as the token table and bench/pipeline.py)

# tokens.py put this checkout first on the path: the code measured comes first again.
sys.path.remove(str(CODE))
sys.path.insert(0, str(CODE))

SIZES = ("0.6b", "1.7b", "4b")
DEFAULT_QUANT = {"0.6b": "Q8_0", "1.7b": "Q8_0", "4b": "Q4_0"}
STAGES = ("rois", "retrieval", "synthesis", "postprocess", "planning")
EMBEDDED = "embedded"


def model_path(size: str) -> Path:
    """The Qwen3-`size`-shaped GGUF, built on first use and cached."""
    from helpers.tiny_qwen3 import build_qwen3_shaped, shaped_file_name

    from grove_tui.llm.embedded import embedded_model_path
    from grove_tui.settings import cache_dir

    quant = DEFAULT_QUANT[size]
    path = cache_dir() / "bench-models" / shaped_file_name(size, quant)
    if not path.is_file():
        path.parent.mkdir(parents=True, exist_ok=True)
        started = time.perf_counter()
        print(f"building {path} (once) ...", file=sys.stderr, flush=True)
        build_qwen3_shaped(path, size, quant, embedded_model_path())
        print(f"  built in {time.perf_counter() - started:.0f} s, {path.stat().st_size / 1e9:.2f} GB", file=sys.stderr)
    return path


def recording_factory(threads: int | None, calls: list[dict[str, Any]]) -> Any:
    """The session's LocalLLMs, each recording its calls (messages, grammar, the Generation)."""
    from grove_tui.llm.local import LocalLLM

    class RecordingLLM(LocalLLM):
        def generate(self, messages_or_prompt: Any, grammar: str | None = None, **options: Any) -> Any:
            result = super().generate(messages_or_prompt, grammar, **options)
            calls.append({"role": self.role, "llm": self, "messages": messages_or_prompt, "grammar": grammar,
                          "generation": result})
            return result

    def make(role: str, choice: Any) -> Any:
        llm = RecordingLLM(choice.path, role=role, n_ctx=choice.n_ctx, n_threads=threads)
        llm.start()
        return llm

    return make


@dataclass
class Row:
    model: str
    threads: int  # 0: the product's default (the idle cores at each request, llm/local.py)
    preset: str
    code: str = "this"  # "before" for --baseline's checkout
    load: float = 0.0
    first: float = 0.0
    warm: float = 0.0
    stages: dict[str, float] = field(default_factory=dict)
    prompt_tokens: int = 0
    output_tokens: int = 0
    prefill_tps: float = float("nan")
    decode_tps: float = float("nan")
    grammar_ms: float = float("nan")
    uncached_tokens: int = 0  # warm synthesis prompt tokens not served from a live or disk cache
    load_average: str = ""  # at the start and the end of the row
    failures: int = 0


def synthesis_call(calls: list[dict[str, Any]], report: dict[str, Any]) -> dict[str, Any] | None:
    """The generate call that wrote the draft: the last one with the report's prompt token count."""
    for call in reversed(calls):
        if call["grammar"] and call["generation"].prompt_tokens == report["prompt_tokens"]:
            return call
    return None


GRAMMAR_PROBE_TOKENS = 24


def grammar_cost_ms(call: dict[str, Any]) -> float:
    """Milliseconds per token the grammar adds: the same prompt (in the KV cache, so both runs are
    decode) decoded for up to GRAMMAR_PROBE_TOKENS tokens with and without it, same seed, timed from
    the first streamed token to the last (a request's fixed costs, spread over a short constrained
    answer, would otherwise count as the grammar's)."""
    from grove_tui.errors import ModelError

    llm, messages = call["llm"], call["messages"]
    per_token = []
    for grammar in (call["grammar"], None):
        stamps: list[float] = []
        try:
            run = llm.generate(messages, grammar, max_tokens=GRAMMAR_PROBE_TOKENS, seed=11, length_retries=0,
                               on_token=lambda _piece: stamps.append(time.perf_counter()))
            tokens = run.completion_tokens
        except ModelError:  # ran to the budget (a cut-off answer is an error to the product, data here)
            tokens = GRAMMAR_PROBE_TOKENS
        # Forced tokens arrive in bursts with the sampled one: count tokens, not pieces.
        per_token.append((stamps[-1] - stamps[0]) / max(1, tokens - 1) if len(stamps) > 1 else float("nan"))
    return 1000 * (per_token[0] - per_token[1])


def measure(model: str, path: Path | None, threads: int, preset: str, out: Path) -> Row:
    """One row: load (models up, then the app's warm-up of the first prompt's world and preset), first, warm."""
    from grove_tui.services.session import GroveSession, ScenarioRequest

    row = Row(model, threads, preset, load_average=_load_text())
    calls: list[dict[str, Any]] = []
    session = GroveSession(bt_model=str(path) if path else None,
                           llm_factory=recording_factory(threads or None, calls))
    cases = PROMPTS[preset][:2]
    try:
        started = time.perf_counter()
        session.load_models()
        # As the app starts: the world and preset's fixed prompt prefix evaluated (or restored from disk).
        session.warm_up(cases[0][0], preset)
        row.load = time.perf_counter() - started
        for index, (world, prompt) in enumerate(cases):
            started = time.perf_counter()
            try:
                made = session.generate(ScenarioRequest(world, preset, prompt, seed=index), out / f"{model}-{threads}-{preset}-{index}")
            except Exception as exc:  # a benchmark reports a failure and goes on
                row.failures += 1
                print(f"  {model} t{threads} {preset}: failed: {prompt}: {exc}", file=sys.stderr)
                continue
            seconds = time.perf_counter() - started
            report = made.result.report
            print(f"  {model} t{threads} {preset} {'first' if index == 0 else 'warm '} {seconds:6.1f} s "
                  + " ".join(f"{s}={report['stages'][s]['seconds']:.1f}" for s in STAGES)
                  + f" tokens={report['prompt_tokens']}+{report['completion_tokens']}", file=sys.stderr, flush=True)
            if index == 0:
                row.first = seconds
                continue
            row.warm = seconds
            row.stages = {s: float(report["stages"][s]["seconds"]) for s in STAGES}
            row.prompt_tokens, row.output_tokens = int(report["prompt_tokens"]), int(report["completion_tokens"])
            call = synthesis_call(calls, report)
            if call is not None:
                generation = call["generation"]
                first_token = generation.first_token_seconds or float("nan")
                row.prefill_tps = (generation.prompt_tokens - generation.cached_tokens) / first_token
                # completion_tokens counts every attempt; time after the first token is the accepted attempt's.
                row.decode_tps = max(1, generation.completion_tokens // generation.attempts - 1) / max(1e-6, generation.seconds - first_token)
                row.uncached_tokens = generation.prompt_tokens - generation.cached_tokens
                row.grammar_ms = grammar_cost_ms(call)
    finally:
        session.close()
    row.load_average += " -> " + _load_text()
    return row


def _load_text() -> str:
    one, five, _ = os.getloadavg()
    return f"{one:.1f}/{five:.1f}"


def measure_in_child(code: Path, label: str, model: str, path: Path | None, threads: int, preset: str) -> Row:
    """measure() in a fresh process whose grove_tui is `code`'s (this checkout or --baseline's)."""
    import dataclasses

    command = [sys.executable, __file__, "--child-measure", model, "--threads", str(threads), "--presets", preset]
    if path is not None:
        command += ["--child-model-path", str(path)]
    env = {**os.environ, "GROVE_BENCH_CODE": str(code), "PYTHONPATH": str(code)}
    done = subprocess.run(command, capture_output=True, text=True, check=False, env=env)
    sys.stderr.write(done.stderr[-3000:])
    try:
        data = json.loads(done.stdout.strip().splitlines()[-1])
    except (IndexError, ValueError):
        return Row(model, threads, preset, code=label, failures=1)
    fields = {f.name for f in dataclasses.fields(Row)}
    return Row(**{k: v for k, v in data.items() if k in fields} | {"code": label})


RATE_TOKENS = 24


def token_rates(name: str, path: Path | None, threads: int) -> dict[str, float]:
    """--rates: load, prefill and decode rates and the grammar's cost on bench/llm.py's short draft
    request (about 300 prompt tokens, RATE_TOKENS output), without the pipeline around it: minutes
    for a 4B-shaped model on a loaded machine where a whole scenario takes most of an hour."""
    from llm import CASES, NODES, messages_for

    from grove_tui.errors import ModelError
    from grove_tui.generation.draft import draft_grammar
    from grove_tui.llm.embedded import embedded_model_path
    from grove_tui.llm.local import LocalLLM

    sentence, places = CASES[0][0], CASES[0][1]
    messages = messages_for(sentence, places)
    grammar = draft_grammar(NODES, places, max_groups=2, max_depth=2)
    started = time.perf_counter()
    llm = LocalLLM(path or embedded_model_path(), role=f"bench-{name}", n_ctx=2048, n_threads=threads)
    llm.start()
    figures: dict[str, float] = {"load_s": time.perf_counter() - started,
                                 "prompt_tokens": llm.count_tokens(messages)}
    try:
        decode = []
        for constraint in (grammar, None):  # the second run finds the prompt in the KV cache
            stamps: list[float] = []
            started = time.perf_counter()
            try:
                llm.generate(messages, constraint, max_tokens=RATE_TOKENS, seed=3, length_retries=0,
                             on_token=lambda _piece: stamps.append(time.perf_counter()))
            except ModelError:  # the budget ran out (a cut-off draft is an error to the product, data here)
                pass
            if constraint is not None and stamps:
                figures["prefill_tps"] = figures["prompt_tokens"] / (stamps[0] - started)
            decode.append((len(stamps) - 1) / (stamps[-1] - stamps[0]) if len(stamps) > 1 else float("nan"))
        figures["decode_tps"], figures["free_decode_tps"] = decode
        figures["grammar_ms"] = 1000 * (1 / decode[0] - 1 / decode[1])
    finally:
        llm.close()
    print(f"  rates {name} t{threads}: {figures}", file=sys.stderr, flush=True)
    return figures


def first_scenario(model: str, path: Path | None, threads: int, preset: str, warm_up: bool) -> dict[str, float]:
    """In this (fresh) process: optionally GroveSession.warm_up, then prompt A, prompt B, prompt A again."""
    from grove_tui.services.session import GroveSession, ScenarioRequest

    os.environ["GROVE_LLM_THREADS"] = str(threads)
    (world_a, prompt_a), (world_b, prompt_b) = PROMPTS[preset][:2]
    figures: dict[str, float] = {}
    with tempfile.TemporaryDirectory(prefix="grove-bench-first-") as tmp, \
            GroveSession(bt_model=str(path) if path else None) as session:
        if warm_up:
            started = time.perf_counter()
            session.warm_up(world_a, preset)
            figures["warm_up_s"] = time.perf_counter() - started
        # The same request twice (same output, same work), prompt B between them so that only the
        # prefix A and B share is still in the model's KV cache, as for any new prompt.
        for key, world, prompt, seed in (("first_s", world_a, prompt_a, 0), ("other_s", world_b, prompt_b, 0),
                                         ("warm_s", world_a, prompt_a, 0)):
            started = time.perf_counter()
            session.generate(ScenarioRequest(world, preset, prompt, seed=seed), Path(tmp) / key)
            figures[key] = time.perf_counter() - started
    return figures


def run_first_scenario_child(model: str, path: Path | None, threads: int, preset: str, warm_up: bool) -> dict[str, float]:
    command = [sys.executable, __file__, "--child-first-scenario", model, "--threads", str(threads), "--presets", preset]
    if path is not None:
        command += ["--child-model-path", str(path)]
    if warm_up:
        command.append("--child-warm-up")
    # As on a machine that never ran this world and preset: no persisted prefix KV (a cache dir of its
    # own), but the node index and unpacked models the user's cache already holds (not a scenario's cost).
    from grove_tui.settings import cache_dir

    with tempfile.TemporaryDirectory(prefix="grove-bench-cache-") as cache:
        for shared in ("chroma", "models"):
            if (cache_dir() / shared).exists():
                os.symlink(cache_dir() / shared, Path(cache) / shared)
        done = subprocess.run(command, capture_output=True, text=True, check=False,
                              env={**os.environ, "GROVE_CACHE_DIR": cache})
    if done.returncode != 0:
        print(done.stderr[-2000:], file=sys.stderr)
        return {}
    return json.loads(done.stdout.strip().splitlines()[-1])


def main() -> int:
    from grove_tui.cpu import core_budget

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default=",".join(SIZES), help="Qwen3 shapes, of " + ", ".join(SIZES))
    parser.add_argument("--threads", default="default",
                        help="llama.cpp thread counts, 'default' for the product's (the idle cores at each request)")
    parser.add_argument("--baseline", default=None, metavar="CHECKOUT",
                        help="also measure another checkout's code (e.g. a worktree of main), each row of both in a "
                             "fresh process, interleaved, so before and after share the minutes and the load")
    parser.add_argument("--presets", default="normal,queuing")
    parser.add_argument("--first-scenario", action="store_true",
                        help="also time the first scenario of a fresh process, cold and after GroveSession.warm_up")
    parser.add_argument("--rates", action="store_true",
                        help="only load, prefill, decode and grammar rates on a short request (no pipeline)")
    parser.add_argument("--child-first-scenario", default=None, help=argparse.SUPPRESS)
    parser.add_argument("--child-measure", default=None, help=argparse.SUPPRESS)
    parser.add_argument("--child-model-path", default=None, help=argparse.SUPPRESS)
    parser.add_argument("--child-warm-up", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    presets = [p.strip() for p in args.presets.split(",") if p.strip()]
    budget = core_budget().cores
    threads = sorted({0 if t.strip() == "default" else int(t) for t in args.threads.split(",") if t.strip()})

    if args.child_measure:
        import dataclasses

        path = Path(args.child_model_path) if args.child_model_path else None
        with tempfile.TemporaryDirectory(prefix="grove-bench-models-") as tmp:
            row = measure(args.child_measure, path, threads[0], presets[0], Path(tmp))
        print(json.dumps(dataclasses.asdict(row)))
        return 0

    if args.child_first_scenario:
        path = Path(args.child_model_path) if args.child_model_path else None
        print(json.dumps(first_scenario(args.child_first_scenario, path, max(1, threads[-1]), presets[0],
                                        args.child_warm_up)))
        return 0

    sizes = [s.strip() for s in args.sizes.split(",") if s.strip()]
    unknown = [s for s in sizes if s not in SIZES]
    if unknown:
        parser.error(f"unknown size(s) {unknown}; sizes: {', '.join(SIZES)}")
    models: list[tuple[str, Path | None]] = [(EMBEDDED, None)]
    models += [(f"qwen3-{size}-{DEFAULT_QUANT[size].lower()}", model_path(size)) for size in sizes]
    if args.rates:
        load = os.getloadavg()
        print(f"\nToken rates on a short draft request ({os.cpu_count()} cores, load average "
              f"{load[0]:.1f} {load[1]:.1f} {load[2]:.1f})")
        print("| model | threads | load s | prompt tok | prefill tok/s | decode tok/s (grammar) | grammar ms/tok |")
        print("|---|---|---|---|---|---|---|")
        headline = []
        for name, path in models:
            for count in threads:
                f = token_rates(name, path, count)
                print(f"| {name} | {count} | {f['load_s']:.1f} | {f.get('prompt_tokens', 0):.0f} | "
                      f"{f.get('prefill_tps', float('nan')):.1f} | {f.get('decode_tps', float('nan')):.2f} | {f['grammar_ms']:.0f} |")
                headline.append(f"{name}_t{count}_decode_tps={f.get('decode_tps', float('nan')):.2f}")
        print(" ".join(headline + [f"load_average={os.getloadavg()[0]:.2f}"]))
        return 0
    rows: list[Row] = []
    started_load = _load_text()
    codes = [("this", ROOT)] + ([("before", Path(args.baseline).resolve())] if args.baseline else [])
    turn = 0
    for name, path in models:
        for count in threads:
            for preset in presets:
                # Alternate which code goes first, so neither always runs on the cooler machine.
                for label, code in (codes if turn % 2 else codes[::-1]):
                    rows.append(measure_in_child(code, label, name, path, count, preset))
                    print(f"  row: {rows[-1]}", file=sys.stderr, flush=True)  # kept if the run is stopped early
                turn += 1
    first_runs: dict[tuple[str, bool], dict[str, float]] = {}
    if args.first_scenario:
        # The app's start with the default (embedded) model: a fresh process each, cold then warmed.
        for name, path in models[:1]:
            for warm_up in (False, True):
                first_runs[(name, warm_up)] = run_first_scenario_child(name, path, threads[-1], presets[0], warm_up)

    load = os.getloadavg()
    print(f"\nPrompt -> bundle through GroveSession, seconds ({os.cpu_count()} cores, llama.cpp budget {budget}, "
          f"load average {started_load} at the start, {load[0]:.1f} {load[1]:.1f} {load[2]:.1f} at the end)")
    print("| model (bt role) | code | threads | preset | load s | first | warm | prompt tok | uncached tok | output tok "
          "| prefill tok/s | decode tok/s | grammar ms/tok | warm stages: rois/retrieval/synthesis/post+plan "
          "| load average (1/5 min) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        stages = r.stages or {s: float("nan") for s in STAGES}
        print(f"| {r.model} | {r.code} | {r.threads or 'default'} | {r.preset} | {r.load:.1f} | {r.first:.1f} "
              f"| {r.warm:.1f} | {r.prompt_tokens} | {r.uncached_tokens} "
              f"| {r.output_tokens} | {r.prefill_tps:.0f} | {r.decode_tps:.1f} | {r.grammar_ms:.1f} | "
              f"{stages['rois']:.1f}/{stages['retrieval']:.1f}/{stages['synthesis']:.1f}/"
              f"{stages['postprocess'] + stages['planning']:.1f} | {r.load_average} |")
    headline = []
    for name, _ in models:
        for preset in presets:
            pair = {r.code: r for r in rows if r.model == name and r.preset == preset and r.warm}
            if len(pair) == 2:
                b, a = pair["before"], pair["this"]
                print(f"before -> after, {name} {preset}: first {b.first:.1f} -> {a.first:.1f} s, "
                      f"warm {b.warm:.1f} -> {a.warm:.1f} s (x{b.warm / a.warm:.2f}), "
                      f"uncached prompt {b.uncached_tokens} -> {a.uncached_tokens} tok, "
                      f"output {b.output_tokens} -> {a.output_tokens} tok")
                headline.append(f"{name}_{preset}_before_warm_s={b.warm:.1f}")
            by_threads = {r.threads: r for r in rows if r.model == name and r.preset == preset and r.warm
                          and r.code == "this"}
            if len(by_threads) > 1:
                low, high = min(by_threads), max(by_threads)
                print(f"scaling {name} {preset}: warm {by_threads[low].warm:.1f} s at {low} thread(s) -> "
                      f"{by_threads[high].warm:.1f} s at {high} (x{by_threads[low].warm / by_threads[high].warm:.2f}); "
                      f"decode {by_threads[low].decode_tps:.1f} -> {by_threads[high].decode_tps:.1f} tok/s")
            best = min((r.warm for r in by_threads.values()), default=float("nan"))
            headline.append(f"{name}_{preset}_warm_s={best:.1f}")
    for (name, warm_up), figures in first_runs.items():
        if not figures:
            continue
        label = "after warm_up" if warm_up else "cold (no warm-up)"
        ratio = figures["first_s"] / figures["warm_s"]
        print(f"first scenario, {name}, {label}: {figures['first_s']:.1f} s vs warm {figures['warm_s']:.1f} s "
              f"(x{ratio:.2f})" + (f"; warm_up took {figures['warm_up_s']:.1f} s" if warm_up else ""))
        headline.append(f"{name}_first_{'warmed' if warm_up else 'cold'}_ratio={ratio:.2f}")
    failures = sum(r.failures for r in rows)
    print(" ".join(headline + [f"load_average={load[0]:.2f}", f"failures={failures}"]))
    return 0 if failures == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
