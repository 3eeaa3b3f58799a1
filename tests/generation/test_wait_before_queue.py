"""A wait said before a queue is played and checked (language/wait_first.py, generation/queue_delay.py):
"sit in the waiting room for a minute before queuing at reception" waits where it starts for that
minute, then queues; the report claims the wait and counts only joins made after it. Planned from
hand-written drafts (no model) and run in the real simulation: the report's ✓ are measured."""

from __future__ import annotations

import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.scenario.events import read_events
from grove_tui.scenario.report import HOLDS
from grove_tui.world import load_world

# (world, sentence, the service the model queues at, the wait in seconds)
CASES = {
    "hospital-sit-before": ("hospital", "Four visitors sit in the main waiting room for a minute before queuing at "
                            "reception.", "reception_desk", 60.0),
    "station-then-join": ("station", "Three commuters hang about by the departure board for 40 seconds, then join the "
                          "queue at the ticket office.", "ticket_office", 40.0),
    "mall-after-waiting": ("mall", "Five shoppers join the queue at the information desk after waiting in the food "
                           "court for 45 seconds.", "information_desk", 45.0),
}


@pytest.fixture(scope="module", params=sorted(CASES))
def waited_queue_run(request, tmp_path_factory):
    world_name, sentence, service, _ = CASES[request.param]
    world = load_world(world_name)
    assert world.find(service)
    # what the model writes for a queue: go to the counter and queue there, no wait
    queue = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": service}),
                                       DraftNode("Queue", {"service_point": service})))
    bundle = tmp_path_factory.mktemp(request.param) / "bundle"
    run = plan_by_hand(world, "queuing", sentence, (DraftGroup("people", 4, world.zones[0].name, queue),), bundle)
    seconds = max(c.needs_seconds or 0.0 for g in run.report.groups for c in g.claims) + 10.0
    return request.param, run, run.run(seconds)


def test_the_wait_is_claimed_and_holds(waited_queue_run):
    case, _, checked = waited_queue_run
    wait = CASES[case][3]
    group = checked.groups[0]
    stay = next(c for c in group.claims if c.kind == "stay")
    assert stay.seconds == wait
    assert stay.status == HOLDS, stay.evidence


def test_they_queue_only_after_the_wait(waited_queue_run):
    case, run, checked = waited_queue_run
    wait = CASES[case][3]
    queue = next(c for c in checked.groups[0].claims if c.kind == "queue")
    assert queue.status == HOLDS, queue.evidence
    assert "0 joined before" in queue.evidence
    joins = [e.t for e in read_events(run.bundle / "events.jsonl") if e.kind == "queue_join"]
    assert joins and min(joins) >= wait
