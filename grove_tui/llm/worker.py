"""The process side of LocalLLM: llama.cpp runs here, never in the app's process.

A crash inside llama.cpp (a bad grammar, a broken file, out of memory) kills only this process, and a
generation can be stopped by terminating it. The model is loaded once and serves every request of
its role, so its live KV cache keeps the shared system prompt from one request to the next (below).
Tokens are sampled grammar-last, as upstream llama.cpp does (SampleFirst).

Protocol over one duplex pipe (parent -> worker: requests; worker -> parent: events):
    worker sends ("ready", {bos_token, eos_token, chat_template, architecture, n_ctx})
                 or ("error", "load", message) and exits
    parent sends {"op": "generate", ...} | {"op": "count", ...} | {"op": "stop"}
    worker sends ("started", prompt_tokens), then ("token", text)*, then ("done", {...})
                 or ("error", kind, message) with kind "context" | "request"
The parent's cancel request is a shared Event checked before every token.

Prompt evaluation is split at fixed places so that output never depends on what the worker ran
before: llama.cpp's logits for a token depend on how the prompt was cut into batches. A chat
request's prompt is evaluated as two segments, the fixed prefix (everything before the last
message's content: the system message, the same for every sentence of a world and preset) and the
rest, each in batches of n_batch from its own start. The worker reuses live KV only up to such a
batch start, never tokens it decoded (one at a time), and persists the fixed prefix's KV to disk
(`kv_cache_dir`, keyed by model file, llama-cpp-python version, n_ctx, n_batch, the caller's label
and the prefix's tokens), so a fresh worker restores it instead of evaluating it again. The same
request gives the same tokens cold, warm or restored (tests/llm/test_kv_cache.py).
"""

from __future__ import annotations

import codecs
import faulthandler
import os
import sys
import time
import traceback
from multiprocessing.connection import Connection
from multiprocessing.synchronize import Event
from pathlib import Path
from typing import TYPE_CHECKING, Literal, Required, TypedDict, Unpack

if TYPE_CHECKING:
    import llguidance
    from llama_cpp import Llama, _internals


class Request(TypedDict, total=False):
    """What the parent sends: an operation, its prompt (text or chat messages), and for "generate" the
    grammar, budget and sampling values."""

    op: Required[Literal["generate", "count", "evaluate", "stop"]]
    prompt: str | None
    messages: list[dict[str, str]] | None
    prefix_label: str
    n_threads: int
    grammar: str | None
    max_tokens: int
    seed: int
    temperature: float
    top_p: float
    top_k: int
    min_p: float
    presence_penalty: float


class ReadyInfo(TypedDict):
    """The "ready" event's payload: what the parent needs of the loaded model."""

    bos_token: str
    eos_token: str
    chat_template: str | None
    architecture: str
    n_ctx: int


class Result(TypedDict, total=False):
    """The "done" event's payload. count: prompt, prompt_tokens. evaluate: prompt_tokens, cached_tokens,
    cache_source, logits_sha256. generate: text, finish_reason and the token counts and timings."""

    prompt: str
    prompt_tokens: int
    text: str
    finish_reason: str  # "stop" | "length" | "cancelled"
    completion_tokens: int
    cached_tokens: int
    cache_source: str  # "live" | "disk" | "cold"
    logits_sha256: str
    grammar_rejections: int
    forced_tokens: int
    grammar_engine: str
    worker_seconds: float


class SamplerOptions(TypedDict):
    """The sampler chain's values (SampleFirst's and MaskFirst's keyword arguments)."""

    top_k: int
    top_p: float
    min_p: float
    temperature: float
    presence_penalty: float
    seed: int


# A log past this size is moved to <log>.1 when a worker starts (one older log kept), so it never grows
# without bound; below it, each worker appends, so a crash's reason survives the restart that follows.
MAX_LOG_BYTES = 4 * 1024 * 1024


