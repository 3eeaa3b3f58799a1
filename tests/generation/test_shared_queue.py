"""A subset queueing behind the rest of its group gets a run long enough to be served
(generation/shared_queue.py): its claim counts the other groups' people in the same queue."""

from __future__ import annotations

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
