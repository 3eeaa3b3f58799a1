"""The Ray driver's choice of the next job for a free actor (no Ray needed): another variation of the
prompt the actor ran last when one is queued, so its model reuses that prompt's evaluated prefix."""

from __future__ import annotations

from grove_tui.services.cluster import _next_job
from grove_tui.services.jobs import BatchJob


def _job(prompt: str, name: str) -> BatchJob:
    return BatchJob(1, "hospital", "normal", prompt, 0, name, None)


def test_a_free_actor_gets_a_variation_of_its_last_prompt_first():
    queue = [_job("a", "a1"), _job("b", "b1"), _job("a", "a2")]
    assert _next_job(queue, ("hospital", "normal", "b")) == 1
    assert _next_job(queue, ("hospital", "normal", "a")) == 0


def test_without_a_match_or_a_history_the_queue_order_holds():
    queue = [_job("a", "a1"), _job("b", "b1")]
    assert _next_job(queue, None) == 0
    assert _next_job(queue, ("hospital", "normal", "c")) == 0
    assert _next_job(queue, ("office", "normal", "b")) == 0, "the same sentence in another world is another prompt"
