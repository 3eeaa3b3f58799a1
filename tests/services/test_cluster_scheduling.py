"""The Ray driver's choices, no Ray needed: the next job for a free actor (another variation of the
prompt the actor ran last when one is queued, so its model reuses that prompt's evaluated prefix), and
the refusal of workers that run other grove_tui code than the driver."""

from __future__ import annotations

from pathlib import Path

import pytest

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


def test_workers_running_other_grove_code_are_refused_naming_both_copies():
    from grove_tui.errors import EXIT_RUNTIME_FAILURE, RuntimeFailure
    from grove_tui.services.cluster import check_same_package, package_fingerprint

    driver = package_fingerprint()
    assert Path(driver[0], "services", "cluster.py").is_file() and len(driver[1]) == 64
    check_same_package(driver, [driver, ("/elsewhere/grove_tui", driver[1])])  # same code at another path
    with pytest.raises(RuntimeFailure) as refused:
        check_same_package(driver, [driver, ("/opt/old/grove_tui", "0" * 64)])
    assert "/opt/old/grove_tui" in str(refused.value) and driver[0] in str(refused.value)
    assert refused.value.exit_code == EXIT_RUNTIME_FAILURE
