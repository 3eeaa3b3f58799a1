"""LocalLLM: one GGUF model in its own worker process, grammar-constrained, cancellable, streaming.

    llm = LocalLLM(path, role="bt")
    result = llm.generate([{"role": "system", "content": ...}, {"role": "user", "content": ...}],
                          grammar=schema_to_gbnf(schema), max_tokens=400, on_token=print, cancel=event)

- The worker (models/worker.py) is a `spawn` process: a crash or hang in llama.cpp never takes the
  app down. A dead worker raises ModelError for that call; the next call starts a fresh one.
- Tokens stream back over a pipe; `on_token` runs in the caller's thread, never blocking the worker.
- `cancel` (a threading.Event) stops the generation at the next token; if the worker does not answer
  within CANCEL_GRACE_SECONDS (a long prompt prefill is not interruptible) it is terminated and
  restarted lazily. Either way generate raises Cancelled within about a second.
- `finish_reason == "length"` is never returned as a result: the output is cut off (a grammar only
  guarantees a valid prefix), so the call is retried with a larger budget and the next seed, and
  raises ModelError if that also runs out.
- One LocalLLM serves one role; calls are serialised (llama.cpp contexts are not thread-safe) and the
  loaded model keeps its KV cache between calls, so a shared system prompt is evaluated once. The
  KV state of a chat request's fixed prefix (everything before the last message's content) is also
  kept on disk under `cache_dir()/kv`, so a fresh worker restores it (worker.PrefixStore); the output
  is the same cold, warm or restored.
"""

from __future__ import annotations

import multiprocessing
import os
import sys
import threading
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from multiprocessing.connection import Connection
from multiprocessing.process import BaseProcess
from pathlib import Path
from typing import TYPE_CHECKING, Literal

from grove_tui.cpu import default_llm_threads
from grove_tui.settings import cache_dir, load_settings
from grove_tui.llm.chat_template import Sampling, default_sampling
from grove_tui.errors import Cancelled, ContextTooSmallError, ModelError
from grove_tui.llm.gguf_info import GGUFInfo, check_loadable, read_gguf_info

if TYPE_CHECKING:
    from grove_tui.llm.worker import ReadyInfo, Request, Result

CANCEL_GRACE_SECONDS = 0.5
LOAD_TIMEOUT_SECONDS = 300.0
_POLL_SECONDS = 0.02

Messages = Sequence[dict[str, str]]

__all__ = ["Generation", "Cancelled", "LocalLLM", "ModelError"]


def default_threads() -> int:
    """llama.cpp's threads: GROVE_LLM_THREADS, else cpu.default_llm_threads (the machine's budget, its
    idle cores now and whether a run plays in the app; cpu.py says why not the load average). The one
    thread policy: a LocalLLM made without `n_threads` asks it again for every request."""
    override = load_settings().llm_threads
    return override if override is not None else default_llm_threads()


@dataclass(frozen=True)
class Generation:
    text: str
    finish_reason: str  # "stop" (the model or the grammar ended it); never "length" or "cancelled"
    prompt_tokens: int
    completion_tokens: int  # all attempts, so accounting sees the real cost
    seconds: float
    first_token_seconds: float | None  # request sent -> first token of the accepted attempt
    attempts: int = 1
    cached_tokens: int = 0  # prompt tokens not evaluated by this request: live KV or the prefix restored from disk
    cache_source: str = "cold"  # where they came from: "live", "disk" or "cold" (none)
    grammar_engine: str = ""  # what kept the answer to its grammar: "llguidance" (token masks), "gbnf" or "" (none)
    forced_tokens: int = 0  # output tokens the grammar forced: evaluated in a batch, not sampled


def _start_resource_tracker() -> None:
    """Start multiprocessing's resource tracker on a valid stderr.

    The tracker hands `sys.stderr.fileno()` to its process. Under a TUI that captures output (Textual
    returns -1 there) every spawn then fails with "bad value(s) in fds_to_keep", so the tracker gets
    devnull instead: it must never write over the screen anyway.
    """
    from multiprocessing import resource_tracker

    try:
        usable = sys.stderr is not None and sys.stderr.fileno() >= 0
    except (AttributeError, OSError, ValueError):
        usable = False
    if usable:
        resource_tracker.ensure_running()
        return
    saved = sys.stderr
    with open(os.devnull, "w") as devnull:
        sys.stderr = devnull
        try:
            resource_tracker.ensure_running()
        finally:
            sys.stderr = saved


