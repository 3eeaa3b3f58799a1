"""How long a run of a scenario should last: long enough for what the sentence asked to happen.

Every planned claim says how long a run needs before its outcome can be told (`Claim.needs_seconds`,
from the planned routes at the group's pace, the asked waits, the queue's service time, the robot's
path and its patrol round). The scenario's length is the longest of them, with a margin for the
detours, crowds and the robot that slow people down, at least `RUN_FLOOR` and at most `RUN_CAP` (a
behaviour that needs more than the cap is said: its claim stays "not checked" with the time it needs).

A run the user sets the length of keeps it; only a run that leaves it to the scenario (`grove generate
--simulate` with no number, `grove simulate` without `--seconds`, a job's `"simulate": true`, the
app's play) runs for this length. The length is part of the planned grounding report (`length`), so
the checked report says it beside the run's own length.
"""

from __future__ import annotations

import math
from dataclasses import replace

from grove_tui.scenario.report import GroundingReport, RunLength

RUN_MARGIN = 1.25  # the slowest claim's estimate times this (estimates leave out crowding and detours)
RUN_SLACK = 10.0  # seconds added after the margin
RUN_FLOOR = 60.0  # a scenario is never shorter than this
RUN_CAP = 900.0  # nor longer: a behaviour that needs more says so and stays "not checked"
STAY_SECONDS = 60.0  # a stay with no asked while is judged over at least this much of the run


def _claim_seconds(kind: str, needs: float | None, asked: float | None) -> float:
    seconds = float(needs or 0.0)
    if kind in ("stay", "robot_stay") and not asked:
        # "most of the run": a stay needs a run long enough to be one after the arrival
        seconds += STAY_SECONDS
    return seconds


def run_length(report: GroundingReport, cap: float = RUN_CAP) -> RunLength:
    """The run length that covers every planned claim of `report`, with its margin and cap."""
    needed, by = 0.0, ""
    rows = [(g.who, g.claims) for g in report.groups]
    if report.robot is not None:
        rows.append(("the robot", report.robot.claims))
    for who, claims in rows:
        for claim in claims:
            seconds = _claim_seconds(claim.kind, claim.needs_seconds, claim.seconds)
            if seconds > needed:
                needed, by = seconds, f"{who}: {claim.kind.replace('_', ' ')} {claim.asked}"
    wanted = max(RUN_FLOOR, math.ceil((needed * RUN_MARGIN + RUN_SLACK) / 10.0) * 10.0)
    return RunLength(round(min(wanted, cap), 1), round(needed, 1), cap, by)


def with_run_length(report: GroundingReport) -> GroundingReport:
    """The planned report carrying the scenario's run length."""
    return replace(report, length=run_length(report))


def scenario_seconds(generation: object) -> float | None:
    """The run length a generation.json's planned report carries (None: a bundle made before lengths)."""
    if not isinstance(generation, dict):
        return None
    grounding = generation.get("grounding")
    length = grounding.get("length") if isinstance(grounding, dict) else None
    if isinstance(length, dict):
        seconds = length.get("seconds")
        if isinstance(seconds, (int, float)) and not isinstance(seconds, bool) and math.isfinite(seconds) \
                and seconds > 0:
            return float(seconds)
    if isinstance(grounding, dict):
        return run_length(GroundingReport.from_dict(grounding)).seconds
    return None