def _redirect_stderr(log_path: str, model_path: str = "") -> None:
    """llama.cpp writes to fd 2; in a terminal app that would paint over the screen, so it goes to a log.

    The log is appended to, one section per worker, each opened by a line naming the process and the
    model: a worker that died and the one started after it (the run "passed when repeated") both keep
    their lines. Python-level faults (a segfault or abort in llama.cpp) print their traceback there too.
    """
    path = Path(log_path)
    path.parent.mkdir(parents=True, exist_ok=True)
    try:
        if path.stat().st_size > MAX_LOG_BYTES:
            os.replace(path, path.with_name(path.name + ".1"))
    except OSError:
        pass
    log_fd = os.open(log_path, os.O_WRONLY | os.O_CREAT | os.O_APPEND, 0o644)
    os.dup2(log_fd, 2)
    os.dup2(log_fd, 1)
    os.close(log_fd)
    sys.stderr = open(2, "w", buffering=1, closefd=False)  # noqa: SIM115 - lives as long as the process
    sys.stdout = open(1, "w", buffering=1, closefd=False)  # noqa: SIM115
    stamp = time.strftime("%Y-%m-%d %H:%M:%S")
    print(f"--- model worker {os.getpid()} started {stamp} for {model_path or '?'} ---", file=sys.stderr, flush=True)
    faulthandler.enable(file=sys.stderr, all_threads=True)


def _log_crash(error: BaseException) -> None:
    """The reason a worker stops unexpectedly, in its log (the parent only sees an exit code)."""
    try:
        print(f"--- model worker {os.getpid()} stopped: {type(error).__name__}: {error} ---", file=sys.stderr)
        traceback.print_exception(error, file=sys.stderr)
        sys.stderr.flush()
    except Exception:  # noqa: BLE001 - the log itself may be the problem; the exit code still tells
        pass


def _log_tail(log_path: str, lines: int = 6) -> str:
    """The last lines this worker wrote (its section of the log, after its start line)."""
    try:
        text = Path(log_path).read_text(encoding="utf-8", errors="replace")
    except OSError:
        return ""
    mine = text.rsplit(f"--- model worker {os.getpid()} started", 1)[-1]
    useful = [line for line in mine.splitlines()[1:] if line.strip()]
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
          log_path: str, kv_cache_dir: str | None = None) -> None:
    """Entry point of the worker process (multiprocessing spawn target); any error that ends it is logged."""
    _redirect_stderr(log_path, model_path)
    try:
        _serve(conn, cancel, model_path, n_ctx, n_threads, architecture, log_path, kv_cache_dir)
    except BaseException as error:
        _log_crash(error)
        raise


def _serve(conn: Connection, cancel: Event, model_path: str, n_ctx: int, n_threads: int, architecture: str,
           log_path: str, kv_cache_dir: str | None) -> None:
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
    info: ReadyInfo = {
        "bos_token": llm._model.token_get_text(bos_id) if bos_id != -1 else "",
        "eos_token": llm._model.token_get_text(eos_id) if eos_id != -1 else "",
        "chat_template": llm.metadata.get("tokenizer.chat_template"),
        "architecture": architecture,
        "n_ctx": llm.n_ctx(),
    }
    conn.send(("ready", info))
    server = _Server(llm, conn, cancel, info, PrefixStore(kv_cache_dir, model_path, n_ctx, llm.n_batch)
                     if kv_cache_dir else None, masks=TokenMasks(llm))
    server.threads = n_threads
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


class _RequestError(Exception):
    def __init__(self, kind: str, message: str) -> None:
        super().__init__(message)
        self.kind = kind


