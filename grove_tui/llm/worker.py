"""The process side of LocalLLM: llama.cpp runs here, never in the app's process.

A crash inside llama.cpp (a bad grammar, a broken file, out of memory) kills only this process, and a
generation can be stopped by terminating it. The model is loaded once and serves every request of
its role, so llama.cpp's live KV cache reuses a shared token prefix (the system prompt) from one
request to the next, in whole evaluation batches only (see `reusable_prefix`), so that an answer never
depends on which request the worker served before.

Protocol over one duplex pipe (parent -> worker: requests; worker -> parent: events):
    worker sends ("ready", {bos_token, eos_token, chat_template, architecture, n_ctx})
                 or ("error", "load", message) and exits
    parent sends {"op": "generate", ...} | {"op": "count", ...} | {"op": "stop"}
    worker sends ("started", prompt_tokens), then ("token", text)*, then ("done", {...})
                 or ("error", kind, message) with kind "context" | "request"
The parent's cancel request is a shared Event checked before every token.
"""

from __future__ import annotations

import codecs
import os
import sys
import time
from multiprocessing.connection import Connection
from multiprocessing.synchronize import Event
from pathlib import Path
from typing import Any


def _redirect_stderr(log_path: str) -> None:
    """llama.cpp writes to fd 2; in a terminal app that would paint over the screen, so it goes to a log."""
    Path(log_path).parent.mkdir(parents=True, exist_ok=True)
    log_fd = os.open(log_path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
    os.dup2(log_fd, 2)
    os.dup2(log_fd, 1)
    os.close(log_fd)
    sys.stderr = open(2, "w", buffering=1, closefd=False)  # noqa: SIM115 - lives as long as the process
    sys.stdout = open(1, "w", buffering=1, closefd=False)  # noqa: SIM115


def _log_tail(log_path: str, lines: int = 6) -> str:
    try:
        text = Path(log_path).read_text(encoding="utf-8", errors="replace")
    except OSError:
        return ""
    useful = [line for line in text.splitlines() if line.strip()]
    return "\n".join(useful[-lines:])


# The package asks OpenMP for passive waits (grove_tui/__init__.py): right for numba's SFM next to
# the UI, wrong here. llama.cpp meets its threads at dozens of barriers per token, and sleeping at
# each one doubled the time per token (SmolLM2 on 2 cores: 35 ms passive, 17.5 ms with a short
# spin, and 2 threads became slower than 1). A short spin, not an active wait: between requests
# the threads must go to sleep, not burn the cores the simulation needs.
LLAMA_SPIN_COUNT = "30000"


def tune_openmp_for_llama() -> None:
    """Set this process's OpenMP spin before llama.cpp loads libgomp (it reads the setting once)."""
    os.environ.setdefault("GOMP_SPINCOUNT", LLAMA_SPIN_COUNT)


def serve(conn: Connection, cancel: Event, model_path: str, n_ctx: int, n_threads: int, architecture: str,
          log_path: str) -> None:
    """Entry point of the worker process (multiprocessing spawn target)."""
    _redirect_stderr(log_path)
    tune_openmp_for_llama()
    try:
        from llama_cpp import Llama
    except Exception as error:  # an unusable llama-cpp-python install is reported, not raised into the void
        conn.send(("error", "load", f"llama-cpp-python cannot be imported: {error}"))
        return
    try:
        llm = Llama(model_path=model_path, n_ctx=n_ctx, n_threads=n_threads, n_threads_batch=n_threads,
                    n_batch=min(512, n_ctx), verbose=True, seed=0)
    except Exception as error:
        sys.stderr.flush()
        conn.send(("error", "load", f"llama.cpp could not load {model_path}: {error}\n{_log_tail(log_path)}"))
        return
    bos_id, eos_id = llm.token_bos(), llm.token_eos()
    info = {
        "bos_token": llm._model.token_get_text(bos_id) if bos_id != -1 else "",
        "eos_token": llm._model.token_get_text(eos_id) if eos_id != -1 else "",
        "chat_template": llm.metadata.get("tokenizer.chat_template"),
        "architecture": architecture,
        "n_ctx": llm.n_ctx(),
    }
    conn.send(("ready", info))
    server = _Server(llm, conn, cancel, info)
    while True:
        try:
            request = conn.recv()
        except (EOFError, OSError):
            return
        if request.get("op") == "stop":
            return
        try:
            server.handle(request)
        except _RequestError as error:
            conn.send(("error", error.kind, str(error)))
        except Exception as error:  # report, keep serving: the next request may be fine
            conn.send(("error", "request", f"{type(error).__name__}: {error}"))


MIN_ANSWER_TOKENS = 16


def reusable_prefix(cached: list[int], tokens: list[int], prompt_evaluated: int, n_batch: int) -> int:
    """How many leading tokens of `tokens` may be served from the live KV cache holding `cached`.

    llama.cpp's result for a token depends on how the prompt was cut into evaluation batches (the
    matrix kernels differ with the batch's size), so reusing "the longest shared prefix" made an answer
    depend on the request served before it: the same job gave different trees in a one-process batch
    and on a Ray worker. A cold evaluation cuts the prompt into batches of `n_batch` from position 0;
    reusing only whole batches of that cut, and only tokens that were evaluated as prompt
    (`prompt_evaluated`: the tokens after it were decoded one at a time), leaves every cached value
    exactly what a cold evaluation of `tokens` computes. At least the last token is always evaluated,
    since its logits give the first answer token.
    """
    shared = 0
    for cached_token, token in zip(cached, tokens):
        if cached_token != token:
            break
        shared += 1
    shared = min(shared, prompt_evaluated, len(tokens) - 1)
    return (shared // n_batch) * n_batch if n_batch > 0 else 0


class _RequestError(Exception):
    def __init__(self, kind: str, message: str) -> None:
        super().__init__(message)
        self.kind = kind


class _Server:
    def __init__(self, llm: Any, conn: Connection, cancel: Event, info: dict[str, Any]) -> None:
        self.llm, self.conn, self.cancel, self.info = llm, conn, cancel, info
        # How many leading tokens of the live KV cache were evaluated as a prompt (in whole batches
        # cut from position 0); 0 when the cache holds nothing a new request may reuse.
        self.prompt_evaluated = 0

    def prompt_text(self, request: dict[str, Any]) -> str:
        if request.get("messages") is not None:
            from grove_tui.llm.chat_template import render_chat

            return render_chat(self.info["chat_template"], request["messages"], bos_token=self.info["bos_token"],
                               eos_token=self.info["eos_token"], architecture=self.info["architecture"])
        return str(request["prompt"])

    def tokens(self, text: str) -> list[int]:
        bos = self.info["bos_token"]
        # Templates that write the BOS themselves must not get a second one from the tokenizer.
        add_bos = not (bos and text.startswith(bos))
        return self.llm.tokenize(text.encode("utf-8"), add_bos=add_bos, special=True)

    def handle(self, request: dict[str, Any]) -> None:
        from grove_tui.errors import ModelError

        try:
            text = self.prompt_text(request)
        except ModelError as error:
            raise _RequestError("request", str(error)) from None
        tokens = self.tokens(text)
        if request["op"] == "count":
            self.conn.send(("done", {"prompt": text, "prompt_tokens": len(tokens)}))
            return
        n_ctx = self.info["n_ctx"]
        room = n_ctx - len(tokens)
        if room < MIN_ANSWER_TOKENS:
            raise _RequestError("context", f"the prompt has {len(tokens)} tokens and the context holds {n_ctx}, "
                                           f"leaving {max(room, 0)} for the answer")
        # A budget beyond the context is clamped: if the answer really needs more it ends as "length".
        self.generate(tokens, {**request, "max_tokens": min(int(request["max_tokens"]), room)})

    def generate(self, tokens: list[int], request: dict[str, Any]) -> None:
        from llama_cpp import LlamaGrammar, llama_vocab_is_eog

        llm = self.llm
        grammar = LlamaGrammar.from_string(request["grammar"], verbose=False) if request.get("grammar") else None
        llm.set_seed(int(request["seed"]))
        reused = reusable_prefix(llm._input_ids.tolist(), tokens, self.prompt_evaluated, llm.n_batch)
        # generate() keeps the longest prefix shared with its first n_tokens cached tokens: cut the cache
        # there, so it evaluates the rest exactly as a cold start would (reset() when nothing is kept).
        if reused == 0:
            llm.reset()
        else:
            llm.n_tokens = reused
        # Until this prompt is evaluated in full, the cache holds nothing a later request may trust.
        self.prompt_evaluated = 0
        self.conn.send(("started", len(tokens)))
        decoder = codecs.getincrementaldecoder("utf-8")(errors="replace")
        pieces: list[str] = []
        completion_tokens = 0
        finish_reason = "length"
        started = time.monotonic()
        max_tokens = int(request["max_tokens"])
        if self.cancel.is_set():
            finish_reason = "cancelled"
        else:
            for token in llm.generate(tokens, top_k=int(request["top_k"]), top_p=float(request["top_p"]),
                                      min_p=float(request["min_p"]), temp=float(request["temperature"]),
                                      presence_penalty=float(request["presence_penalty"]), repeat_penalty=1.0,
                                      grammar=grammar):
                self.prompt_evaluated = len(tokens)  # a token was sampled: the whole prompt is evaluated
                if llama_vocab_is_eog(llm._model.vocab, token):
                    finish_reason = "stop"
                    break
                completion_tokens += 1
                piece = decoder.decode(llm.detokenize([token], special=False))
                if piece:
                    pieces.append(piece)
                    self.conn.send(("token", piece))
                if self.cancel.is_set():
                    finish_reason = "cancelled"
                    break
                if completion_tokens >= max_tokens:
                    break
        tail = decoder.decode(b"", final=True)
        if tail:
            pieces.append(tail)
            self.conn.send(("token", tail))
        self.conn.send(("done", {"text": "".join(pieces), "finish_reason": finish_reason,
                                 "prompt_tokens": len(tokens), "completion_tokens": completion_tokens,
                                 "cached_tokens": reused,
                                 "worker_seconds": time.monotonic() - started}))
