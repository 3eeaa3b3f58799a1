"""Token-mask engines against llama.cpp's GBNF sampler, on the draft grammar and a 151,936-token vocabulary.

What a constrained decode pays per token, without the model: the engine computes which tokens the
grammar allows next over the whole vocabulary and then takes the token the model "chose" (here: the
tokens of a valid draft, one by one, so every engine walks the same path). The vocabulary is the
bt model's (default: the Qwen3-0.6B-shaped bench model of bench/models.py, Qwen3's 151,936 tokens).

- `gbnf`: llama.cpp's grammar sampler applied to all candidates (llama-cpp-python's grammar-first
  chain, and what the worker's sample-first scheme falls back to whenever a token is refused);
- `llguidance`: the grammar converted to Lark (llguidance.gbnf_to_lark), an LLMatcher over the
  llama.cpp vocabulary (llguidance.llamacpp), the bitmask per token;
- `xgrammar`: GrammarCompiler over the same vocabulary (raw bytes), GrammarMatcher bitmask per token;
- `outlines_core`: the grammar, which is regular (bounded, recursion unrolled), inlined into one
  regex and compiled into an Index (a DFA over the vocabulary), allowed tokens per state.

Compile time (once per request: the grammar names that request's nodes and places) and mask time
per token are printed; xgrammar and outlines-core are optional here (not the product's
dependencies; install them into a side folder and put it on PYTHONPATH to include them).

    python bench/grammar_engines.py [--model PATH] [--rounds 3]

The last line holds the headline figures as key=value pairs.
"""

from __future__ import annotations

import argparse
import ctypes
import os
import re
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "bench"))
sys.path.insert(0, str(ROOT / "tests"))


def walk_text(request) -> str:
    """A valid draft of the request (the plain tree of every reading group), as the model would write it."""
    from grove_tui.generation.draft import parse_draft

    places = request.roi_names
    lines = []
    for _ in range(request.max_groups):
        lines.append(f"10 patients from {places[-1]}: Sequence(GoTo({places[0]}), Queue({places[0]}, spacing=0.6))")
    text = "\n".join(lines)
    parse_draft(text, request.node_names, request.roi_names, max_groups=request.max_groups, max_count=40)
    return text


def gbnf_to_regex(grammar: str) -> str:
    """Inline a non-recursive GBNF (draft.py's subset: literals, classes, groups, ?, |) into one regex."""
    rules: dict[str, str] = {}
    for line in grammar.splitlines():
        if "::=" in line:
            name, _, body = line.partition("::=")
            rules[name.strip()] = body.strip()
    token = re.compile(r'\s*(?:(?P<lit>"(?:\\.|[^"\\])*")|(?P<cls>\[(?:\\.|[^\]\\])*\])|(?P<name>[a-z0-9-]+)|(?P<op>[()|?*+]))')
    cache: dict[str, str] = {}

    def expand(name: str) -> str:
        if name not in cache:
            out, body, at = [], rules[name], 0
            while at < len(body):
                m = token.match(body, at)
                if m is None:
                    break
                at = m.end()
                if m.group("lit"):
                    out.append(re.escape(m.group("lit")[1:-1].encode().decode("unicode_escape")))
                elif m.group("cls"):
                    out.append(m.group("cls"))
                elif m.group("name"):
                    out.append(f"({expand(m.group('name'))})")
                else:
                    out.append(m.group("op"))
            cache[name] = "".join(out)
        return cache[name]

    return expand("root")


class Gbnf:
    def __init__(self, llm, grammar: str) -> None:
        import llama_cpp

        self.lc, self.llm = llama_cpp, llm
        self.sampler = llama_cpp.llama_sampler_init_grammar(llm._model.vocab, grammar.encode(), b"root")
        n = llm.n_vocab()
        self.cells = np.zeros(n, dtype=np.dtype([("id", np.intc), ("logit", np.single), ("p", np.single)], align=True))
        self.ids = np.arange(n, dtype=np.intc)

    def step(self, token: int) -> int:
        lc = self.lc
        self.cells["id"] = self.ids
        self.cells["logit"] = 0.0
        array = lc.llama_token_data_array(data=self.cells.ctypes.data_as(ctypes.POINTER(lc.llama_token_data)),
                                          size=len(self.cells), selected=-1, sorted=False)
        lc.llama_sampler_apply(self.sampler, ctypes.byref(array))
        allowed = int(np.isfinite(self.cells["logit"][:array.size]).sum())
        lc.llama_sampler_accept(self.sampler, token)
        return allowed