class PrefixStore:
    """The fixed prefix's KV state (sequence 0) on disk: one file per model, settings, label and prefix."""

    MAGIC = b"GROVE-KV2\n"
    KEEP_FILES = 32  # the most recently used prefixes kept; a Qwen3-4B prefix of 320 tokens is ~46 MB
    MIN_TOKENS = 32  # shorter prefixes cost less to evaluate than to read back

    def __init__(self, folder: str, model_path: str, n_ctx: int, n_batch: int) -> None:
        import llama_cpp

        stat = os.stat(model_path)
        self.folder = Path(folder)
        # What the state depends on besides the tokens: the model's bytes (size and mtime stand in for
        # a hash of gigabytes), the library that wrote it, and the context layout. Not the thread count:
        # it changes per request (cpu.py), and llama.cpp's CPU results do not depend on it
        # (tests/llm/test_kv_cache.py checks the logits at one and two threads).
        self.identity = {"model": os.path.abspath(model_path), "size": stat.st_size, "mtime_ns": stat.st_mtime_ns,
                         "llama_cpp": llama_cpp.__version__, "n_ctx": n_ctx, "n_batch": n_batch}

    def path(self, label: str, tokens: list[int]) -> Path:
        import hashlib
        import json
        import re

        key = hashlib.sha256(json.dumps({**self.identity, "label": label, "tokens": tokens}).encode()).hexdigest()
        name = re.sub(r"[^A-Za-z0-9_.-]+", "-", label)[:80].strip("-") or "prefix"
        return self.folder / f"{name}-{key[:24]}.kv"

    def load(self, llm: Llama, label: str, tokens: list[int]) -> bool:
        """Restore the prefix into sequence 0 of an emptied context; False when no usable file exists."""
        import ctypes
        import json

        import llama_cpp

        path = self.path(label, tokens)
        try:
            data = path.read_bytes()
        except OSError:
            return False
        header_end = data.find(b"\n", len(self.MAGIC))
        if not data.startswith(self.MAGIC) or header_end < 0:
            return False
        try:
            header = json.loads(data[len(self.MAGIC):header_end])
        except ValueError:
            return False
        if header.get("tokens") != tokens or header.get("identity") != self.identity:
            return False
        state = data[header_end + 1:]
        buffer = (ctypes.c_uint8 * len(state)).from_buffer_copy(state)
        llm.reset()
        llm._ctx.kv_cache_clear()
        if llama_cpp.llama_state_seq_set_data(llm._ctx.ctx, buffer, len(state), 0) != len(state):
            llm._ctx.kv_cache_clear()
            return False
        llm.input_ids[:len(tokens)] = tokens
        llm.n_tokens = len(tokens)
        try:
            os.utime(path)  # recently used: kept when the folder is pruned
        except OSError:
            pass
        return True

    def save(self, llm: Llama, label: str, tokens: list[int]) -> None:
        import ctypes
        import json

        import llama_cpp

        from grove_tui.files import write_bytes_atomic

        if len(tokens) < self.MIN_TOKENS:
            return
        size = llama_cpp.llama_state_seq_get_size(llm._ctx.ctx, 0)
        buffer = (ctypes.c_uint8 * size)()
        written = llama_cpp.llama_state_seq_get_data(llm._ctx.ctx, buffer, size, 0)
        header = json.dumps({"identity": self.identity, "label": label, "tokens": tokens}).encode()
        path = self.path(label, tokens)
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            write_bytes_atomic(path, self.MAGIC + header + b"\n" + bytes(buffer)[:written])
        except OSError as error:  # a read-only or full cache costs speed, never the answer
            print(f"grove: could not write the prefix cache {path}: {error}", file=sys.stderr)
            return
        self.prune()

    def prune(self) -> None:
        """Keep the KEEP_FILES most recently used prefix files of this folder."""
        try:
            files = sorted(self.folder.glob("*.kv"), key=lambda f: f.stat().st_mtime_ns, reverse=True)
            for stale in files[self.KEEP_FILES:]:
                stale.unlink()
        except OSError:
            pass  # another worker pruned the same folder


def segment_starts(fixed: int, total: int, n_batch: int) -> list[int]:
    """Where a cold evaluation of `total` prompt tokens starts a batch: the prefix's batches, then the rest's."""
    starts = list(range(0, fixed, n_batch)) if fixed > 0 else []
    starts += list(range(fixed, total, n_batch))
    return starts


