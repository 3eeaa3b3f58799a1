"""First request of a fresh model worker: cold, with the world+preset prefix restored from disk, and warm.

The bt model's system message is fixed per world and preset; the worker persists its KV state under
the cache dir and a fresh worker restores it instead of evaluating it (worker.PrefixStore). This
times the prompt evaluation of one real synthesis request (`LocalLLM.evaluate`, no sampling) in a
fresh worker without a persisted prefix, in a fresh worker with one, and again in the same worker
(live KV), and checks that all three see the same next-token logits. Run by hand:

    python bench/prefix_cache.py [--model PATH] [--threads N]

The last line holds the headline figures as key=value pairs.
"""

from __future__ import annotations

import argparse
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
sys.path.insert(0, str(Path(__file__).resolve().parent))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", default=None, help="GGUF (default: the bt role's model)")
    parser.add_argument("--threads", type=int, default=None)
    args = parser.parse_args()

    from grammar import synthesis_request  # the same request as bench/grammar.py

    from grove_tui.llm.local import LocalLLM
    from grove_tui.llm.registry import resolve_models

    path = Path(args.model) if args.model else resolve_models(None, None)["bt"].path
    request = synthesis_request()
    kv_home = Path(tempfile.mkdtemp(prefix="grove-kv-bench-"))
    os.environ["GROVE_CACHE_DIR"] = str(kv_home)  # a private kv/ folder: the first run is really cold
    rows = []
    try:
        for name in ("cold", "restored", "warm"):
            if name != "warm":
                llm = LocalLLM(path, role="bt", n_ctx=4096, n_threads=args.threads)
                llm.start()  # loading the model is not part of the figure
            started = time.perf_counter()
            result = llm.evaluate(request.messages, request.prefix_label)
            seconds = time.perf_counter() - started
            rows.append((name, seconds, result))
            print(f"{name:9s} {seconds:7.2f} s  prompt {result['prompt_tokens']} tokens, "
                  f"{result['cached_tokens']} from {result['cache_source']}", flush=True)
            if name == "cold":
                llm.close()
        llm.close()
    finally:
        shutil.rmtree(kv_home, ignore_errors=True)
    same = len({r[2]["logits_sha256"] for r in rows}) == 1
    cold, restored, warm = (r[1] for r in rows)
    print(f"model={path.name} prompt_tokens={rows[0][2]['prompt_tokens']} prefix_tokens={rows[1][2]['cached_tokens']} "
          f"cold_s={cold:.2f} restored_s={restored:.2f} warm_s={warm:.2f} restored_speedup={cold / restored:.2f} "
          f"same_logits={same} load={os.getloadavg()[0]:.2f}")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
