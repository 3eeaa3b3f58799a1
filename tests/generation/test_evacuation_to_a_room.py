"""People who evacuate "along the screens corridor to the foyer" in an emergency go to the foyer. Before,
an evacuating group's tree in the emergency preset was the field to the exit nearest to where they start,
whatever room the sentence sent them to: all ninety viewers left by the corridor's fire exit, none came to
the foyer, and the report's reach was ✗ on every run of the sentence."""

from __future__ import annotations

import json

from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.scenario.report import HOLDS
from grove_tui.world import load_world

CINEMA = "eval/understanding/worlds/cinema.yaml"
SENTENCE = ("Screen 3 is evacuated: its 90 viewers hurry along the screens corridor to the foyer and the robot "
            "waits in the foyer.")


def test_evacuees_sent_to_a_room_go_there_and_the_report_says_so(tmp_path):
    cinema = load_world(CINEMA)
    model = DraftNode("Sequence", {}, (DraftNode("Wait", {"duration": 5.0}),
                                       DraftNode("FollowVelocityField", {"exit": "screen_1_fire_exit"})))
    run = plan_by_hand(cinema, "emergency", SENTENCE, (DraftGroup("viewers", 90, "screen_3", model),),
                       tmp_path / "b")
    claims = {(c.kind, c.place): c for c in run.report.groups[0].claims}
    foyer = claims[("reach", "foyer")]
    report = run.run(2.0 * (foyer.needs_seconds or 75.0))  # ninety people in single file through doors
    checked = {(c.kind, c.place): c for c in report.groups[0].claims}
    assert checked[("reach", "foyer")].status == HOLDS, checked[("reach", "foyer")].evidence
    assert checked[("reach", "screens_corridor")].status == HOLDS, checked[("reach", "screens_corridor")].evidence


def test_evacuees_sent_to_a_room_leave_by_the_exit_nearest_to_it(tmp_path):
    """"Everyone in the cinema lobby evacuates to the south entrance hall": the hall has the main entrance,
    and they leave by it. Before, each one's exit was the one nearest to where they started (the east
    entrance, by the cinema lobby): they walked to the hall and then all the way back across the mall."""
    mall = load_world("mall")
    run = plan_by_hand(mall, "emergency", "Everyone in the cinema lobby, roughly 50 people, evacuates to the south "
                       "entrance hall and the robot follows them.",
                       (DraftGroup("people", 50, "cinema_lobby", DraftNode("FollowVelocityField",
                                                                         {"exit": "main_entrance"})),),
                       tmp_path / "b")
    notes = json.loads((run.bundle / "generation.json").read_text())["notes"]
    used = [n for n in notes if n.startswith("exits in use")]
    assert used == ["exits in use: main_entrance (50 people)"], used