class _Server:
    def __init__(self, llm: Llama, conn: Connection, cancel: Event, info: ReadyInfo,
                 store: PrefixStore | None = None, masks: TokenMasks | None = None) -> None:
        self.llm, self.conn, self.cancel, self.info, self.store = llm, conn, cancel, info, store
        self.masks = masks
        self.threads = 0  # llama.cpp's threads now (0: as loaded); a request may ask for others
        self.live_prompt = 0  # leading live KV tokens that came from prompt evaluation (not decoding)
        self.live_bounds: list[int] = []  # where that evaluation's batches started, and its end

    def prompt_text(self, request: Request) -> str:
        messages = request.get("messages")
        if messages is not None:
            from grove_tui.llm.chat_template import render_chat

            return render_chat(self.info["chat_template"], messages, bos_token=self.info["bos_token"],
                               eos_token=self.info["eos_token"], architecture=self.info["architecture"])
        return str(request["prompt"])

    def tokens(self, text: str) -> list[int]:
        bos = self.info["bos_token"]
        # Templates that write the BOS themselves must not get a second one from the tokenizer.
        add_bos = not (bos and text.startswith(bos))
        return self.llm.tokenize(text.encode("utf-8"), add_bos=add_bos, special=True)

    def fixed_length(self, request: Request, tokens: list[int]) -> int:
        """Tokens before the last message's content: shared by every request with the same earlier messages."""
        messages = request.get("messages")
        if not messages or len(messages) < 2:
            return 0
        empty = self.tokens(self.prompt_text({**request, "messages": [*messages[:-1], {**messages[-1], "content": ""}]}))
        fixed = 0
        for a, b in zip(empty, tokens):
            if a != b:
                break
            fixed += 1
        # Stop short of the empty message's own closing tokens, which the real prompt does not share
        # when its content starts differently; and leave at least one token to evaluate.
        return min(fixed, len(tokens) - 1)

    def prepare(self, tokens: list[int], fixed: int, label: str) -> tuple[int, str]:
        """Bring the KV cache to a batch start of this prompt's cold evaluation; evaluate the prefix.

        Returns (prompt tokens not evaluated by this request, where they came from: live, disk, cold).
        """
        llm = self.llm
        shared = 0
        for cached_token, token in zip(llm._input_ids[:self.live_prompt].tolist(), tokens):
            if cached_token != token:
                break
            shared += 1
        self.live_prompt = 0  # until this prompt is evaluated, a cancel or error leaves the live state unknown
        limit = min(shared, len(tokens) - 1)
        starts = segment_starts(fixed, len(tokens), llm.n_batch)
        # A live token is reused only if the batches that computed it are the ones a cold evaluation of
        # this prompt would use: a batch of the earlier prompt ended there, and every start below agrees.
        usable = [b for b in starts if b <= limit and b in self.live_bounds
                  and [x for x in self.live_bounds if x < b] == [x for x in starts if x < b]]
        start = max(usable, default=0)
        self.live_bounds = starts + [len(tokens)]
        source = "live" if start > 0 else "cold"
        if (start < fixed and self.store is not None and fixed >= self.store.MIN_TOKENS
                and self.store.load(llm, label, tokens[:fixed])):
            start, source = fixed, "disk"
        elif start == 0 or llm.n_tokens < start:  # nothing to keep, or a failed restore emptied the context
            start, source = 0, "cold"
            llm.reset()
        else:
            llm._ctx.kv_cache_seq_rm(-1, start, -1)
            llm.n_tokens = start
        reused = start
        if start < fixed:
            llm.eval(tokens[start:fixed])  # batches from a batch start, as a cold evaluation has them
            if self.store is not None:
                self.store.save(llm, label, tokens[:fixed])
        return reused, source

    def handle(self, request: Request) -> None:
        from grove_tui.errors import ModelError

        try:
            text = self.prompt_text(request)
        except ModelError as error:
            raise _RequestError("request", str(error)) from None
        tokens = self.tokens(text)
        if request["op"] == "count":
            self.conn.send(("done", {"prompt": text, "prompt_tokens": len(tokens)}))
            return
        self.use_threads(int(request.get("n_threads") or 0))
        n_ctx = self.info["n_ctx"]
        room = n_ctx - len(tokens)
        if room < MIN_ANSWER_TOKENS:
            raise _RequestError("context", f"the prompt has {len(tokens)} tokens and the context holds {n_ctx}, "
                                           f"leaving {max(room, 0)} for the answer")
        if request["op"] == "evaluate":
            self.evaluate(tokens, request)
            return
        # A budget beyond the context is clamped: if the answer really needs more it ends as "length".
        self.generate(tokens, {**request, "max_tokens": min(int(request["max_tokens"]), room)})

    def use_threads(self, threads: int) -> None:
        """Run this request on `threads` llama.cpp threads (cpu.py decides per request; results do not depend on it)."""
        if threads > 0 and threads != self.threads:
            import llama_cpp

            llama_cpp.llama_set_n_threads(self.llm._ctx.ctx, threads, threads)
            self.threads = threads

    def evaluate(self, tokens: list[int], request: Request) -> None:
        """Evaluate the prompt as generate does and report a digest of the next-token logits.

        The logits are what sampling draws from, so equal digests mean every sampler sees the same
        distribution: how the tests check that a restored or live cache changes nothing.
        """
        import ctypes
        import hashlib

        llm = self.llm
        reused, source = self.prepare(tokens, self.fixed_length(request, tokens), str(request.get("prefix_label") or ""))
        llm.eval(tokens[llm.n_tokens:])  # the rest in batches from its start, as generate() evaluates it
        self.live_prompt = len(tokens)
        n_vocab = llm.n_vocab()
        logits = ctypes.string_at(llm._ctx.get_logits_ith(-1), n_vocab * ctypes.sizeof(ctypes.c_float))
        self.conn.send(("done", {"prompt_tokens": len(tokens), "cached_tokens": reused, "cache_source": source,
                                 "logits_sha256": hashlib.sha256(logits).hexdigest()}))

    def generate(self, tokens: list[int], request: Request) -> None:
        from llama_cpp import llama_vocab_is_eog

        llm = self.llm
        self.conn.send(("started", len(tokens)))
        reused, source = self.prepare(tokens, self.fixed_length(request, tokens), str(request.get("prefix_label") or ""))
        decoder = codecs.getincrementaldecoder("utf-8")(errors="replace")
        pieces: list[str] = []
        completion_tokens = 0
        finish_reason = "length"
        started = time.monotonic()
        max_tokens = int(request["max_tokens"])
        rejections = forced_tokens = 0
        engine = ""
        if self.cancel.is_set():
            finish_reason = "cancelled"
        else:
            sampler = make_sampler(llm, request.get("grammar") or None, self.masks, top_k=int(request["top_k"]),
                                   top_p=float(request["top_p"]), min_p=float(request["min_p"]),
                                   temperature=float(request["temperature"]),
                                   presence_penalty=float(request["presence_penalty"]), seed=int(request["seed"]))
            try:
                llm.eval(tokens[llm.n_tokens:])  # the rest of the prompt, in batches from its own start
                self.live_prompt = len(tokens)  # what follows is decoded one token at a time: never reused
                while True:
                    token = sampler.sample()
                    if llama_vocab_is_eog(llm._model.vocab, token):
                        finish_reason = "stop"
                        break
                    # Tokens the grammar forces next (a node's name after its first letters, "(" ...) are
                    # not sampled: they go into the same evaluation as the sampled one, one batch.
                    step = [token] + sampler.forced(max_tokens - completion_tokens - 1)
                    for each in step:
                        piece = decoder.decode(llm.detokenize([each], special=False))
                        if piece:
                            pieces.append(piece)
                            self.conn.send(("token", piece))
                    completion_tokens += len(step)
                    forced_tokens += len(step) - 1
                    if self.cancel.is_set():
                        finish_reason = "cancelled"
                        break
                    if completion_tokens >= max_tokens:
                        break
                    llm.eval(step)
            finally:
                rejections = sampler.rejections
                engine = sampler.engine if request.get("grammar") else ""
                sampler.close()
        tail = decoder.decode(b"", final=True)
        if tail:
            pieces.append(tail)
            self.conn.send(("token", tail))
        self.conn.send(("done", {"text": "".join(pieces), "finish_reason": finish_reason,
                                 "prompt_tokens": len(tokens), "completion_tokens": completion_tokens,
                                 "cached_tokens": reused, "cache_source": source,
                                 "grammar_rejections": rejections, "forced_tokens": forced_tokens,
                                 "grammar_engine": engine,
                                 "worker_seconds": time.monotonic() - started}))


