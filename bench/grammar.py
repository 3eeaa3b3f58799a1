"""Grammar cost per decoded token: no grammar, llama-cpp-python's grammar-first chain, and sample-first.

llama-cpp-python puts the grammar sampler first in its chain, so every token checks the grammar
against the whole vocabulary (152k entries for Qwen3). Upstream llama.cpp (common/sampling.cpp,
`common_sampler_sample`) samples without the grammar first and asks the grammar only about the
chosen token, resampling with the grammar applied when it is rejected. This script times the three
on one model, the same prompt (a real synthesis request) and the draft grammar of that request:

- `free`: no grammar (what decoding alone costs);
- `grammar_first`: llama-cpp-python's chain (what GROVE runs today);
- `sample_first`: the upstream scheme, the worker's fallback when llguidance is missing (`worker.SampleFirst`);
- `mask_first`: llguidance's token mask, then the chain over the allowed tokens only (`worker.MaskFirst`,
  what the worker runs; bench/grammar_engines.py compares the mask engines without a model).

Per-token times exclude the prompt's evaluation. Run by hand (loads a model; the figures scale with
the machine's load, printed with them):

    python bench/grammar.py [--model PATH] [--tokens 96] [--threads N]

The last line holds the headline figures as key=value pairs.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

PROMPT = ("Ten patients queue at the pharmacy counter", "hospital", "queuing")


def synthesis_request():
    from grove_tui.generation.presets import load_preset
    from grove_tui.generation.retrieval import NodeRetriever
    from grove_tui.generation.rois import select_rois
    from grove_tui.generation.synthesis import prepare_request
    from grove_tui.language.reading import read_prompt
    from grove_tui.world import load_world

    prompt, world_name, preset_name = PROMPT
    world, preset, retriever = load_world(world_name), load_preset(preset_name), NodeRetriever()
    reading = read_prompt(prompt, world, seed=0)
    selection = select_rois(world, preset, reading)
    retrieved = retriever.retrieve(prompt, preset.retrieval_filter, k=preset.retrieval_k)
    return prepare_request(preset, selection, retrieved, reading, retriever.documents_for, world=world,
                           cards_for=retriever.cards_for, documents_named=retriever.documents_named)


_MASKS = None


def run(llm, tokens, grammar_text, sampling, mode: str, n_tokens: int, seed: int) -> tuple[float, int, int, str]:
    """(seconds per decoded token, tokens, rejections, text) for one mode, prompt evaluated beforehand."""
    from llama_cpp import LlamaGrammar, llama_vocab_is_eog

    keep = len(tokens) - 1
    if llm.n_tokens >= keep and llm._input_ids[:keep].tolist() == tokens[:keep]:
        llm._ctx.kv_cache_seq_rm(-1, keep, -1)  # the prompt is evaluated once for every mode
        llm.n_tokens = keep
    else:
        llm.reset()
        llm.eval(tokens[:keep])
    decoded: list[int] = []
    rejections = 0
    started = time.perf_counter()
    if mode in ("sample_first", "mask_first"):
        from grove_tui.llm.worker import SampleFirst, TokenMasks, make_sampler

        options = dict(top_k=sampling.top_k, top_p=sampling.top_p, min_p=sampling.min_p,
                       temperature=sampling.temperature, presence_penalty=sampling.presence_penalty, seed=seed)
        if mode == "mask_first":
            global _MASKS
            _MASKS = _MASKS or TokenMasks(llm)
            sampler = make_sampler(llm, grammar_text, _MASKS, **options)
        else:
            sampler = SampleFirst(llm, grammar_text, **options)
        llm.eval(tokens[-1:])
        for _ in range(n_tokens):
            token = sampler.sample()
            if llama_vocab_is_eog(llm._model.vocab, token):
                break
            decoded.append(token)
            llm.eval([token])
        rejections = sampler.rejections
        sampler.close()
    else:
        grammar = LlamaGrammar.from_string(grammar_text, verbose=False) if mode == "grammar_first" else None
        llm.set_seed(seed)
        for token in llm.generate(tokens, top_k=sampling.top_k, top_p=sampling.top_p, min_p=sampling.min_p,
                                  temp=sampling.temperature, presence_penalty=sampling.presence_penalty,
                                  repeat_penalty=1.0, grammar=grammar):
            if llama_vocab_is_eog(llm._model.vocab, token) or len(decoded) >= n_tokens:
                break
            decoded.append(token)
    seconds = time.perf_counter() - started
    text = llm.detokenize(decoded).decode("utf-8", errors="replace")
    return seconds / max(1, len(decoded)), len(decoded), rejections, text


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", default=None, help="GGUF (default: the bt role's model)")
    parser.add_argument("--tokens", type=int, default=96)
    parser.add_argument("--threads", type=int, default=None)
    parser.add_argument("--rounds", type=int, default=2, help="rounds of the three modes; the best is kept")
    args = parser.parse_args()

    from grove_tui.cpu import free_cores
    from grove_tui.llm.chat_template import default_sampling, render_chat
    from grove_tui.llm.gguf_info import read_gguf_info
    from grove_tui.llm.registry import resolve_models
    from grove_tui.llm.worker import tune_openmp_for_llama

    path = Path(args.model) if args.model else resolve_models(None, None)["bt"].path
    info = read_gguf_info(path)
    request = synthesis_request()
    grammar_text = request.grammar
    threads = args.threads or free_cores()
    tune_openmp_for_llama()
    from llama_cpp import Llama

    llm = Llama(model_path=str(path), n_ctx=2048, n_threads=threads, n_threads_batch=threads, n_batch=512,
                verbose=False, seed=0)
    bos, eos = llm.token_bos(), llm.token_eos()
    text = render_chat(llm.metadata.get("tokenizer.chat_template"), request.messages,
                       bos_token=llm._model.token_get_text(bos) if bos != -1 else "",
                       eos_token=llm._model.token_get_text(eos) if eos != -1 else "", architecture=info.architecture)
    tokens = llm.tokenize(text.encode(), add_bos=not text.startswith(llm._model.token_get_text(bos) if bos != -1 else "\0"),
                          special=True)
    sampling = default_sampling(info.architecture, info.size_bytes)
    load = os.getloadavg()[0]
    print(f"model {path.name}: vocabulary {llm.n_vocab()}, prompt {len(tokens)} tokens, {threads} threads, "
          f"load average {load:.2f}")
    figures: dict[str, float] = {}
    for mode in ("free", "grammar_first", "sample_first", "mask_first") * args.rounds:
        per_token, count, rejected, output = run(llm, tokens, grammar_text, sampling, mode, args.tokens, seed=3)
        figures[mode] = min(figures.get(mode, float("inf")), per_token)  # best of two: the machine is shared
        print(f"{mode:14s} {per_token * 1000:8.1f} ms/token  {count:4d} tokens  {rejected:3d} rejected  {output[:70]!r}")
    grammar_ms = (figures["grammar_first"] - figures["free"]) * 1000
    sample_first_ms = (figures["sample_first"] - figures["free"]) * 1000
    mask_first_ms = (figures["mask_first"] - figures["free"]) * 1000
    print(f"vocab={llm.n_vocab()} free_ms={figures['free'] * 1000:.1f} grammar_first_ms={figures['grammar_first'] * 1000:.1f} "
          f"sample_first_ms={figures['sample_first'] * 1000:.1f} grammar_cost_ms={grammar_ms:.1f} "
          f"sample_first_cost_ms={sample_first_ms:.1f} mask_first_ms={figures['mask_first'] * 1000:.1f} "
          f"mask_first_cost_ms={mask_first_ms:.1f} load={os.getloadavg()[0]:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
