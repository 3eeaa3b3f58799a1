"""The worker's live KV cache never changes an answer: a request gives the same text on a fresh worker
as after any other request (the Ray batch wrote different trees than the one-process batch for the same
job, because llama.cpp evaluated the last prompt token alone after an identical earlier prompt)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from grove_tui.llm.embedded import embedded_model_path
from grove_tui.llm.worker import _Server

REQUESTS = json.loads((Path(__file__).parents[1] / "data" / "variation_requests.json").read_text())["requests"]


class _Events:
    def __init__(self) -> None:
        self.sent: list[tuple] = []

    def send(self, event: tuple) -> None:
        self.sent.append(event)


class _NeverCancelled:
    def is_set(self) -> bool:
        return False


def _answer(server: _Server, name: str, max_tokens: int | None = None) -> tuple[str, int]:
    server.conn = _Events()
    request = dict(REQUESTS[name]["request"])
    if max_tokens is not None:
        request["max_tokens"] = max_tokens
    server.generate(list(REQUESTS[name]["tokens"]), request)
    done = server.conn.sent[-1]
    assert done[0] == "done", done
    return done[1]["text"], done[1]["cached_tokens"]


@pytest.mark.slow
def test_an_answer_is_the_same_whatever_the_worker_served_before():
    from llama_cpp import Llama

    llm = Llama(model_path=str(embedded_model_path()), n_ctx=4096, n_threads=1, n_threads_batch=1, n_batch=512,
                verbose=False, seed=0)
    server = _Server(llm, _Events(), _NeverCancelled(), {"n_ctx": 4096})
    cold, cached = _answer(server, "variation 3")
    assert cached == 0
    for before in ("variation 2", "variation 0"):  # the whole prompt shared, then all but its last 20 tokens
        # The request served before only leaves its prompt in the live KV cache: its answer is never
        # compared, and the tokens it decodes are never reused (only prompt tokens are), so one answer
        # token leaves the cache as a whole answer would, without decoding up to 512 more.
        _answer(server, before, max_tokens=1)
        warm, cached = _answer(server, "variation 3")
        assert cached > 0, before
        assert warm == cold, f"after {before}"