class SampleFirst:
    """Sample as upstream llama.cpp does (common/sampling.cpp): the grammar is asked about one token.

    llama-cpp-python puts the grammar first in its sampler chain, so every token checks the grammar
    against the whole vocabulary (152k entries for Qwen3: tens of ms per token, bench/grammar.py).
    Here the chain (presence penalty, top-k, top-p, min-p, temperature, seeded draw) samples without
    the grammar; the grammar then checks only the chosen token, and when it refuses it, the token is
    drawn again from a chain with the grammar first, over the whole vocabulary. Every token is one the
    grammar accepts, so every output is grammar-valid, and the same seed gives the same output.

    A model that mostly writes what the grammar refuses (random weights; a model that does not know
    the format) would pay for both draws, so once more than half of at least SWITCH_AFTER tokens were
    refused the rest of the answer is drawn grammar-first only. The switch depends only on the tokens
    drawn so far, so it is as deterministic as the draws.
    """

    SWITCH_AFTER = 8
    engine = "gbnf"

    def __init__(self, llm: Llama, grammar: str | None, *, top_k: int, top_p: float, min_p: float, temperature: float,
                 presence_penalty: float, seed: int) -> None:
        import ctypes

        import llama_cpp
        import numpy as np
        from llama_cpp import _internals

        self._lc, self._ctypes, self._np, self.llm = llama_cpp, ctypes, np, llm
        self.n_vocab = llm.n_vocab()

        def chain(grammar_first: str | None) -> _internals.LlamaSampler:
            sampler = _internals.LlamaSampler()
            sampler.add_penalties(n_vocab=self.n_vocab, penalty_last_n=llm.last_n_tokens_size, penalty_repeat=1.0,
                                  penalty_freq=0.0, penalty_present=presence_penalty)
            if grammar_first is not None:
                sampler.add_grammar(llm._model, llama_cpp.LlamaGrammar.from_string(grammar_first, verbose=False))
            if temperature <= 0.0:
                sampler.add_greedy()
            else:
                sampler.add_top_k(top_k)
                sampler.add_top_p(top_p, 1)
                sampler.add_min_p(min_p, 1)
                sampler.add_temp(temperature)
                sampler.add_dist(seed)
            return sampler

        self.free = chain(None)
        self.constrained = chain(grammar) if grammar else None
        self.grammar = (llama_cpp.llama_sampler_init_grammar(llm._model.vocab, grammar.encode("utf-8"), b"root")
                        if grammar else None)
        self.ids = np.arange(self.n_vocab, dtype=np.intc)
        self.cells = np.zeros(self.n_vocab, dtype=np.dtype([("id", np.intc), ("logit", np.single), ("p", np.single)],
                                                          align=True))
        self.one = (llama_cpp.llama_token_data * 1)()
        self.rejections = 0
        self.drawn = 0
        self.grammar_first = False

    def _draw(self, sampler: _internals.LlamaSampler) -> int:
        lc, np = self._lc, self._np
        self.cells["id"] = self.ids
        self.cells["logit"] = np.ctypeslib.as_array(self.llm._ctx.get_logits_ith(-1), shape=(self.n_vocab,))
        self.cells["p"] = 0.0
        array = lc.llama_token_data_array(data=self.cells.ctypes.data_as(self._ctypes.POINTER(lc.llama_token_data)),
                                          size=self.n_vocab, selected=-1, sorted=False)
        lc.llama_sampler_apply(sampler.sampler, self._ctypes.byref(array))
        if array.selected < 0:
            raise RuntimeError("the sampler chain selected no token")
        return int(self.cells["id"][array.selected])

    def sample(self) -> int:
        """The next token (also accepted into the chains and the grammar, so they follow the output)."""
        lc = self._lc
        self.drawn += 1
        if (self.constrained is not None and self.drawn > self.SWITCH_AFTER
                and 2 * self.rejections > self.drawn - 1):
            self.grammar_first = True  # for the rest of the answer: the model keeps missing the grammar
        if self.grammar_first and self.constrained is not None:  # only ever set with a grammar
            token = self._draw(self.constrained)
        else:
            token = self._sample_first()
        for sampler in (self.free, self.constrained):
            if sampler is not None:
                lc.llama_sampler_accept(sampler.sampler, token)
        if self.grammar is not None:
            lc.llama_sampler_accept(self.grammar, token)
        return token

    def _sample_first(self) -> int:
        lc = self._lc
        token = self._draw(self.free)
        if self.grammar is not None:
            cell = self.one[0]
            cell.id, cell.logit, cell.p = token, 0.0, 0.0  # type: ignore[assignment]  # ctypes converts the int
            single = lc.llama_token_data_array(data=self.one, size=1, selected=-1, sorted=False)
            lc.llama_sampler_apply(self.grammar, self._ctypes.byref(single))
            if not self._np.isfinite(cell.logit):
                assert self.constrained is not None  # made with the grammar
                self.rejections += 1
                token = self._draw(self.constrained)
        return token

    def forced(self, most: int) -> list[int]:
        """llama.cpp's grammar cannot say what it forces next: every token is sampled."""
        return []

    def close(self) -> None:
        if self.grammar is not None:
            self._lc.llama_sampler_free(self.grammar)
            self.grammar = None
        for sampler in (self.free, self.constrained):
            if sampler is not None:
                sampler.close()