class LLGuidance:
    tokenizer = None

    def __init__(self, llm, grammar: str) -> None:
        import llguidance
        import llguidance.llamacpp
        from llguidance.gbnf_to_lark import gbnf_to_lark

        if LLGuidance.tokenizer is None:
            LLGuidance.tokenizer = llguidance.llamacpp.lltokenizer_from_vocab(llm._model.vocab)
        self.matcher = llguidance.LLMatcher(LLGuidance.tokenizer, llguidance.LLMatcher.grammar_from_lark(gbnf_to_lark(grammar)))
        assert not self.matcher.is_error(), self.matcher.get_error()
        self.mask = np.zeros((llm.n_vocab() + 31) // 32, dtype=np.int32)

    def step(self, token: int) -> int:
        self.matcher.unsafe_compute_mask_ptr(self.mask.ctypes.data, self.mask.nbytes)
        allowed = int(np.unpackbits(self.mask.view(np.uint8)).sum())
        assert self.matcher.consume_token(token), self.matcher.get_error()
        return allowed


class XGrammar:
    info = None

    def __init__(self, llm, grammar: str) -> None:
        import xgrammar as xgr

        if XGrammar.info is None:
            pieces = [llm._model.token_get_text(i).encode("utf-8", "replace") for i in range(0)]  # noqa: F841
            vocab = llm._model.vocab
            buffer = ctypes.create_string_buffer(256)
            import llama_cpp

            encoded = []
            for i in range(llm.n_vocab()):
                n = llama_cpp.llama_token_to_piece(vocab, i, buffer, 256, 0, True)
                encoded.append(bytes(buffer[:max(0, n)]))
            XGrammar.info = xgr.TokenizerInfo(encoded, vocab_type=xgr.VocabType.RAW,
                                              stop_token_ids=[llm.token_eos()])
        self.compiled = xgr.GrammarCompiler(XGrammar.info, cache_enabled=False).compile_grammar(grammar)
        self.matcher = xgr.GrammarMatcher(self.compiled)
        self.mask = xgr.allocate_token_bitmask(1, XGrammar.info.vocab_size)
        self.xgr = xgr

    def step(self, token: int) -> int:
        self.matcher.fill_next_token_bitmask(self.mask)
        allowed = int(np.unpackbits(self.mask.numpy().view(np.uint8)).sum())
        assert self.matcher.accept_token(token)
        return allowed


class OutlinesCore:
    vocabulary = None

    def __init__(self, llm, grammar: str) -> None:
        from outlines_core import Guide, Index, Vocabulary

        if OutlinesCore.vocabulary is None:
            import llama_cpp

            buffer = ctypes.create_string_buffer(256)
            eos = llm.token_eos()
            table: dict[bytes, list[int]] = {}
            for i in range(llm.n_vocab()):
                if i == eos:
                    continue
                n = llama_cpp.llama_token_to_piece(llm._model.vocab, i, buffer, 256, 0, False)
                piece = bytes(buffer[:max(0, n)])
                if piece:
                    table.setdefault(piece, []).append(i)
            OutlinesCore.vocabulary = Vocabulary(eos, table)
        self.guide = Guide(Index(gbnf_to_regex(grammar), OutlinesCore.vocabulary))

    def step(self, token: int) -> int:
        allowed = len(self.guide.get_tokens())
        self.guide.advance(token)
        return allowed


ENGINES = {"gbnf": Gbnf, "llguidance": LLGuidance, "xgrammar": XGrammar, "outlines_core": OutlinesCore}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", default=None, help="GGUF whose vocabulary is used (default: the 0.6B-shaped bench model)")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--engines", default=",".join(ENGINES))
    args = parser.parse_args()

    from grammar import synthesis_request
    from llama_cpp import Llama

    if args.model:
        path = Path(args.model)
    else:
        from models import model_path

        path = model_path("0.6b")
    llm = Llama(model_path=str(path), vocab_only=True, verbose=False)
    request = synthesis_request()
    text = walk_text(request)
    tokens = llm.tokenize(text.encode(), add_bos=False, special=False) + [llm.token_eos()]
    load = os.getloadavg()
    print(f"vocabulary {llm.n_vocab()} ({path.name}), grammar {len(request.grammar)} bytes, "
          f"walk of {len(tokens)} tokens, load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    figures = {}
    for name in [e.strip() for e in args.engines.split(",") if e.strip()]:
        try:
            compile_s, per_token = [], []
            for _ in range(args.rounds):
                started = time.perf_counter()
                engine = ENGINES[name](llm, request.grammar)
                compile_s.append(time.perf_counter() - started)
                started = time.perf_counter()
                allowed = [engine.step(t) for t in tokens[:-1]]
                per_token.append((time.perf_counter() - started) / (len(tokens) - 1))
        except ImportError as error:
            print(f"{name:14s} not installed ({error})")
            continue
        figures[name] = min(per_token) * 1000
        print(f"{name:14s} compile {min(compile_s) * 1000:8.1f} ms   mask {min(per_token) * 1000:8.3f} ms/token   "
              f"allowed per step: median {int(np.median(allowed))}, max {max(allowed)}")
    print(" ".join(f"{k}_ms_per_token={v:.3f}" for k, v in figures.items())
          + f" vocab={llm.n_vocab()} load_average={os.getloadavg()[0]:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
