"""The grounding panel (inspect and simulation screens): planned and checked reports, drawn."""

from __future__ import annotations

from grove_tui.scenario.report import Claim, GroundingReport, GroupGrounding, RobotGrounding, RunCheck
from grove_tui.tui.widgets.grounding import grounding_text, read_grounding, summary

PATIENTS = GroupGrounding("ten patients", "patient", (
    Claim("count", "10", "10 people"),
    Claim("queue", "pharmacy", "queue at pharmacy_counter", place="pharmacy_counter"),
), tuple(range(1, 11)))
FAMILY = GroupGrounding("a family", "family", (
    Claim("count", "3", "3 people"),
    Claim("reach", "main_entrance", "walk to main_entrance", point=(5.0, 0.6), radius=1.9),
), (11, 12, 13), added=("waits for 10 s afterwards",), unsure=("'a family' count: 3 or 4? (guessed)",),
    edit="the sentence asked 3 ('a family'); you changed it to 4")
PLANNED = GroundingReport("ten patients queue at the pharmacy while a family walks to the exit", (PATIENTS, FAMILY),
                          unhonoured=("'by the window': the world has no window",),
                          robot=RobotGrounding("cross", "a robot crosses the lobby", (
                              Claim("robot_reach", "lobby", "drive to lobby", zone="lobby"),)))


def checked() -> GroundingReport:
    patients = GroupGrounding(PATIENTS.who, PATIENTS.label, (
        PATIENTS.claims[0].checked("holds", "10 in the run from its first frame"),
        PATIENTS.claims[1].checked("holds", "joined 10/10 at pharmacy_counter, advanced 9, served 4")),
        PATIENTS.members)
    family = GroupGrounding(FAMILY.who, FAMILY.label, (
        FAMILY.claims[0].checked("holds", "3 in the run"),
        FAMILY.claims[1].checked("fails", "1/3 reached main_entrance (last at t = 40.0 s)")),
        FAMILY.members, FAMILY.added)
    robot = RobotGrounding("cross", "a robot crosses the lobby",
                           (PLANNED.robot.claims[0].checked("unchecked", "never reached lobby; needs about 80 s"),))
    return GroundingReport(PLANNED.prompt, (patients, family), robot=robot, run=RunCheck(60.0, 1200))


def test_a_planned_report_shows_no_tick():
    report = read_grounding({"grounding": PLANNED.to_dict()})
    text = grounding_text(report, width=70)
    assert "✓" not in text.replace("Nothing is ✓ before a run", "")
    assert "· ten patients ×10" in text and "planned: queue at pharmacy_counter" in text
    assert "+ added  waits for 10 s afterwards" in text
    assert "? unsure" in text and "! edited" in text
    assert "! 'by the window': the world has no window" in text
    assert summary(report) == "planned: 2 groups and the robot"


def test_a_checked_report_shows_the_measured_figures():
    report = read_grounding(checked().to_dict())  # grounding.json is the report itself
    text = grounding_text(report, width=70)
    assert "✓ ten patients ×10" in text and "served 4" in text
    assert "✗ a family ×3" in text and "1/3 reached main_entrance" in text
    assert "? robot: cross" in text and "needs about 80 s" in text
    assert summary(report) == "1/2 groups ✓, 1 ✗; robot ? (run of 60 s)"


def test_text_wraps_inside_its_column_at_80x24_widths():
    lines = grounding_text(read_grounding(checked().to_dict()), width=34).splitlines()
    assert max(len(line.rstrip()) for line in lines) <= 34
    evidence = [i for i, line in enumerate(lines) if "1/3 reached" in line][0]
    assert lines[evidence].index("1/3") > 5  # under the value column, not under the mark


def test_missing_reports():
    assert read_grounding({"stages": {}}) is None and read_grounding(None) is None
    assert "No grounding report" in grounding_text(None)
    assert summary(None) == ""
    # a report written before claims existed: its agreeing checks are only planned, never ✓
    old = read_grounding({"grounding": {"prompt": "p", "groups": [{"who": "visitors", "label": "visitor", "checks": [
        {"field": "count", "asked": "4", "does": "4", "ok": True}]}]}})
    assert old.groups[0].claims[0].status == "planned"
