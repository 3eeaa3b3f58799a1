"""Synthesis counts every model call as an attempt and says why it asks again (issue 21 item 12).

Real llama.cpp: the tiny random-weight Qwen3 (byte-level vocabulary) under a grammar that allows one
small draft, so how many tokens an answer needs is known without trusting what the weights prefer.
"""

from __future__ import annotations

import pytest

from grove_tui.errors import ModelError
from grove_tui.generation.presets import load_preset
from grove_tui.generation.synthesis import SynthesisRequest, is_cut_off, synthesize
from grove_tui.llm.grammar import gbnf_literal

pytestmark = pytest.mark.slow  # every test here runs a real model

# A grammar that allows exactly one draft of two groups, 79 characters. The vocabulary is single bytes
# plus four two-byte merges ("Ġt", "ou", "ro", "es"), of which the answer can use at most four, so it
# takes 75 to 79 tokens: cut off at 45, complete within 90.
DRAFT = "2 people from lobby: Wait(duration=30)\n3 visitors from lobby: Wait(duration=60)"
GRAMMAR = f"root ::= {gbnf_literal(DRAFT)}\n"
MESSAGES = [{"role": "user", "content": "Two people wait in the lobby."}]


def request() -> SynthesisRequest:
    return SynthesisRequest(MESSAGES, ["Wait"], ["lobby"], GRAMMAR, 2)


def run(llm, max_tokens):
    calls: list[tuple[int, str, int]] = []  # (attempt, reason, tokens streamed before it)
    streamed: list[str] = []

    def on_attempt(attempt, reason):
        calls.append((attempt, reason, len(streamed)))
        streamed.clear()

    try:
        return synthesize(llm, request(), load_preset("normal"), seed=3, on_token=streamed.append,
                          max_tokens=max_tokens, on_attempt=on_attempt), calls, streamed
    except ModelError as exc:
        return exc, calls, streamed


def test_a_cut_off_answer_is_a_second_attempt_with_twice_the_budget(tiny_llm):
    result, calls, streamed = run(tiny_llm, max_tokens=45)
    assert not isinstance(result, Exception), result
    assert calls == [(2, "cut off at 45 tokens", calls[0][2])]
    assert 0 < calls[0][2] <= 45, "attempt 1 streamed at most its budget before attempt 2 was announced"
    assert result.attempts == 2
    assert result.draft.groups[0].spawn == "lobby" and result.text == DRAFT
    assert "".join(streamed) == result.text, "after the announcement only attempt 2's text streams"
    assert result.completion_tokens >= calls[0][2] + len(streamed), "both attempts are accounted"


def test_an_answer_cut_off_twice_fails_naming_the_budget_and_attempt(tiny_llm):
    result, calls, _ = run(tiny_llm, max_tokens=3)
    assert isinstance(result, ModelError) and is_cut_off(result)
    assert "within 6 tokens (attempt 2)" in str(result)
    assert [c[:2] for c in calls] == [(2, "cut off at 3 tokens")]


def test_an_answer_that_fits_is_one_attempt_and_announces_nothing(tiny_llm):
    result, calls, streamed = run(tiny_llm, max_tokens=200)
    assert not isinstance(result, Exception), result
    assert (result.attempts, calls) == (1, [])
    assert "".join(streamed) == result.text