class TokenMasks:
    """The model's vocabulary as llguidance sees it, built once per worker, in a thread after the load.

    llguidance precompiles a grammar against the vocabulary (a token trie), so the mask of allowed
    tokens costs about half a millisecond over Qwen3's 151,936 tokens where llama.cpp's GBNF sampler
    takes tens (bench/grammar_engines.py). Reading the vocabulary out of llama.cpp takes a second or
    two for that size, so it runs while the app does its other stages; the first grammar waits for it.
    Without llguidance (or a grammar it refuses) the worker samples with llama.cpp's GBNF (SampleFirst).
    """

    def __init__(self, llm: Llama) -> None:
        import threading

        self._tokenizer: llguidance.LLTokenizer | None = None
        self._thread = threading.Thread(target=self._build, args=(llm,), name="grove-token-masks", daemon=True)
        self._thread.start()

    def _build(self, llm: Llama) -> None:
        try:
            import llguidance.llamacpp

            self._tokenizer = llguidance.llamacpp.lltokenizer_from_vocab(llm._model.vocab)
        except Exception as error:  # not installed, or a vocabulary it cannot read: GBNF it is
            print(f"grove: token masks unavailable, sampling with llama.cpp's grammar: {error}", file=sys.stderr)

    def matcher(self, grammar: str) -> llguidance.LLMatcher | None:
        """An LLMatcher for the GBNF `grammar`, or None when llguidance cannot take it."""
        self._thread.join()
        if self._tokenizer is None:
            return None
        import llguidance
        from llguidance.gbnf_to_lark import gbnf_to_lark

        try:
            matcher = llguidance.LLMatcher(self._tokenizer, llguidance.LLMatcher.grammar_from_lark(gbnf_to_lark(grammar)),
                                           log_level=0)
        except Exception as error:
            print(f"grove: llguidance refused the grammar, sampling with llama.cpp's: {error}", file=sys.stderr)
            return None
        if matcher.is_error():
            print(f"grove: llguidance refused the grammar, sampling with llama.cpp's: {matcher.get_error()}",
                  file=sys.stderr)
            return None
        return matcher


