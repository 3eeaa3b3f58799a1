"""Speculative decoding with the embedded model as the draft: can it win? (issue 33, item 5)

Speculative decoding lets a small model propose the next k tokens and the big one check them in one
batch; it pays only where the big model would have chosen the same tokens. Two conditions:

1. The vocabularies must be the same token for token. The embedded SmolLM2-135M has 49,152 tokens;
   Qwen3 has 151,936 of its own BPE, so for the models users run it cannot apply at all. The
   Qwen3-shaped bench models (bench/models.py) carry SmolLM2's tokens padded to Qwen3's size, so
   there it can be measured.
2. The acceptance: the share of the target's tokens the draft model proposes. Tokens the grammar
   forces are not counted: the worker already evaluates them in one batch without sampling
   (worker.MaskFirst.forced), so speculation can only win on the tokens where the grammar leaves a choice.

For the bench's synthesis request (bench/grammar.py) this prints both, and the speed-up that
acceptance allows given the measured cost of a draft step, a target step and a verification batch
(speed-up = expected tokens per round / (k draft steps + one batch of k+1), in target steps).

    python bench/speculative.py [--target PATH] [--k 4]

The last line holds the headline figures as key=value pairs.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "bench"))
sys.path.insert(0, str(ROOT / "tests"))


def same_vocabulary(a, b, sample: int = 49152) -> bool:
    """Token i is the same text in both, for every token of the smaller vocabulary."""
    n = min(a.n_vocab(), b.n_vocab(), sample)
    return all(a._model.token_get_text(i) == b._model.token_get_text(i) for i in range(n))


def greedy_masked(llm, sampler_matcher, masks_mask, n_vocab) -> int:
    logits = np.ctypeslib.as_array(llm._ctx.get_logits_ith(-1), shape=(n_vocab,)).copy()
    sampler_matcher.unsafe_compute_mask_ptr(masks_mask.ctypes.data, masks_mask.nbytes)
    allowed = np.unpackbits(masks_mask.view(np.uint8), bitorder="little")[:n_vocab].astype(bool)
    logits[~allowed] = -np.inf
    return int(np.argmax(logits)), int(allowed.sum())


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--target", default=None, help="target GGUF (default: the 0.6B-shaped bench model)")
    parser.add_argument("--k", type=int, default=4)
    parser.add_argument("--tokens", type=int, default=40)
    args = parser.parse_args()

    import llguidance
    import llguidance.llamacpp
    from grammar import synthesis_request
    from llama_cpp import Llama
    from llguidance.gbnf_to_lark import gbnf_to_lark

    from grove_tui.llm.chat_template import render_chat
    from grove_tui.llm.embedded import embedded_model_path
    from grove_tui.llm.gguf_info import read_gguf_info

    if args.target:
        target_path = Path(args.target)
    else:
        from models import model_path

        target_path = model_path("0.6b")
    threads = 1
    load = os.getloadavg()
    models = {name: Llama(model_path=str(path), n_ctx=2048, n_threads=threads, n_threads_batch=threads, verbose=False)
              for name, path in (("draft", embedded_model_path()), ("target", target_path))}
    draft, target = models["draft"], models["target"]
    compatible = same_vocabulary(draft, target)
    print(f"draft {Path(embedded_model_path()).name} ({draft.n_vocab()} tokens), target {target_path.name} "
          f"({target.n_vocab()} tokens): same tokens for the draft's vocabulary: {compatible}; "
          f"load average {load[0]:.1f} {load[1]:.1f}")
    if not compatible:
        print("speculative decoding cannot apply: the vocabularies differ")
        print(f"compatible=False load_average={os.getloadavg()[0]:.2f}")
        return 0

    request = synthesis_request()
    tokens = {}
    for name, llm in models.items():
        info = read_gguf_info(embedded_model_path() if name == "draft" else target_path)
        bos, eos = llm.token_bos(), llm.token_eos()
        text = render_chat(llm.metadata.get("tokenizer.chat_template"), request.messages,
                           bos_token=llm._model.token_get_text(bos) if bos != -1 else "",
                           eos_token=llm._model.token_get_text(eos) if eos != -1 else "",
                           architecture=info.architecture)
        tokens[name] = llm.tokenize(text.encode(), add_bos=False, special=True)
        llm.eval(tokens[name])
    tokenizer = llguidance.llamacpp.lltokenizer_from_vocab(target._model.vocab)
    grammar = llguidance.LLMatcher.grammar_from_lark(gbnf_to_lark(request.grammar))
    matcher = llguidance.LLMatcher(tokenizer, grammar, log_level=0)
    mask = np.zeros((target.n_vocab() + 31) // 32, dtype=np.int32)
    draft_mask = np.zeros((target.n_vocab() + 31) // 32, dtype=np.int32)
    # The target's greedy answer under the grammar; at each free choice, the draft's greedy pick too.
    choices = agreed = 0
    target_step = draft_step = 0.0
    steps = 0
    while steps < args.tokens and not matcher.is_stopped():
        token, allowed = greedy_masked(target, matcher, mask, target.n_vocab())
        if allowed > 1:
            choices += 1
            mine, _ = greedy_masked(draft, matcher, draft_mask, draft.n_vocab()) if token < draft.n_vocab() else (-1, 0)
            agreed += int(mine == token)
        if token == target.token_eos():
            break
        matcher.consume_token(token)
        started = time.perf_counter()
        target.eval([token])
        target_step += time.perf_counter() - started
        started = time.perf_counter()
        draft.eval([token] if token < draft.n_vocab() else [draft.token_eos()])
        draft_step += time.perf_counter() - started
        steps += 1
    target_step /= max(1, steps)
    draft_step /= max(1, steps)
    # One verification batch of k+1 tokens on the target, timed on the prompt's last tokens.
    target._ctx.kv_cache_seq_rm(-1, len(tokens["target"]) - (args.k + 1), -1)
    target.n_tokens = len(tokens["target"]) - (args.k + 1)
    started = time.perf_counter()
    target.eval(tokens["target"][-(args.k + 1):])
    verify = time.perf_counter() - started
    p = agreed / max(1, choices)
    expected = sum(p ** i for i in range(args.k + 1))  # tokens per round: accepted drafts plus the target's own
    cost = (args.k * draft_step + verify) / target_step
    speedup = expected / cost
    print(f"free choices {choices} of {steps} tokens; the draft agreed on {agreed} ({100 * p:.0f} %)")
    print(f"target step {1000 * target_step:.0f} ms, draft step {1000 * draft_step:.0f} ms, verify batch of {args.k + 1} "
          f"{1000 * verify:.0f} ms: {expected:.2f} tokens per round for {cost:.2f} target steps, speed-up x{speedup:.2f}")
    print(f"compatible=True acceptance={p:.2f} speedup={speedup:.2f} k={args.k} load_average={os.getloadavg()[0]:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