class LocalLLM:
    """A GGUF model for one role ("roi" or "bt"), served by a worker process started on first use."""

    def __init__(self, path: str | os.PathLike[str], role: str = "bt", n_ctx: int = 4096,
                 n_threads: int | None = None, sampling: Sampling | None = None) -> None:
        self.info: GGUFInfo = read_gguf_info(path)
        self.path: Path = self.info.path
        self.role = role
        if self.info.context_length and n_ctx > self.info.context_length:
            n_ctx = self.info.context_length
        self.n_ctx = n_ctx
        self.fixed_threads = n_threads  # None: follow the machine, request by request (threads_now)
        self.n_threads = n_threads or default_threads()  # the count the model is loaded with
        check_loadable(self.info, n_ctx)
        self.sampling = sampling or default_sampling(self.info.architecture, self.info.size_bytes)
        self.log_path = cache_dir() / "logs" / f"llm-{role}.log"
        self._context = multiprocessing.get_context("spawn")
        _start_resource_tracker()  # before the first Event/Lock: they register with the tracker
        self._cancel_flag = self._context.Event()
        self._process: BaseProcess | None = None
        self._conn: Connection | None = None
        self._ready_info: ReadyInfo | None = None
        self._lock = threading.Lock()

    # ---- lifecycle -------------------------------------------------------------------------------

    @property
    def running(self) -> bool:
        return self._process is not None and self._process.is_alive()

    @property
    def worker_pid(self) -> int | None:
        process = self._process
        return process.pid if process is not None and process.is_alive() else None

    @property
    def context_size(self) -> int:
        """The context llama.cpp actually allocated (it rounds small requests up); n_ctx until loaded."""
        return self._ready_info["n_ctx"] if self._ready_info is not None else self.n_ctx

    def start(self) -> None:
        """Start the worker and load the model now (otherwise the first generate does it)."""
        with self._lock:
            self._ensure_worker()

    def _ensure_worker(self) -> Connection:
        """The running worker's pipe, starting the worker (and loading the model) when there is none."""
        if self.running and self._conn is not None:
            return self._conn
        self._discard_worker()
        from grove_tui.llm import worker

        parent_conn, child_conn = self._context.Pipe(duplex=True)
        self._cancel_flag.clear()
        process = self._context.Process(
            target=worker.serve, name=f"grove-llm-{self.role}", daemon=True,
            args=(child_conn, self._cancel_flag, str(self.path), self.n_ctx, self.n_threads,
                  self.info.architecture, str(self.log_path), str(cache_dir() / "kv")))
        process.start()
        child_conn.close()
        self._process, self._conn = process, parent_conn
        deadline = time.monotonic() + LOAD_TIMEOUT_SECONDS
        while not parent_conn.poll(_POLL_SECONDS):
            if not process.is_alive():
                raise self._crashed("while loading the model")
            if time.monotonic() > deadline:
                self._discard_worker()
                raise ModelError(f"{self.path}: loading took longer than {LOAD_TIMEOUT_SECONDS:.0f} s")
        try:
            message = parent_conn.recv()
        except (EOFError, OSError):
            raise self._crashed("while loading the model") from None
        if message[0] == "error":
            self._discard_worker()
            raise ModelError(f"{self.path}: {message[2]}")
        self._ready_info = message[1]
        return parent_conn

    def _discard_worker(self) -> None:
        process, conn = self._process, self._conn
        self._process = self._conn = None
        if conn is not None:
            try:
                conn.send({"op": "stop"})
            except (OSError, ValueError, BrokenPipeError):
                pass
            conn.close()
        if process is not None:
            process.join(timeout=0.5)
            if process.is_alive():
                process.terminate()
                process.join(timeout=2)
            if process.is_alive():
                process.kill()
                process.join(timeout=2)

    def _crashed(self, when: str) -> ModelError:
        process = self._process
        code = None
        if process is not None:
            process.join(timeout=1)
            code = process.exitcode
        self._discard_worker()
        how = f"killed by signal {-code}" if code is not None and code < 0 else f"exit code {code}"
        return ModelError(f"the {self.role} model process ({self.path.name}) stopped unexpectedly {when} ({how}); "
                          f"it restarts on the next request. llama.cpp's log: {self.log_path}")

    def close(self) -> None:
        """Stop the worker. A generation running in another thread ends with ModelError."""
        if self._lock.acquire(timeout=CANCEL_GRACE_SECONDS):
            try:
                self._discard_worker()
            finally:
                self._lock.release()
            return
        # Busy: end the process so the generating thread sees the pipe close and returns promptly.
        process = self._process
        if process is not None and process.is_alive():
            process.terminate()

    def __enter__(self) -> LocalLLM:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __del__(self) -> None:
        try:
            self._discard_worker()
        except Exception:
            pass

    def threads_now(self) -> int:
        """llama.cpp's threads for the next request: the fixed count, else what the machine has idle now."""
        return self.fixed_threads or default_threads()

    # ---- requests --------------------------------------------------------------------------------

    @staticmethod
    def _request_body(op: Literal["generate", "count", "evaluate"], messages_or_prompt: Messages | str) -> Request:
        if isinstance(messages_or_prompt, str):
            return {"op": op, "prompt": messages_or_prompt, "messages": None}
        return {"op": op, "prompt": None, "messages": [dict(message) for message in messages_or_prompt]}

    def count_tokens(self, messages_or_prompt: Messages | str) -> int:
        """Tokens the rendered prompt takes (chat template applied), without generating."""
        with self._lock:
            self._ensure_worker().send(self._request_body("count", messages_or_prompt))
            result, _, _ = self._collect(None, None, None)
            return int(result["prompt_tokens"])

    def evaluate(self, messages_or_prompt: Messages | str, prefix_label: str = "") -> Result:
        """Evaluate the prompt exactly as `generate` would, without sampling.

        Returns {"prompt_tokens", "cached_tokens", "cache_source", "logits_sha256"}: the digest of the
        next-token logits, so callers can check that caches never change what the model sees.
        """
        with self._lock:
            self._ensure_worker().send({**self._request_body("evaluate", messages_or_prompt),
                                        "prefix_label": prefix_label, "n_threads": self.threads_now()})
            result, _, _ = self._collect(None, None, None)
            return result.copy()

    def render(self, messages: Messages) -> str:
        """The exact prompt text the chat template produces (Qwen3: ends with the empty think block)."""
        with self._lock:
            self._ensure_worker().send(self._request_body("count", messages))
            result, _, _ = self._collect(None, None, None)
            return str(result["prompt"])

    def generate(self, messages_or_prompt: Messages | str, grammar: str | None = None, *, max_tokens: int = 512,
                 temperature: float | None = None, top_p: float | None = None, top_k: int | None = None,
                 min_p: float | None = None, presence_penalty: float | None = None, seed: int = 0,
                 on_token: Callable[[str], None] | None = None, cancel: threading.Event | None = None,
                 timeout: float | None = None, length_retries: int = 1, prefix_label: str = "") -> Generation:
        """Generate a reply to chat `messages` (rendered with the model's template) or to a raw prompt string.

        `grammar` must come from models.grammar.schema_to_gbnf. Sampling values left None take the model's
        defaults (Qwen's non-thinking settings for Qwen3). A cut-off answer is retried `length_retries` times
        with twice the budget and the next seed. `prefix_label` names the fixed prefix's persisted KV file
        (what it is for, e.g. world, preset and template version; the tokens themselves are part of its key).
        Raises Cancelled or ModelError.
        """
        if max_tokens < 1:
            raise ModelError(f"max_tokens must be at least 1, got {max_tokens}")
        sampling = {
            "temperature": self.sampling.temperature if temperature is None else temperature,
            "top_p": self.sampling.top_p if top_p is None else top_p,
            "top_k": self.sampling.top_k if top_k is None else top_k,
            "min_p": self.sampling.min_p if min_p is None else min_p,
            "presence_penalty": self.sampling.presence_penalty if presence_penalty is None else presence_penalty,
        }
        body = self._request_body("generate", messages_or_prompt)
        started = time.monotonic()
        deadline = None if timeout is None else started + timeout
        spent_tokens = 0
        budget = max_tokens
        with self._lock:
            for attempt in range(1, length_retries + 2):
                conn = self._ensure_worker()
                self._cancel_flag.clear()
                sent = time.monotonic()
                conn.send({**body, "grammar": grammar, "max_tokens": budget,
                                 "seed": seed + attempt - 1, "prefix_label": prefix_label,
                                 "n_threads": self.threads_now(), **sampling})
                result, first_token_at, _ = self._collect(on_token, cancel, deadline)
                spent_tokens += int(result["completion_tokens"])
                if result["finish_reason"] == "cancelled":
                    raise Cancelled(f"{self.role} generation cancelled")
                if result["finish_reason"] == "stop":
                    return Generation(
                        text=result["text"], finish_reason="stop", prompt_tokens=int(result["prompt_tokens"]),
                        completion_tokens=spent_tokens, seconds=time.monotonic() - started,
                        first_token_seconds=None if first_token_at is None else first_token_at - sent,
                        attempts=attempt, cached_tokens=int(result.get("cached_tokens", 0)),
                        cache_source=str(result.get("cache_source", "cold")),
                        grammar_engine=str(result.get("grammar_engine", "")),
                        forced_tokens=int(result.get("forced_tokens", 0)))
                room = self.context_size - int(result["prompt_tokens"])
                budget = max(1, min(budget * 2, room))
        raise ModelError(f"the {self.role} model did not finish its answer within {budget} tokens "
                         f"({length_retries + 1} attempts); the output was cut off, so it was not used")

    def _collect(self, on_token: Callable[[str], None] | None, cancel: threading.Event | None,
                 deadline: float | None) -> tuple[Result, float | None, int]:
        """Relay worker events until the request is done; enforce cancel and timeout."""
        conn, process = self._conn, self._process
        assert conn is not None and process is not None  # the caller started the worker
        first_token_at: float | None = None
        prompt_tokens = 0
        stop_requested_at: float | None = None
        stop_reason = ""
        while True:
            if stop_requested_at is None:
                if cancel is not None and cancel.is_set():
                    stop_requested_at, stop_reason = time.monotonic(), "cancel"
                    self._cancel_flag.set()
                elif deadline is not None and time.monotonic() > deadline:
                    stop_requested_at, stop_reason = time.monotonic(), "timeout"
                    self._cancel_flag.set()
            elif time.monotonic() - stop_requested_at > CANCEL_GRACE_SECONDS:
                # The worker is stuck in a prefill or in llama.cpp: stop it the hard way.
                self._discard_worker()
                if stop_reason == "cancel":
                    raise Cancelled(f"{self.role} generation cancelled (model process stopped)")
                raise ModelError(f"the {self.role} model did not answer in time; the model process was stopped")
            try:
                if not conn.poll(_POLL_SECONDS):
                    if not process.is_alive():
                        raise self._crashed("during generation")
                    continue
                message = conn.recv()
            except (EOFError, OSError, BrokenPipeError):
                raise self._crashed("during generation") from None
            kind = message[0]
            if kind == "token":
                if first_token_at is None:
                    first_token_at = time.monotonic()
                if on_token is not None and stop_requested_at is None:
                    on_token(message[1])
            elif kind == "started":
                prompt_tokens = int(message[1])
            elif kind == "done":
                result: Result = message[1]
                if stop_reason == "timeout":
                    raise ModelError(f"the {self.role} model did not answer in time (generation stopped)")
                if stop_reason == "cancel":
                    result = {**result, "finish_reason": "cancelled"}
                return result, first_token_at, prompt_tokens
            elif kind == "error":
                if message[1] == "context":
                    raise ContextTooSmallError(f"context too small for the prompt: {message[2]} "
                                     f"({self.path.name}, role {self.role}); shorten the prompt or raise n_ctx")
                raise ModelError(f"the {self.role} model ({self.path.name}) failed: {message[2]}")
