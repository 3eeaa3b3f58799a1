"""People who talk with no place named talk where they start (generation/reconcile.py): "... while two
nurses chat" had a 60 s wait as its tree, and the report a ✗ "the trees never talk" for a sentence that
asks nothing harder than a chat. Planned from a hand-written draft (no model), run in the real simulation."""

from __future__ import annotations

from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.scenario.report import HOLDS
from grove_tui.world import load_world


def test_a_chat_with_no_place_is_a_conversation_where_they_are(tmp_path):
    world = load_world("hospital")
    sentence = "two nurses chat while the robot delivers medicine to ward a"
    idle = DraftNode("Wait", {"duration": 60.0})  # what the model (or the fallback) gives a placeless chat
    run = plan_by_hand(world, "normal", sentence, (DraftGroup("nurse", 2, "staff_room", idle),), tmp_path / "b")
    trees = [t for p, t in run.op.trees.items()]
    assert trees and all(any(n.name == "Converse" for n in t.nodes()) for t in trees)
    converse = next(c for c in run.report.groups[0].claims if c.kind == "converse")
    assert converse.status != "fails", converse.evidence
    checked = run.run(60.0)
    converse = next(c for c in checked.groups[0].claims if c.kind == "converse")
    assert converse.status == HOLDS, converse.evidence
