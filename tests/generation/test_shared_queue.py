"""A subset queueing behind the rest of its group gets a run long enough to be served
(generation/shared_queue.py): its claim counts the other groups' people in the same queue."""

from __future__ import annotations

import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.world import load_world

PROMPT = "Twenty passengers queue at check-in counter A and a few of them glance at the robot"


def test_a_subset_at_the_back_of_a_shared_queue_has_a_run_long_enough_to_be_served(tmp_path):
    airport = load_world("worlds/airport.yaml")
    run = plan_by_hand(airport, "queuing", PROMPT,
                       (DraftGroup("passengers", 20, "check_in_hall",
                                   DraftNode("Queue", {"target": "check_in_counter_a"})),),
                       tmp_path / "b", as_the_pipeline=True)
    queues = {g.who: next(c for c in g.claims if c.kind == "queue") for g in run.report.groups}
    assert len(queues) == 2
    main, subset = sorted(run.report.groups, key=lambda g: -len(g.members))
    # the subset is served after everyone of the other group ahead of it, at 10 s each at least
    assert queues[subset.who].needs_seconds >= 10.0 * len(main.members)
    assert run.report.length is not None and run.report.length.needed >= queues[subset.who].needs_seconds


SUBSET = "Four passengers queue at check-in counter A and two of them glance at the robot"


def _served_claims(report):
    return {g.who: next(c for c in g.claims if c.kind == "queue") for g in report.groups}


@pytest.mark.parametrize("service", [30.0, 4.0])
def test_the_queue_is_served_for_the_trees_time_and_the_run_covers_it(tmp_path, service):
    """The Queue's service time is the tree's (the model's, kept by reconciliation, one per counter), and
    the claims' times and the run length count it: a 30 s counter's run lasts until the people at the back
    are served, a 4 s counter's run is not padded to 10 s each."""
    airport = load_world("worlds/airport.yaml")
    run = plan_by_hand(airport, "queuing", SUBSET,
                       (DraftGroup("passengers", 4, "check_in_hall",
                                   DraftNode("Queue", {"service_point": "check_in_counter_a",
                                                       "service_time": service})),),
                       tmp_path / "b", as_the_pipeline=True)
    times = {float(n.get("service_time") or 0) for doc in run.op.trees.values()
             for n in doc.nodes() if n.id == "Queue"}
    assert times == {service}  # every member of both groups, the subset too
    queues = _served_claims(run.report)
    main, subset = sorted(run.report.groups, key=lambda g: -len(g.members))
    assert queues[subset.who].needs_seconds >= service * (len(main.members) + 1)
    assert run.report.length is not None and run.report.length.needed >= queues[subset.who].needs_seconds
    if service < 10.0:
        assert queues[subset.who].needs_seconds < queues[main.who].needs_seconds + 10.0 * len(main.members)
    checked = run.run(run.report.length.seconds)
    served = {g.who: next(c for c in g.claims if c.kind == "queue") for g in checked.groups}
    for claim in served.values():
        assert claim.status == "holds", claim.evidence
    assert f"served {len(subset.members)}" in served[subset.who].evidence