def make_sampler(llm: Llama, grammar: str | None, masks: TokenMasks | None,
                 **options: Unpack[SamplerOptions]) -> MaskFirst | SampleFirst:
    """MaskFirst when llguidance takes the grammar, else SampleFirst (llama.cpp's GBNF); both draw the same way."""
    matcher = masks.matcher(grammar) if grammar and masks is not None else None
    if matcher is not None:
        return MaskFirst(llm, matcher, **options)
    return SampleFirst(llm, grammar, **options)


class MaskFirst:
    """Sample from the tokens the grammar allows: llguidance's mask, then the sampler chain over those only.

    The chain (presence penalty, top-k, top-p, min-p, temperature, seeded draw) is SampleFirst's, run
    on the allowed candidates instead of the whole vocabulary, so it costs less than free sampling
    (top-k over 152k logits) and every token is valid by construction. `forced` hands the caller
    the tokens the grammar allows no choice about (llguidance's fast-forward), which are then
    evaluated with the sampled token in one batch rather than decoded one by one.
    """

    def __init__(self, llm: Llama, matcher: llguidance.LLMatcher, *, top_k: int, top_p: float, min_p: float, temperature: float,
                 presence_penalty: float, seed: int) -> None:
        import ctypes

        import llama_cpp
        import numpy as np
        from llama_cpp import _internals

        self._lc, self._ctypes, self._np, self.llm, self.matcher = llama_cpp, ctypes, np, llm, matcher
        self.n_vocab = llm.n_vocab()
        chain = _internals.LlamaSampler()
        chain.add_penalties(n_vocab=self.n_vocab, penalty_last_n=llm.last_n_tokens_size, penalty_repeat=1.0,
                            penalty_freq=0.0, penalty_present=presence_penalty)
        if temperature <= 0.0:
            chain.add_greedy()
        else:
            chain.add_top_k(top_k)
            chain.add_top_p(top_p, 1)
            chain.add_min_p(min_p, 1)
            chain.add_temp(temperature)
            chain.add_dist(seed)
        self.chain = chain
        self.mask = np.zeros((self.n_vocab + 31) // 32, dtype=np.int32)
        self.cells = np.zeros(self.n_vocab, dtype=np.dtype([("id", np.intc), ("logit", np.single), ("p", np.single)],
                                                          align=True))
        self.eos = llm.token_eos()
        self.rejections = 0  # nothing is ever refused: only allowed tokens are drawn
        self.engine = "llguidance"

    def sample(self) -> int:
        lc, np = self._lc, self._np
        if self.matcher.is_stopped():
            token = self.eos
        else:
            self.matcher.unsafe_compute_mask_ptr(self.mask.ctypes.data, self.mask.nbytes)
            bits = np.unpackbits(self.mask.view(np.uint8), bitorder="little")[:self.n_vocab]
            allowed = np.flatnonzero(bits).astype(np.intc)
            if len(allowed) == 0:
                raise RuntimeError(f"the grammar allows no token: {self.matcher.get_error()}")
            if len(allowed) == 1:
                token = int(allowed[0])
            else:
                logits = np.ctypeslib.as_array(self.llm._ctx.get_logits_ith(-1), shape=(self.n_vocab,))
                cells = self.cells[:len(allowed)]
                cells["id"] = allowed
                cells["logit"] = logits[allowed]
                cells["p"] = 0.0
                array = lc.llama_token_data_array(
                    data=cells.ctypes.data_as(self._ctypes.POINTER(lc.llama_token_data)), size=len(allowed),
                    selected=-1, sorted=False)
                lc.llama_sampler_apply(self.chain.sampler, self._ctypes.byref(array))
                if array.selected < 0:
                    raise RuntimeError("the sampler chain selected no token")
                token = int(cells["id"][array.selected])
        self._accept(token)
        return token

    def _accept(self, token: int) -> None:
        self._lc.llama_sampler_accept(self.chain.sampler, token)
        if not self.matcher.is_stopped() and not self.matcher.consume_token(token):
            raise RuntimeError(f"the grammar refused token {token}: {self.matcher.get_error()}")

    def forced(self, most: int) -> list[int]:
        """Up to `most` tokens the grammar forces next (already accepted): evaluate them, do not sample them."""
        if most <= 0 or self.matcher.is_stopped():
            return []
        tokens = [t for t in self.matcher.compute_ff_tokens() if t != self.eos][:most]
        for token in tokens:
            self._accept(token)
        return tokens

    def close(self) -> None:
        self.chain.close()
