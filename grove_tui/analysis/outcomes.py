"""Outcome checks: every claim of a planned grounding report checked against what happened in a run.

The planned report (generation.json `grounding`, built by generation/reconcile.py) says per group
what the sentence asks and where: reach a zone, stay, queue at a counter, talk with the others,
leave through a named exit, follow or block the robot, walk slowly. This module measures each claim
on the run's trajectories and event log and gives it ✓ with the measured figure, ✗ with the figure,
or "not checked" when the run ended before the outcome could show (saying how long it needs).

One function for every path: `grove metrics`, `grove simulate`, `grove generate --simulate`,
`grove batch` and the app all call `check_bundle` or feed an `OutcomeChecker`, so a report means the
same thing everywhere. The trajectories are streamed a block of frames at a time (as metrics.py
does) and sampled every SAMPLE_DT seconds: memory is set by the crowd, not by the run's length.

    report, path = check_bundle("out/pharmacy")          # writes out/pharmacy/grounding.json
    for line in report.lines():
        print(line)
"""

from __future__ import annotations

import json
import math
from abc import ABC, abstractmethod
from collections import deque
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import shapely

from grove_tui.analysis.arrival import Arrivals
from grove_tui.analysis.kept_up import ArrivalWith, follow_distance
from grove_tui.analysis.left_run import gone_reason
from grove_tui.analysis.robot_kept_away import Nearness, kept_away
from grove_tui.analysis.robot_errand import StopTrack, dropoff_verdict, pickup_verdict
from grove_tui.analysis.robot_errand import speeds as errand_speeds
from grove_tui.analysis.metrics import Trajectories, iter_trajectory_chunks
from grove_tui.errors import MetricsError
from grove_tui.files import write_text_atomic
from grove_tui.scenario.events import SimEvent
from grove_tui.scenario.reach import GLANCE_SECONDS, LOOK_RANGE, LOOK_SHARE, PASS_AT, PASS_BY
from grove_tui.scenario.report import (
    FAILS,
    HOLDS,
    UNCHECKED,
    Claim,
    GroundingReport,
    RobotGrounding,
    RunCheck,
)
from grove_tui.scenario.model import Scenario

if TYPE_CHECKING:
    from shapely.geometry.base import BaseGeometry

    from grove_tui.world import World

GROUNDING_FILE = "grounding.json"
SAMPLE_DT = 0.2  # seconds between the frames the checks look at
ZONE_MARGIN = 0.3  # a person's centre this far outside a zone's boundary still counts as in it (doorways)
MOVING = 0.3  # m/s: faster than this is walking, for pace
PACE_QUANTILE = 0.75  # the pace is this quantile of the moving speeds
ROBOT_MOVING = 0.1  # m/s
PARTNER_WALKING = 0.3  # m/s: the people followed are on their way (standing people sway slower than this)
CHAIN_LINK = 2.0  # metres between neighbours of a column that walks behind someone
CHAIN_MAX = 120  # followers checked as a column (the pairwise distances grow with its square)
FOLLOW_SHARE = 0.5  # share of the robot's moving time a follower must keep within reach
LOOK_ANGLE = 0.6  # rad: facing within this counts as looking
AVOID_NEAR = 6.0  # metres (centres): the robot is near enough for a wary person to keep away
AVOID_MOVED = 0.5  # metres moved away while it was near
BLOCK_AHEAD = 2.5  # metres ahead of the robot's front
BLOCK_SIDE = 0.8  # metres to either side of its heading
BLOCK_SECONDS = 2.0
BLOCK_SLOWED = 0.5  # the robot's speed while blocked, as a share of its own speed
STAY_SHARE = 0.9  # share of the time after arriving spent there
WANDER_WALKED = 3.0  # metres walked inside the zone
MOVE_WALKED = 3.0
PATROL_RADIUS = 1.0
CROSS_EDGE = 1.5  # metres: at least this near a zone's boundary is at its edge (a quarter of its width if more)
CROSS_APART = 0.5  # a crossing's ends at least this share of the zone's width apart
ON_THE_WAY_SECONDS = 10.0  # the last stretch of a run over which people not there yet are seen walking on
ON_THE_WAY_WALKED = 2.0  # metres walked over that stretch: still on the way, not stuck
ON_THE_WAY_PATIENCE = 3.0  # a run this many times the estimated time, and they are still not there: ✗


# ---- the public functions -------------------------------------------------------------------------

def check_bundle(bundle_dir: str | Path, write: bool = True) -> tuple[GroundingReport, Path]:
    """The bundle's planned report checked on its run (trajectories.csv, events.jsonl); with `write`,
    saved as grounding.json beside metrics.json. A bundle without a planned report or a run is refused."""
    from grove_tui.scenario.bundle import REPORT_FILE, load_report, load_scenario
    from grove_tui.scenario.events import read_events
    from grove_tui.world import load_world

    bundle = Path(bundle_dir)
    scenario = load_scenario(bundle)
    planned = planned_report(load_report(bundle) if (bundle / REPORT_FILE).is_file() else {})
    if planned is None:
        raise MetricsError(f"{bundle}: {REPORT_FILE} has no grounding report to check (generated before the "
                           f"sentence was read into groups); regenerate the bundle")
    world = load_world(_world_reference(scenario.world, bundle))
    events_path = bundle / "events.jsonl"
    events = read_events(events_path) if events_path.exists() else []
    checker = OutcomeChecker(planned, scenario, world)
    ids, _groups, chunks = iter_trajectory_chunks(bundle / "trajectories.csv")
    checker.set_ids(ids)
    for chunk in chunks:
        checker.add(chunk)
    report = checker.result(events)
    path = bundle / GROUNDING_FILE
    if write:
        write_text_atomic(path, json.dumps(report.to_dict(), indent=2, ensure_ascii=False) + "\n")
    return report, path


def planned_report(generation: Mapping[str, object]) -> GroundingReport | None:
    """The planned report of a generation.json (None when it has none)."""
    data = generation.get("grounding") if isinstance(generation, dict) else None
    if not isinstance(data, dict):
        return None
    report = GroundingReport.from_dict(data)
    return replace(report, run=None)


def check_run(planned: GroundingReport, scenario: Scenario, world: World, traj: Trajectories,
              events: Sequence[SimEvent], partial: bool = False) -> GroundingReport:
    """A run held in memory checked in one go (tests, evaluation)."""
    checker = OutcomeChecker(planned, scenario, world)
    checker.set_ids(traj.ids)
    checker.add(traj)
    return checker.result(events, partial=partial)


def _world_reference(reference: str, bundle: Path) -> str:
    candidate = bundle / reference
    return str(candidate) if candidate.suffix in (".yaml", ".yml") and candidate.exists() else reference


# ---- the checker ----------------------------------------------------------------------------------

class OutcomeChecker:
    """Feed it frames (whole frames, in time order, any block size) and the event log; `result` gives
    the checked report. The app keeps one for a run and feeds it the new frames as they come."""

    def __init__(self, planned: GroundingReport, scenario: Scenario, world: World, sample_dt: float = SAMPLE_DT):
        self.planned = planned
        self.scenario = scenario
        self.world = world
        self.sample_dt = float(sample_dt)
        self.ids = np.array(sorted(a.id for a in scenario.agents), dtype=np.int64)
        self._bucket = -1  # the last sampled time bucket
        self.t_end = 0.0
        self.frames = 0
        self._zones: dict[str, BaseGeometry] = {}
        self._probes: list[tuple[tuple[int, int], _Probe]] = []  # ((group index or -1 for the robot, claim index), probe)
        self.robot_max_vel = scenario.robot.max_vel if scenario.robot is not None else 0.8
        self._build()

    def set_ids(self, ids: np.ndarray) -> None:
        """The id axis the frames come on (a CSV's people); before the first `add`."""
        self.ids = np.asarray(ids, dtype=np.int64)
        self._build()

    def _cols(self, members: Iterable[int]) -> np.ndarray:
        wanted = np.asarray(sorted(set(int(m) for m in members)), dtype=np.int64)
        if wanted.size == 0 or self.ids.size == 0:
            return np.zeros(0, dtype=np.int64)
        cols = np.searchsorted(self.ids, wanted)
        cols = np.clip(cols, 0, self.ids.size - 1)
        return cols[self.ids[cols] == wanted]

    def zone_shape(self, name: str) -> BaseGeometry:
        if name not in self._zones:
            own = self.world.zone(name).polygon
            polygon = own.buffer(ZONE_MARGIN)
            # the margin is for doorways and walls, not for the room next door: someone standing inside
            # the kitchen by its opening to the living room is in the kitchen, not the living room
            near = [z.polygon for z in self.world.zones if z.name != name and z.polygon.intersects(polygon)]
            if near:
                polygon = polygon.difference(shapely.union_all(near).difference(own))
            shapely.prepare(polygon)
            self._zones[name] = polygon
        return self._zones[name]

    def _build(self) -> None:
        self._probes = []
        for gi, group in enumerate(self.planned.groups):
            cols = self._cols(group.members)
            for ci, claim in enumerate(group.claims):
                probe = _make_probe(claim, self, cols, len(group.members))
                if probe is not None:
                    self._probes.append(((gi, ci), probe))
        self._near = Nearness({gi: self._cols(g.members) for gi, g in enumerate(self.planned.groups)})
        if self.planned.robot is not None:
            for ci, claim in enumerate(self.planned.robot.claims):
                probe = _make_probe(claim, self, np.zeros(0, dtype=np.int64), 0, robot_row=True)
                if probe is not None:
                    self._probes.append(((-1, ci), probe))

    def add(self, traj: Trajectories) -> None:
        """Frames of the run (a chunk from iter_trajectory_chunks, or a run held in memory)."""
        if traj.frames == 0:
            return
        if traj.ids.shape != self.ids.shape or not np.array_equal(traj.ids, self.ids):
            raise MetricsError("outcome checks: frames on another id axis than the first ones")
        buckets = np.floor(traj.t / self.sample_dt + 1e-6).astype(np.int64)
        keep = np.flatnonzero(np.diff(buckets, prepend=self._bucket) > 0)
        self.t_end = max(self.t_end, float(traj.t[-1]))
        self.frames += traj.frames
        if keep.size == 0:
            return
        self._bucket = int(buckets[keep[-1]])
        frames = _Frames(traj.t[keep], traj.people[keep], traj.people_vel[keep], traj.people_yaw[keep],
                         None if traj.robot is None else traj.robot[keep],
                         None if traj.robot_vel is None else traj.robot_vel[keep])
        for _, probe in self._probes:
            probe.add(frames)
        self._near.add(frames.pos, frames.robot)

    def add_rows(self, rows: np.ndarray) -> None:
        """Rows as the recorder keeps them ((R, 9): frame, t, id, x, y, vx, vy, yaw, group), whole frames."""
        if len(rows) == 0:
            return
        self.add(Trajectories.from_rows_on(np.asarray(rows, dtype=np.float64), self.ids,
                                           np.full(self.ids.size, -1, dtype=np.int64)))

    def result(self, events: Sequence[SimEvent], partial: bool = False) -> GroundingReport:
        """The report with every claim checked on the frames so far and the events."""
        by_agent: dict[int, list[SimEvent]] = {}
        for event in events:
            by_agent.setdefault(int(event.agent_id), []).append(event)
        checked: dict[tuple[int, int], Claim] = {}
        for key, probe in self._probes:
            status, evidence = probe.verdict(self, by_agent)
            claim = probe.claim
            if status != HOLDS and status != FAILS:
                status = UNCHECKED
            gone = gone_reason(claim.kind, [int(i) for i in self.ids[probe.cols]], by_agent) \
                if key[0] >= 0 and status != HOLDS else ""
            if gone:
                status, evidence = FAILS, f"{evidence}; {gone}" if evidence else gone
            elif status == FAILS and claim.needs_seconds is not None and self.t_end + 1e-6 < claim.needs_seconds \
                    and not probe.final:
                status = UNCHECKED
                evidence = f"{evidence}; needs about {claim.needs_seconds:.0f} s, the run has {self.t_end:.0f} s"
            elif status == FAILS and not probe.final:
                walking = probe.still_on_the_way()
                patience = ON_THE_WAY_PATIENCE * (claim.needs_seconds or 30.0)
                if walking and self.t_end + 1e-6 < patience:
                    # the estimate was short (a longer detour, a crowd, the robot in the way), but they are
                    # walking on: the run ended too soon to tell, which is not a ✗
                    status = UNCHECKED
                    evidence = f"{evidence}; {walking} still walking on when the run ended at {_when(self.t_end)}: " \
                               f"run it longer"
            away = kept_away(claim, self._near.closest.get(key[0], np.full(1, np.inf)), self.planned.robot) \
                if key[0] >= 0 and status != HOLDS else ""
            if away:  # why the reaction could not fire: the robot's task kept it away from them
                evidence = f"{evidence}; {away}" if evidence else away
            checked[key] = claim.checked(status, evidence)
        groups = []
        for gi, group in enumerate(self.planned.groups):
            claims = tuple(checked.get((gi, ci), _unprobed(c)) for ci, c in enumerate(group.claims))
            groups.append(replace(group, claims=claims))
        robot = self.planned.robot
        if robot is not None:
            robot = RobotGrounding(robot.task, robot.text,
                                   tuple(checked.get((-1, ci), _unprobed(c)) for ci, c in enumerate(robot.claims)),
                                   robot.plan, robot.unsure)
        return replace(self.planned, groups=tuple(groups), robot=robot,
                       run=RunCheck(round(self.t_end, 3), self.frames, partial))


def _unprobed(claim: Claim) -> Claim:
    """A claim no probe measures (a kind this version does not know): said, never ✓."""
    if claim.status == FAILS:
        return claim
    return claim.checked(UNCHECKED, claim.evidence or f"no outcome check for '{claim.kind}'")


class _Frames:
    __slots__ = ("t", "pos", "vel", "yaw", "robot", "robot_vel")

    def __init__(self, t: np.ndarray, pos: np.ndarray, vel: np.ndarray, yaw: np.ndarray, robot: np.ndarray | None,
                 robot_vel: np.ndarray | None) -> None:
        self.t, self.pos, self.vel, self.yaw, self.robot, self.robot_vel = t, pos, vel, yaw, robot, robot_vel


# ---- probes: one per claim ------------------------------------------------------------------------

def _need(claim: Claim, n: int) -> int:
    return max(1, math.ceil(claim.share * n - 1e-9)) if n else 0


def _when(t: float) -> str:
    return f"t = {t:.1f} s"


def _judged_frames(t: np.ndarray, arrived: np.ndarray, seconds: float | None) -> np.ndarray:
    """Frames x members judged for a stay or a wander: from each member's arrival on, and when the
    sentence asks a while ("wait for 90 seconds and then walk on", "wander for two minutes") only that
    while, since going on once it is over is what the sentence says, not a broken stay."""
    since: np.ndarray = t[:, None] >= arrived[None, :]
    if seconds:
        since &= t[:, None] < arrived[None, :] + seconds
    return since


class _Probe(ABC):
    """Accumulates what one claim needs from the frames; `verdict` says holds/fails and the figure."""

    final = False  # a verdict that a longer run cannot change (a count, a start)

    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        self.claim = claim
        self.cols = cols
        self.members = members  # how many the group has in the scenario (some may be absent from the run)
        self.checker = checker

    def add(self, f: _Frames) -> None:
        """Take in a chunk of frames (probes that judge only from events keep nothing)."""

    def still_on_the_way(self) -> int:
        """How many of those who have not done it yet were walking on at the end of the frames (0: none,
        or a claim a longer run cannot change)."""
        return 0

    @abstractmethod
    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        """The claim's status and the evidence for it, from what add() gathered and the run's events."""

    # helpers
    def inside(self, f: _Frames, cols: np.ndarray | None = None) -> np.ndarray:
        """(F, M) whether each member is at the claim's place (its zone, or within radius of its point)."""
        cols = self.cols if cols is None else cols
        pos = f.pos[:, cols]
        return self.at_place(pos)

    def at_place(self, pos: np.ndarray) -> np.ndarray:
        claim = self.claim
        shape = pos.shape[:-1]
        finite = np.isfinite(pos[..., 0])
        out = np.zeros(shape, dtype=bool)
        if claim.point is not None:
            d = np.hypot(pos[..., 0] - claim.point[0], pos[..., 1] - claim.point[1])
            out = finite & (d <= claim.radius)
            if claim.zone is None:
                return out
        if claim.zone is not None:
            polygon = self.checker.zone_shape(claim.zone)
            flat = pos.reshape(-1, 2)
            ok = finite.reshape(-1)
            hit = np.zeros(flat.shape[0], dtype=bool)
            if ok.any():
                hit[ok] = shapely.contains_xy(polygon, flat[ok, 0], flat[ok, 1])
            out = out | hit.reshape(shape)
        return out

    def where(self) -> str:
        c = self.claim
        return c.place or c.zone or (f"({c.point[0]:.1f}, {c.point[1]:.1f})" if c.point else "the place")


class _CountProbe(_Probe):
    final = True

    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        self.present: int | None = None

    def add(self, f: _Frames) -> None:
        if self.present is None and f.t.size:
            self.present = int(np.isfinite(f.pos[0, self.cols, 0]).sum()) if self.cols.size else 0

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        present = self.present or 0
        if present == self.members:
            return HOLDS, f"{present} in the run from its first frame"
        return FAILS, f"{present} in the run, {self.members} planned"


class _StartProbe(_Probe):
    final = True

    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        self.first = np.full((self.cols.size, 2), np.nan)

    def add(self, f: _Frames) -> None:
        missing = ~np.isfinite(self.first[:, 0])
        if not missing.any():
            return
        pos = f.pos[:, self.cols]
        seen = np.isfinite(pos[..., 0])
        for j in np.flatnonzero(missing):
            rows = np.flatnonzero(seen[:, j])
            if rows.size:
                self.first[j] = pos[rows[0], j]

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        ok = self.at_place(self.first[None])[0] if self.cols.size else np.zeros(0, bool)
        n, hits = self.members, int(ok.sum())
        status = HOLDS if hits >= _need(replace(self.claim, share=1.0), n) else FAILS
        c = self.claim
        if c.zone and c.place and c.place != c.zone and c.point is None:
            # a thing or door is where they start in its zone: the zone is what is measured, so say it
            return status, f"{hits}/{n} started in {c.zone} (where {c.place} is)"
        return status, f"{hits}/{n} started in {self.where()}"


class _Trail:
    """The members' positions over the last ON_THE_WAY_SECONDS: who is still walking on at the end."""

    def __init__(self) -> None:
        self.samples: deque[tuple[float, np.ndarray]] = deque()

    def add(self, t: np.ndarray, pos: np.ndarray) -> None:
        self.samples.extend((float(x), pos[k]) for k, x in enumerate(t))
        cut = self.samples[-1][0] - ON_THE_WAY_SECONDS
        while len(self.samples) > 2 and self.samples[1][0] <= cut:
            self.samples.popleft()

    def walking(self, pending: np.ndarray) -> int:
        """How many of the `pending` members walked ON_THE_WAY_WALKED over the last stretch."""
        if len(self.samples) < 2 or self.samples[-1][0] - self.samples[0][0] < 0.5 * ON_THE_WAY_SECONDS:
            return 0
        (_, then), (_, now) = self.samples[0], self.samples[-1]
        walked = np.hypot(now[:, 0] - then[:, 0], now[:, 1] - then[:, 1])
        return int((pending & np.isfinite(walked) & (walked >= ON_THE_WAY_WALKED)).sum())


class _ReachProbe(_Probe):
    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        self.first = np.full(self.cols.size, np.inf)
        self.trail = _Trail()
        self.arrivals = Arrivals(self.cols.size)  # one who starts there has not arrived (analysis/arrival)

    def add(self, f: _Frames) -> None:
        if not self.cols.size or not np.isinf(self.first).any():
            return
        self.trail.add(f.t, f.pos[:, self.cols])
        inside = self.arrivals.arrived(self.inside(f), np.isfinite(f.pos[:, self.cols, 0]))
        if self.claim.seconds:
            # "wait in the kitchen for a minute and then walk to the living room": the walk comes after the
            # asked wait, so being there (or by its doorway) before the wait can be over is not reaching it
            inside &= f.t[:, None] >= self.claim.seconds
        hit = inside.any(axis=0)
        for j in np.flatnonzero(hit & np.isinf(self.first)):
            self.first[j] = f.t[np.argmax(inside[:, j])]

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        n = self.members
        reached = self.first[np.isfinite(self.first)]
        k = int(reached.size)
        text = f"{k}/{n} reached {self.where()}"
        if k:
            text += f" by {_when(float(reached.max()))}" if k == n else f" (last at {_when(float(reached.max()))})"
        there = self.arrivals.started_there(np.isinf(self.first))
        if there:
            text += f"; {there} started there and never came to it from elsewhere"
        return (HOLDS if k >= _need(self.claim, n) else FAILS), text

    def still_on_the_way(self) -> int:
        walking = self.trail.walking(np.isinf(self.first))
        return walking if int(np.isfinite(self.first).sum()) + walking >= _need(self.claim, self.members) else 0


class _StayProbe(_Probe):
    """Arrive, then stay: the share of the time after arriving spent at the place."""

    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        m = self.cols.size
        self.arrived = np.full(m, np.inf)
        self.after = np.zeros(m)
        self.inside_after = np.zeros(m)
        self.trail = _Trail()
        self.held = 0  # how many stayed, as the last verdict found
        # an asked while: the best dropped window of each member, and when they first came
        self.best_after = np.zeros(m)
        self.best_inside = np.zeros(m)
        self.first_arrival = np.full(m, np.inf)

    def add(self, f: _Frames) -> None:
        if not self.cols.size:
            return
        if np.isinf(self.arrived).any():
            self.trail.add(f.t, f.pos[:, self.cols])
        inside = self.inside(f)
        present = np.isfinite(f.pos[:, self.cols, 0])
        if self.claim.seconds:
            self._add_windows(f.t, inside, present, float(self.claim.seconds))
            return
        for j in np.flatnonzero(np.isinf(self.arrived) & inside.any(axis=0)):
            self.arrived[j] = f.t[np.argmax(inside[:, j])]
        since = _judged_frames(f.t, self.arrived, self.claim.seconds)
        # "most of the run": one who left the building after arriving (pushed out by a crowd, out of an
        # exit while keeping away from the robot) no longer stays, so the frames they are gone count
        self.after += since.sum(axis=0)
        self.inside_after += (since & inside).sum(axis=0)

    def _add_windows(self, t: np.ndarray, inside: np.ndarray, present: np.ndarray, seconds: float) -> None:
        """An asked while ("wait at the seats for a minute"): judged from an arrival, but passing by on
        the way (within the radius for a few seconds, then on round the seats to come back later) is
        not the arrival: a window that can no longer reach STAY_SHARE is dropped and the next coming
        back opens a new one; the best window is kept."""
        allowed = (1.0 - STAY_SHARE) * seconds / self.checker.sample_dt + 1.0
        for i in range(t.size):
            opened = np.isinf(self.arrived) & inside[i]
            self.arrived[opened] = t[i]
            self.first_arrival = np.minimum(self.first_arrival, self.arrived)
            window = (t[i] >= self.arrived) & (t[i] < self.arrived + seconds)
            self.after += window & present[i]
            self.inside_after += window & inside[i]
            doomed = window & (self.after - self.inside_after > allowed)
            if doomed.any():
                better = doomed & (self.inside_after > self.best_inside)
                self.best_after[better] = self.after[better]
                self.best_inside[better] = self.inside_after[better]
                self.arrived[doomed] = np.inf
                self.after[doomed] = 0.0
                self.inside_after[doomed] = 0.0

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        n = self.members
        # the best window of each member who came (a dropped one, or the one still open)
        keep = self.best_inside > self.inside_after
        after = np.where(keep, self.best_after, self.after)
        inside_after = np.where(keep, self.best_inside, self.inside_after)
        arrived = np.isfinite(self.arrived) | np.isfinite(self.first_arrival)
        share = np.divide(inside_after, after, out=np.zeros_like(after), where=after > 0)
        stayed_for = (inside_after * checker.sample_dt)
        ok = arrived & (share >= STAY_SHARE)
        asked = self.claim.seconds
        if asked and ok.any():
            # "waits for five minutes": the run must cover the wait (else a longer run is needed)
            long_enough = stayed_for + checker.sample_dt >= asked
            ok = ok & long_enough
        k = self.held = int(ok.sum())
        mean_share = float(share[arrived].mean()) if arrived.any() else 0.0
        text = f"{k}/{n} stayed at {self.where()}"
        if arrived.any():
            text += f" ({mean_share:.0%} of the {asked:g} s after arriving" if asked else \
                f" ({mean_share:.0%} of the time after arriving"
            text += f", {float(stayed_for[arrived].min()):.0f} s at least)" if asked else ")"
        else:
            text = f"0/{n} got to {self.where()}"
        if asked and arrived.any() and (share[arrived] >= STAY_SHARE).all() and not ok.all():
            return UNCHECKED, text + f"; asked {asked:.0f} s"
        return (HOLDS if k >= _need(self.claim, n) else FAILS), text

    def still_on_the_way(self) -> int:
        # those who arrived and left are not waiting; only the ones not there yet can still make it hold
        walking = self.trail.walking(np.isinf(self.arrived) & np.isinf(self.first_arrival))
        return walking if self.held + walking >= _need(self.claim, self.members) else 0


class _WanderProbe(_Probe):
    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        m = self.cols.size
        self.present = np.zeros(m)
        self.inside_n = np.zeros(m)
        self.walked = np.zeros(m)
        self.last = np.full((m, 2), np.nan)
        self.last_inside = np.zeros(m, dtype=bool)
        self.arrived = np.zeros(m, dtype=bool)
        self.arrived_at = np.full(m, np.inf)

    def add(self, f: _Frames) -> None:
        if not self.cols.size:
            return
        pos = f.pos[:, self.cols]
        inside = self.inside(f)
        present = np.isfinite(pos[..., 0])
        seq = np.concatenate([self.last[None], pos], axis=0)
        ins = np.concatenate([self.last_inside[None], inside], axis=0)
        step = np.hypot(*(np.diff(seq, axis=0).transpose(2, 0, 1)))
        step = np.where(np.isfinite(step) & ins[1:] & ins[:-1], step, 0.0)
        self.walked += step.sum(axis=0)
        # the share inside counts from arrival: walking there from elsewhere is not wandering outside
        for j in np.flatnonzero(~self.arrived & inside.any(axis=0)):
            self.arrived_at[j] = f.t[np.argmax(inside[:, j])]
        since = _judged_frames(f.t, self.arrived_at, self.claim.seconds)
        self.present += (present & since).sum(axis=0)
        self.inside_n += (inside & since).sum(axis=0)
        self.arrived |= inside.any(axis=0)
        self.last = np.where(present[-1][:, None], pos[-1], self.last)
        self.last_inside = np.where(present[-1], inside[-1], self.last_inside)

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        n = self.members
        share = np.divide(self.inside_n, self.present, out=np.zeros_like(self.present), where=self.present > 0)
        ok = self.arrived & (share >= STAY_SHARE) & (self.walked >= WANDER_WALKED)
        k = int(ok.sum())
        text = f"{k}/{n} wandered in {self.where()}"
        if self.arrived.any():
            text += (f" ({float(share[self.arrived].mean()):.0%} of the time inside, "
                     f"{float(self.walked[self.arrived].mean()):.0f} m walked there on average)")
        return (HOLDS if k >= _need(self.claim, n) else FAILS), text


class _LeaveProbe(_Probe):
    """They leave a place: each member is somewhere else than `zone` at some time of the run."""

    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        self.left = np.full(self.cols.size, np.inf)

    def add(self, f: _Frames) -> None:
        if not self.cols.size or not np.isinf(self.left).any():
            return
        outside = ~self.inside(f) & np.isfinite(f.pos[:, self.cols, 0])
        for j in np.flatnonzero(np.isinf(self.left) & outside.any(axis=0)):
            self.left[j] = f.t[np.argmax(outside[:, j])]

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        n = self.members
        gone = self.left[np.isfinite(self.left)]
        k = int(gone.size) + sum(1 for a in self._evacuated(events))
        k = min(k, n)
        text = f"{k}/{n} left {self.where()}" + (f" (last at {_when(float(gone.max()))})" if gone.size else "")
        return (HOLDS if k >= _need(self.claim, n) else FAILS), text

    def _evacuated(self, events: dict[int, list[SimEvent]]) -> list[int]:
        """Members out of the building without a frame outside the zone first (left through its own exit)."""
        ids = [int(i) for i in self.checker.ids[self.cols]] if self.cols.size else []
        return [i for j, i in enumerate(ids) if np.isinf(self.left[j])
                and any(e.kind in ("evacuated", "left_building") for e in events.get(i, ()))]


class _KeepOutProbe(_Probe):
    """They keep out of a place all the run long: each member's first time there, if any."""

    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        self.entered = np.full(self.cols.size, np.inf)

    def add(self, f: _Frames) -> None:
        if not self.cols.size:
            return
        inside = self.inside(f)
        for j in np.flatnonzero(inside.any(axis=0) & np.isinf(self.entered)):
            self.entered[j] = f.t[np.argmax(inside[:, j])]

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        n = self.members
        went = self.entered[np.isfinite(self.entered)]
        kept = n - int(went.size)
        text = f"{kept}/{n} never in {self.where()}"
        if went.size:
            text += f" (first in at {_when(float(went.min()))})"
        return (HOLDS if kept >= _need(self.claim, n) else FAILS), text


# Metres from its goal at which the robot's drive is over (a keep_out judged on the whole drive).
ARRIVED_RADIUS = 1.0


class _RobotKeepOutProbe(_Probe):
    """keep_out in the robot's row ("drives to the pharmacy, avoiding the cafeteria"): its trajectory never
    enters the place; a run that ends before its drive would be over cannot say it kept out."""

    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        self.entered = math.inf
        self.seen_robot = False
        self.last_t = 0.0
        self.arrived = False

    def add(self, f: _Frames) -> None:
        if f.robot is None:
            return
        self.seen_robot = True
        self.last_t = max(self.last_t, float(f.t[-1]))
        inside = self.at_place(f.robot[:, None, :2])[:, 0]
        if inside.any() and math.isinf(self.entered):
            self.entered = float(f.t[np.argmax(inside)])
            self.final = True  # in is in: a longer run cannot undo it
        goal = self.checker.scenario.robot.goal if self.checker.scenario.robot is not None else None
        if goal is not None and not self.arrived:
            # at its goal, the drive the sentence is about is over
            self.arrived = bool((np.hypot(f.robot[:, 0] - goal[0], f.robot[:, 1] - goal[1]) <= ARRIVED_RADIUS).any())

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        if not self.seen_robot:
            return FAILS, "no robot in the run"
        if not math.isinf(self.entered):
            return FAILS, f"the robot was in {self.where()} at {_when(self.entered)}"
        text = f"the robot never in {self.where()}"
        needs = self.claim.needs_seconds or 0.0
        if self.last_t + 1e-6 < needs and not self.arrived:
            return UNCHECKED, f"{text} up to {_when(self.last_t)}; its drive takes about {needs:.0f} s: run it longer"
        return HOLDS, text


class _MoveProbe(_Probe):
    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        self.walked = np.zeros(self.cols.size)
        self.last = np.full((self.cols.size, 2), np.nan)

    def add(self, f: _Frames) -> None:
        if not self.cols.size:
            return
        pos = f.pos[:, self.cols]
        seq = np.concatenate([self.last[None], pos], axis=0)
        step = np.hypot(*(np.diff(seq, axis=0).transpose(2, 0, 1)))
        self.walked += np.where(np.isfinite(step), step, 0.0).sum(axis=0)
        present = np.isfinite(pos[-1, :, 0])
        self.last = np.where(present[:, None], pos[-1], self.last)

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        n = self.members
        k = int((self.walked >= MOVE_WALKED).sum())
        mean = float(self.walked.mean()) if self.walked.size else 0.0
        return (HOLDS if k >= _need(self.claim, n) else FAILS), f"{k}/{n} walked (on average {mean:.0f} m)"


class _PaceProbe(_Probe):
    BINS = np.linspace(0.0, 3.0, 151)

    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        self.histogram = np.zeros(self.BINS.size - 1)

    def add(self, f: _Frames) -> None:
        if not self.cols.size:
            return
        v = f.vel[:, self.cols]
        speed = np.hypot(v[..., 0], v[..., 1])
        if self.claim.distance is not None and f.robot is not None:
            # a pace on the way to the robot: only while farther than `distance` from it
            pos = f.pos[:, self.cols]
            away = np.hypot(pos[..., 0] - f.robot[:, 0:1], pos[..., 1] - f.robot[:, 1:2]) > self.claim.distance
            speed = np.where(away, speed, np.nan)
        speed = speed.ravel()
        speed = speed[np.isfinite(speed) & (speed > MOVING)]
        if speed.size:
            self.histogram += np.histogram(np.clip(speed, 0.0, 2.999), self.BINS)[0]

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        total = self.histogram.sum()
        if total * checker.sample_dt < 2.0:
            return UNCHECKED, "too little walking to measure a pace"
        # The pace people keep while under way: the upper quartile of their moving speeds (slowing to
        # arrive, to go through a door, to stop beside someone is not their pace).
        cumulative = np.cumsum(self.histogram)
        k = int(np.searchsorted(cumulative, PACE_QUANTILE * total))
        pace = float((self.BINS[k] + self.BINS[k + 1]) / 2.0)
        low, high = self.claim.low or 0.0, self.claim.high or 9.9
        ok = low <= pace <= high
        band = f"{low:.2f}-{high:.2f}" if self.claim.low and self.claim.high and high < 9 else (
            f"at most {high:.2f}" if high < 9 else f"at least {low:.2f}")
        return (HOLDS if ok else FAILS), f"walking pace {pace:.2f} m/s (asked {self.claim.asked}: {band} m/s)"


class _EventsProbe(_Probe):
    """Claims told by the event log (queues, conversations, evacuations)."""

    def member_ids(self) -> list[int]:
        return [int(i) for i in self.checker.ids[self.cols]] if self.cols.size else []


class _QueueProbe(_EventsProbe):
    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        place = self.claim.place
        joined = advanced = served = 0
        first_served = math.inf
        elsewhere: set[str] = set()
        # a queue after a wait ("sit for five minutes before queuing"): a join before the wait is over is too soon
        after = self.claim.seconds or 0.0
        early = 0
        for agent in self.member_ids():
            mine = [e for e in events.get(agent, ()) if e.kind.startswith("queue_")]
            here = [e for e in mine if self._here(e.detail)]
            early += any(e.kind == "queue_join" and e.t < after for e in here)
            here = [e for e in here if e.t >= after]
            elsewhere |= {e.detail for e in mine if e.kind == "queue_join" and not self._here(e.detail)}
            joined += any(e.kind == "queue_join" for e in here)
            advanced += any(e.kind == "queue_advance" for e in here)
            got = [e.t for e in here if e.kind == "queue_served"]
            served += bool(got)
            if got:
                first_served = min(first_served, min(got))
        n = self.members
        text = f"joined {joined}/{n} at {place or self.claim.zone or 'a queue'}, advanced {advanced}, served {served}"
        if served:
            text += f" (first at {_when(first_served)})"
        if after:
            text += f"; {early} joined before the {after:g} s wait was over"
        if elsewhere:
            text += f"; queued elsewhere: {', '.join(sorted(elsewhere))}"
        ok = joined >= _need(self.claim, n) and served >= 1 and (n < 2 or advanced + served >= 2 or served >= 1)
        return (HOLDS if ok else FAILS), text


    def _here(self, service: str) -> bool:
        """A queue at the claim's service point, or (a claim about a zone) at any service point in it."""
        claim = self.claim
        if claim.place is not None:
            return service == claim.place
        if claim.zone is None:
            return True
        try:
            found = self.checker.world.find(service)
        except Exception:
            return False
        return getattr(found, "zone", getattr(found, "name", None)) == claim.zone


class _ConverseProbe(_EventsProbe):
    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        partners = set(self.claim.partners) or set(self.member_ids())
        starts = [(agent, e.t, frozenset(int(x) for x in e.detail.split(",") if x.strip().isdigit()))
                  for agent in self.member_ids() for e in events.get(agent, ()) if e.kind == "conversation_start"]
        circles = _circles([ids for _, _, ids in starts])
        talked = 0
        first = math.inf
        seen: set[int] = set()
        for agent, t, ids in starts:
            # everyone named (but the member itself) is in the circle it talked in: the people in it
            # when it started and those who joined it later (a circle that started without its last
            # arrivals, as the simulation's patience allows, is still one circle)
            if agent not in seen and (partners - {agent}) <= circles[ids]:
                seen.add(agent)
                talked += 1
                first = min(first, t)
        n = self.members
        text = f"{talked}/{n} talked with " + ("each other" if not self.claim.partners else
                                               f"agents {', '.join(map(str, sorted(partners)))}")
        if talked:
            text += f" (from {_when(first)})"
        return (HOLDS if talked >= _need(self.claim, n) else FAILS), text


def _circles(sets: list[frozenset[int]]) -> dict[frozenset[int], frozenset[int]]:
    """Each conversation_start's people -> everyone in its circle: the starts that share someone merged
    (a late arrival's start names the people already talking)."""
    merged: list[set[int]] = []
    for ids in sets:
        hit = [m for m in merged if m & ids]
        union = set(ids).union(*hit) if hit else set(ids)
        merged = [m for m in merged if not (m & ids)] + [union]
    return {ids: frozenset(next(m for m in merged if ids <= m)) for ids in sets}


class _EvacuateProbe(_EventsProbe):
    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        exits = set(self.claim.exits)
        out = through = 0
        last = 0.0
        used: dict[str, int] = {}
        for agent in self.member_ids():
            done = [e for e in events.get(agent, ()) if e.kind == "evacuated"]
            if not done:
                continue
            out += 1
            last = max(last, done[0].t)
            used[done[0].detail] = used.get(done[0].detail, 0) + 1
            through += (not exits) or done[0].detail in exits
        n = self.members
        text = f"{out}/{n} out of the building"
        if out:
            text += f" by {_when(last)} (" + ", ".join(f"{k or 'an exit'} {v}" for k, v in sorted(used.items())) + ")"
        if exits:
            text += f"; {through} through " + (', '.join(sorted(exits)) if len(exits) <= 3 else "the exits asked")
        ok = through >= _need(self.claim, n)
        return (HOLDS if ok else FAILS), text


class _RobotProbe(_Probe):
    """Reactions to the robot: distances and bearings between each member and the robot."""

    def no_robot(self) -> tuple[str, str]:
        return FAILS, "the scenario has no robot"

    def robot_distances(self, f: _Frames) -> np.ndarray | None:
        """Each member's distance to the robot in each frame (frames x members; NaN where a member is
        absent), or None for frames without a robot or a group without members."""
        if f.robot is None or not self.cols.size:
            return None
        self.seen_robot = True
        pos = f.pos[:, self.cols]
        return np.hypot(pos[..., 0] - f.robot[:, 0:1], pos[..., 1] - f.robot[:, 1:2])


class _RobotFollowProbe(_RobotProbe):
    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        m = self.cols.size
        self.since = np.full(m, np.inf)  # first time within reach
        self.moving = np.zeros(m)  # robot-moving frames since then
        self.near = np.zeros(m)
        self.seen_robot = False
        # kept up with it: the group's reach stretched by its size, and at its goal with it (kept_up.py)
        self.reach = follow_distance(self.claim.distance or 3.0, m)
        robot = checker.scenario.robot
        self.arrival = ArrivalWith(robot.goal if robot is not None else None,
                                   robot.start if robot is not None else None, m, self.reach)
        self.behind: list[np.ndarray] = []  # the nearest member's distance while the robot drives

    def add(self, f: _Frames) -> None:
        d = self.robot_distances(f)
        if d is None:
            return
        if f.robot is not None:
            self.arrival.add(f.t, f.robot, f.pos[:, self.cols])
        within = np.isfinite(d) & (d <= self.reach)
        if 1 < self.cols.size <= CHAIN_MAX:
            # eight tourists behind a guiding robot walk as a crowd, the last ones 5 m back but with the others
            pos = f.pos[:, self.cols]
            within = _along_the_chain(pos, within, np.isfinite(pos[..., 0]))
        for j in np.flatnonzero(np.isinf(self.since) & within.any(axis=0)):
            self.since[j] = f.t[np.argmax(within[:, j])]
        speed = np.hypot(f.robot_vel[:, 0], f.robot_vel[:, 1]) if f.robot_vel is not None else np.zeros(f.t.size)
        counted = (f.t[:, None] >= self.since[None, :]) & (speed[:, None] > ROBOT_MOVING) & np.isfinite(d)
        self.moving += counted.sum(axis=0)
        self.near += (counted & within).sum(axis=0)
        driving = (speed > ROBOT_MOVING) & (f.t >= self.since.min())
        if driving.any():
            self.behind.append(np.nanmin(np.where(np.isfinite(d[driving]), d[driving], np.inf), axis=1))

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        if not self.seen_robot:
            return self.no_robot()
        n = self.members
        reached = np.isfinite(self.since)
        share = np.divide(self.near, self.moving, out=np.zeros_like(self.near), where=self.moving > 0)
        enough = self.moving * checker.sample_dt >= 3.0
        ok = reached & enough & (share >= FOLLOW_SHARE)
        d = self.reach
        text = f"{int(ok.sum())}/{n} followed it within {d:g} m" + \
            (f" or {CHAIN_LINK:g} m of one who is" if 1 < self.cols.size <= CHAIN_MAX else "")
        if reached.any():
            text += f" ({float(share[reached].mean()):.0%} of its moving time since reaching it, first at " \
                    f"{_when(float(self.since[reached].min()))})"
            behind = np.concatenate(self.behind) if self.behind else np.zeros(0)
            behind = behind[np.isfinite(behind)]
            if behind.size:
                low, mid, high = np.percentile(behind, [10, 50, 90])
                text += f"; the nearest {mid:.1f} m behind it ({low:.1f}-{high:.1f} m) while it drove"
        else:
            text = f"0/{n} came within {d:g} m of the robot"
        if reached.any() and not enough[reached].any():
            return UNCHECKED, text + "; the robot hardly moved after they reached it"
        kept = int(ok.sum()) >= _need(self.claim, n)
        arrived, how = self.arrival.judged(_need(self.claim, n)) if kept else (None, "")
        if how:
            text += "; " + how
        if kept and arrived is False:
            return FAILS, text
        return (HOLDS if kept else FAILS), text


class _RobotApproachProbe(_RobotProbe):
    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        self.closest = np.full(self.cols.size, np.inf)
        self.when = np.full(self.cols.size, np.nan)
        self.seen_robot = False

    def add(self, f: _Frames) -> None:
        d = self.robot_distances(f)
        if d is None:
            return
        d = np.where(np.isfinite(d), d, np.inf)
        if self.claim.zone is not None or self.claim.point is not None:
            # "approach the robot at the entrance": only a meeting at that place counts
            d = np.where(self.at_place(f.pos[:, self.cols]), d, np.inf)
        k = np.argmin(d, axis=0)
        best = d[k, np.arange(d.shape[1])]
        better = best < self.closest
        self.closest[better] = best[better]
        self.when[better] = f.t[k[better]]

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        if not self.seen_robot:
            return self.no_robot()
        n = self.members
        d = self.claim.distance or 2.0
        ok = self.closest <= d
        k = int(ok.sum())
        finite = np.isfinite(self.closest)
        at = f" at {self.where()}" if self.claim.zone is not None or self.claim.point is not None else ""
        text = f"{k}/{n} came within {d:g} m of the robot{at}"
        if finite.any():
            j = int(np.nanargmin(np.where(finite, self.closest, np.nan)))
            text += f" (closest {float(self.closest[j]):.1f} m at {_when(float(self.when[j]))})"
        return (HOLDS if k >= _need(self.claim, n) else FAILS), text


class _RobotBlockProbe(_RobotProbe):
    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        m = self.cols.size
        self.blocked = np.zeros(m)  # frames standing in its path
        self.speed_sum = np.zeros(m)  # the robot's speed summed over those frames
        self.seen_robot = False

    def add(self, f: _Frames) -> None:
        if f.robot is None or not self.cols.size:
            return
        self.seen_robot = True
        rx, ry, ryaw = f.robot[:, 0], f.robot[:, 1], f.robot[:, 2]
        hx, hy = np.cos(ryaw), np.sin(ryaw)
        pos = f.pos[:, self.cols]
        dx, dy = pos[..., 0] - rx[:, None], pos[..., 1] - ry[:, None]
        ahead = dx * hx[:, None] + dy * hy[:, None]
        side = np.abs(-dx * hy[:, None] + dy * hx[:, None])
        in_path = np.isfinite(ahead) & (ahead > 0.0) & (ahead <= BLOCK_AHEAD) & (side <= BLOCK_SIDE)
        if self.claim.zone is not None or self.claim.point is not None:
            # "block the robot in the doorway": only a block at that place counts
            in_path &= self.at_place(pos)
        speed = np.hypot(f.robot_vel[:, 0], f.robot_vel[:, 1]) if f.robot_vel is not None else np.zeros(f.t.size)
        self.blocked += in_path.sum(axis=0)
        self.speed_sum += (in_path * speed[:, None]).sum(axis=0)

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        if not self.seen_robot:
            return self.no_robot()
        n = self.members
        seconds = self.blocked * checker.sample_dt
        speed = np.divide(self.speed_sum, self.blocked, out=np.zeros_like(self.speed_sum), where=self.blocked > 0)
        slowed = speed <= BLOCK_SLOWED * checker.robot_max_vel
        ok = (seconds >= BLOCK_SECONDS) & slowed
        k = int(ok.sum())
        placed = self.claim.zone is not None or self.claim.point is not None
        at = f" at {self.where()}" if placed else ""
        if not (self.blocked > 0).any():
            return FAILS, f"0/{n} stood in the robot's path{at}"
        j = int(np.argmax(seconds))
        text = (f"{k}/{n} stood in its path{at} and slowed it ({float(seconds[j]):.0f} s in its path; its speed "
                f"there {float(speed[j]):.2f} m/s against {checker.robot_max_vel:.2f})")
        return (HOLDS if k >= _need(self.claim, n) else FAILS), text


class _RobotAvoidProbe(_RobotProbe):
    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        m = self.cols.size
        self.away = np.zeros(m)  # net metres moved away from the robot while it was near, so far
        self.best = np.zeros(m)  # the most that net ever was: stepping away and coming back is avoiding it
        self.near = np.zeros(m)
        self.closest = np.full(m, np.inf)
        self.last = np.full((m, 2), np.nan)
        self.last_robot = np.full(2, np.nan)
        self.seen_robot = False

    def add(self, f: _Frames) -> None:
        if f.robot is None or not self.cols.size:
            return
        self.seen_robot = True
        pos = f.pos[:, self.cols]
        robot = f.robot[:, :2]
        prev = np.concatenate([self.last[None], pos[:-1]], axis=0)
        prev_robot = np.concatenate([self.last_robot[None], robot[:-1]], axis=0)
        rel = prev - prev_robot[:, None, :]
        dist = np.hypot(rel[..., 0], rel[..., 1])
        near = np.isfinite(dist) & (dist <= (self.claim.distance or AVOID_NEAR)) & (dist > 1e-6)
        move = pos - prev
        radial = np.where(near, (move[..., 0] * rel[..., 0] + move[..., 1] * rel[..., 1]) / np.where(near, dist, 1.0), 0.0)
        running = self.away[None, :] + np.cumsum(np.where(np.isfinite(radial), radial, 0.0), axis=0)
        self.best = np.maximum(self.best, running.max(axis=0))
        self.away = running[-1]
        self.near += near.sum(axis=0)
        now = np.hypot(pos[..., 0] - robot[:, 0:1], pos[..., 1] - robot[:, 1:2])
        self.closest = np.fmin(self.closest, np.nanmin(np.where(np.isfinite(now), now, np.inf), axis=0))
        present = np.isfinite(pos[-1, :, 0])
        self.last = np.where(present[:, None], pos[-1], self.last)
        self.last_robot = robot[-1]

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        if not self.seen_robot:
            return self.no_robot()
        n = self.members
        came = self.near > 0
        ok = came & (self.best >= AVOID_MOVED)
        k = int(ok.sum())
        if not came.any():
            closest = float(self.closest.min()) if self.closest.size else math.inf
            return FAILS, f"the robot never came within {self.claim.distance or AVOID_NEAR:g} m of them " \
                          f"(closest {closest:.1f} m)"
        text = (f"{k}/{int(came.sum())} moved away when it came within {self.claim.distance or AVOID_NEAR:g} m "
                f"({float(self.best[came].mean()):.1f} m on average; closest {float(self.closest[came].min()):.1f} m)")
        return (HOLDS if k >= _need(self.claim, int(came.sum())) else FAILS), text


from grove_tui.analysis.passing_window import PassingWindow  # noqa: E402


class _RobotLookProbe(_RobotProbe):
    """A look at the robot while it is within LOOK_RANGE. A claim with `seconds` ("glance at it", "look at
    it": generation/look_span.py) asks for one look at least that long; one without ("stare at it", "watch
    it") for facing it LOOK_SHARE of the time it is in range."""

    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        m = self.cols.size
        self.in_sight = np.zeros(m)
        self.facing = np.zeros(m)
        self.run = np.zeros(m)  # frames of the look going on
        self.longest = np.zeros(m)  # frames of the longest look
        self.seen_robot = False
        # a look tied to the robot passing (claim.moment "pass"): when it passed, how near it came, when they looked
        self.passed: list[float] = []
        self.closest = math.inf
        self.looked: list[float] = []
        self.window = PassingWindow()

    def _passing(self, f: _Frames, d: np.ndarray) -> np.ndarray:
        """(F, M) frames the robot is passing the claim's place (within its radius), else them (PASS_BY)."""
        assert f.robot is not None
        if self.claim.point is not None:
            px, py = self.claim.point
            near = np.hypot(f.robot[:, 0] - px, f.robot[:, 1] - py)
            finite = near[np.isfinite(near)]
            if finite.size:
                self.closest = min(self.closest, float(finite.min()))
            return np.broadcast_to((np.nan_to_num(near, nan=np.inf) <= (self.claim.radius or PASS_AT))[:, None], d.shape)
        if self.claim.place is not None and self.claim.place in {z.name for z in self.checker.world.zones}:
            # a zone passed ("as it passes the gateline"): while the robot is in it
            xy = np.nan_to_num(f.robot[:, :2], nan=1e9)
            inside = shapely.contains_xy(self.checker.zone_shape(self.claim.place), xy[:, 0], xy[:, 1])
            return np.broadcast_to(np.asarray(inside, dtype=bool)[:, None], d.shape)
        finite = d[np.isfinite(d)]
        if finite.size:
            self.closest = min(self.closest, float(finite.min()))
        return np.isfinite(d) & (d <= PASS_BY)

    def pass_times(self, t: np.ndarray, passing: np.ndarray) -> None:
        rows = passing.any(axis=1)
        if rows.any():
            times = t[rows]
            self.passed = [min(self.passed[0], float(times[0])) if self.passed else float(times[0]),
                           max(self.passed[1], float(times[-1])) if self.passed else float(times[-1])]

    def look_times(self, t: np.ndarray, looking: np.ndarray) -> None:
        rows = looking.any(axis=1)
        if rows.any():
            times = t[rows]
            self.looked = [min(self.looked[0], float(times[0])) if self.looked else float(times[0]),
                           max(self.looked[1], float(times[-1])) if self.looked else float(times[-1])]

    def add(self, f: _Frames) -> None:
        if f.robot is None or not self.cols.size:
            return
        self.seen_robot = True
        pos = f.pos[:, self.cols]
        dx, dy = f.robot[:, 0:1] - pos[..., 0], f.robot[:, 1:2] - pos[..., 1]
        d = np.hypot(dx, dy)
        sight = np.isfinite(d) & (d <= LOOK_RANGE)
        bearing = np.arctan2(dy, dx)
        off = np.abs((bearing - f.yaw[:, self.cols] + np.pi) % (2 * np.pi) - np.pi)
        looking = sight & (off <= LOOK_ANGLE)
        if self.claim.moment == "pass":
            # "looks up as the robot passes the desk": only the frames of that pass count, each member's
            # once in place (passing_window.py: the verdict recounts from the frames kept here)
            passing = self._passing(f, d)
            self.window.add(f.t, sight & passing, looking & passing,
                            np.hypot(f.vel[:, self.cols, 0], f.vel[:, self.cols, 1]))
            self.pass_times(f.t, passing)
            sight &= passing
            looking &= passing
            self.look_times(f.t, looking)
        self.in_sight += sight.sum(axis=0)
        self.facing += looking.sum(axis=0)
        for row in looking:
            self.run = np.where(row, self.run + 1, 0)
            self.longest = np.maximum(self.longest, self.run)

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        if not self.seen_robot:
            return self.no_robot()
        n = self.members
        moment = self.claim.moment == "pass"
        ids = [int(i) for i in checker.ids[self.cols]]
        in_place = self.window.in_place(ids, events) if moment else None
        if in_place is not None:  # each member's time near the passing robot once in place
            counts = self.window.counted(in_place, checker.sample_dt)
            self.in_sight, self.facing, self.longest, self.passed, self.looked = counts
        seen = self.in_sight * checker.sample_dt >= 1.0
        what = self.claim.place or "them"
        if moment and not self.passed:
            reach = (self.claim.radius or PASS_AT) if self.claim.point is not None else PASS_BY
            closest = f" (closest {self.closest:.1f} m)" if math.isfinite(self.closest) else ""
            return FAILS, f"the robot never passed {what}: it never came within {reach:g} m{closest}"
        if moment and not seen.any():
            return FAILS, (f"the robot passed {what} from {_when(self.passed[0])} to {_when(self.passed[1])}, "
                           f"never within {LOOK_RANGE:g} m of them for 1 s then")
        if not seen.any():
            return FAILS, f"the robot never came within {LOOK_RANGE:g} m of them"
        share = np.divide(self.facing, self.in_sight, out=np.zeros_like(self.facing), where=self.in_sight > 0)
        near = f"{float(self.in_sight[seen].mean() * checker.sample_dt):.0f} s it was within {LOOK_RANGE:g} m"
        if self.claim.seconds:
            longest = self.longest * checker.sample_dt
            ok = seen & (longest >= self.claim.seconds - 1e-6)
            k = int(ok.sum())
            text = (f"{k}/{n} looked at it for {self.claim.seconds:g} s or more at once (longest look "
                    f"{float(longest[seen].max()):.1f} s; {float(share[seen].mean()):.0%} of the {near})")
        else:
            ok = seen & (share >= LOOK_SHARE)
            k = int(ok.sum())
            text = f"{k}/{n} looked at it for {LOOK_SHARE:.0%} or more of the time it was near " \
                   f"({float(share[seen].mean()):.0%} of the {near})"
        if moment:
            looked = f"they looked from {_when(self.looked[0])} to {_when(self.looked[1])}" if self.looked else \
                "they did not look at it then"
            text = (f"the robot passed {what} from {_when(self.passed[0])} to {_when(self.passed[1])}; {looked}; "
                    f"{text} while it passed")
            if in_place is not None:
                text += self.window.said(ids, in_place)
        return (HOLDS if k >= _need(self.claim, n) else FAILS), text


def _along_the_chain(pos: np.ndarray, near: np.ndarray, present: np.ndarray) -> np.ndarray:
    """(F, M) members with the one followed: near them, or within CHAIN_LINK of a member who is (a class
    behind its teacher walks as a column, its tail as much with her as its head)."""
    diff = pos[:, :, None, :] - pos[:, None, :, :]
    linked = np.hypot(diff[..., 0], diff[..., 1]) <= CHAIN_LINK  # NaN (absent) compares False
    reached = near.copy()
    for _ in range(min(pos.shape[1], 40)):
        grown = reached | (linked & reached[:, None, :]).any(axis=2)
        grown &= present
        if (grown == reached).all():
            break
        reached = grown
    return reached


class _FollowPersonProbe(_Probe):
    """Close to the people followed while they walk ("follow their guide to the gallery": on the way;
    once the guide stands still, anywhere); all the time when they never walk."""

    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        self.partner_cols = self.checker._cols(self.claim.partners)
        m = self.cols.size
        self.present = np.zeros(m)
        self.near = np.zeros(m)
        self.moving_present = np.zeros(m)
        self.moving_near = np.zeros(m)

    def add(self, f: _Frames) -> None:
        if not self.cols.size or not self.partner_cols.size:
            return
        pos = f.pos[:, self.cols]
        partners = f.pos[:, self.partner_cols]
        d = np.hypot(pos[:, :, None, 0] - partners[:, None, :, 0], pos[:, :, None, 1] - partners[:, None, :, 1])
        d = np.where(np.isfinite(d), d, np.inf).min(axis=2)
        present = np.isfinite(pos[..., 0]) & np.isfinite(partners[..., 0]).any(axis=1)[:, None]
        near = present & (d <= (self.claim.distance or 3.0))
        if 1 < self.cols.size <= CHAIN_MAX:
            near = _along_the_chain(pos, near, present)
        self.present += present.sum(axis=0)
        self.near += near.sum(axis=0)
        speed = np.hypot(f.vel[:, self.partner_cols, 0], f.vel[:, self.partner_cols, 1])
        walking: np.ndarray = np.asarray((np.where(np.isfinite(speed), speed, 0.0) > PARTNER_WALKING).any(axis=1))
        walking = walking[:, None]
        self.moving_present += (present & walking).sum(axis=0)
        self.moving_near += (near & walking).sum(axis=0)

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        n = self.members
        # verdict is asked again and again during a live run: read the counts, never swap them
        present, near = (self.moving_present, self.moving_near) if self.moving_present.sum() > 0 else \
            (self.present, self.near)
        share = np.divide(near, present, out=np.zeros_like(near), where=present > 0)
        ok = share >= 0.6
        k = int(ok.sum())
        text = f"{k}/{n} kept within {self.claim.distance or 3.0:g} m of them"
        if 1 < self.cols.size <= CHAIN_MAX:
            text += f" or {CHAIN_LINK:g} m of one who is"
        if share.size:
            text += f" ({float(share.mean()):.0%} of the time" + (" they walked)" if self.moving_present.sum() else ")")
        return (HOLDS if k >= _need(self.claim, n) else FAILS), text


# the robot's own claims ---------------------------------------------------------------------------

def _robot_driving(trail: _Trail) -> int:
    """1 when the robot is still driving at the end of the frames: it went ON_THE_WAY_WALKED over the last
    stretch and is moving in its last second (one parked at the far end after a drive is not)."""
    if not trail.walking(np.ones(1, dtype=bool)):
        return 0
    samples = [(t, p) for t, p in trail.samples if t >= trail.samples[-1][0] - 1.0]
    if len(samples) < 2:
        return 0
    (t0, p0), (t1, p1) = samples[0], samples[-1]
    speed = float(np.hypot(*(p1[0] - p0[0]))) / max(t1 - t0, 1e-6)
    return 1 if speed >= ROBOT_MOVING else 0


class _RobotPlaceProbe(_Probe):
    """robot_reach / robot_via: the robot at a place at some time; robot_stay: there nearly all the time
    (with asked seconds, nearly all of them from its arrival, and the run must cover them)."""

    from_elsewhere = True  # a robot_via counts once it came to the place from elsewhere

    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        self.first = math.inf
        self.frames = 0
        self.there = 0
        self.seen_robot = False
        self.last_t = 0.0
        self.trail = _Trail()  # where the robot drove over the run's last stretch: still on its way?
        self.arrivals = Arrivals(1)

    def add(self, f: _Frames) -> None:
        if f.robot is None:
            return
        self.seen_robot = True
        if self.claim.kind != "robot_stay" and math.isinf(self.first):
            self.trail.add(f.t, f.robot[:, None, :2])
        inside = self.at_place(f.robot[:, None, :2])[:, 0]
        if self.claim.kind == "robot_reach" and self.claim.needs_seconds or \
                self.claim.kind == "robot_via" and self.from_elsewhere and self.claim.zone is None:
            # a drive there, not its start ("start in ..." needs no time): arriving from elsewhere (arrival);
            # "passes the desk" too: setting off at the desk is not passing it. A room is passed through from
            # inside it as well ("patrols the corridor" sets off in the corridor and drives along it)
            inside = self.arrivals.arrived(inside[:, None], np.ones((inside.size, 1), dtype=bool))[:, 0]
        if inside.any() and math.isinf(self.first):
            self.first = float(f.t[np.argmax(inside)])
        self.last_t = max(self.last_t, float(f.t[-1]))
        counted = np.ones(inside.size, dtype=bool)
        if self.claim.kind == "robot_stay" and self.claim.seconds:
            # "waits there for two minutes": only the asked window from its arrival is judged
            counted = (f.t >= self.first) & (f.t < self.first + self.claim.seconds)
        self.frames += int(counted.sum())
        self.there += int((inside & counted).sum())

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        if not self.seen_robot:
            return FAILS, "no robot in the run"
        if self.claim.kind == "robot_stay":
            return self._stay()
        verb = "passed through" if self.claim.kind == "robot_via" else "reached"
        if math.isinf(self.first):
            if self.arrivals.started_there():
                return FAILS, f"it started at {self.where()} and never came to it from elsewhere"
            return FAILS, f"never {verb.split()[0]} {self.where()}" if verb == "reached" else \
                f"never passed through {self.where()}"
        return HOLDS, f"{verb} {self.where()} at {_when(self.first)}"

    def still_on_the_way(self) -> int:
        # a robot slowed by the people it leads or drives through, still driving when the run ended
        if self.claim.kind == "robot_stay" or not math.isinf(self.first):
            return 0
        return _robot_driving(self.trail)

    def _stay(self) -> tuple[str, str]:
        asked = self.claim.seconds
        if asked and math.isinf(self.first):
            return FAILS, f"never got to {self.where()}"
        share = self.there / self.frames if self.frames else 0.0
        if not asked:
            return (HOLDS if share >= STAY_SHARE else FAILS), f"at {self.where()} {share:.0%} of the run"
        stayed = self.there * self.checker.sample_dt
        text = (f"at {self.where()} {share:.0%} of the time from {_when(self.first)} "
                f"({stayed:.0f} s of the {asked:g} s asked)")
        if share < STAY_SHARE:
            return FAILS, text
        if self.last_t + 1e-6 < self.first + asked - self.checker.sample_dt:
            # it was there all the run had, but the run ended before the asked wait did: not a ✓ yet
            return UNCHECKED, text + f"; the run ended at {_when(self.last_t)}: run it longer"
        return HOLDS, text


class _RobotCrossProbe(_RobotPlaceProbe):
    """robot_via of a robot asked to cross a zone ("the robot crosses the waiting room"): one visit that
    begins at the zone's edge (it came in, or set off by a wall) and goes a good way across (half the zone's
    width, out of it or to its goal inside: "crosses the hall to the information desk"); setting off from
    the middle and driving out by the nearest door is half a crossing."""

    from_elsewhere = False  # it may set off by a wall inside the zone: the crossing is judged from its edge

    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        own = checker.world.zone(claim.zone or "").polygon
        self.edge_line = own.boundary
        rect = own.minimum_rotated_rectangle
        xs, ys = rect.exterior.coords.xy
        sides = [math.dist((xs[i], ys[i]), (xs[i + 1], ys[i + 1])) for i in range(2)]
        self.width = min(sides) if min(sides) > 0 else max(sides)
        self.edge = max(CROSS_EDGE, 0.25 * self.width)
        self.visit_from: tuple[float, float] | None = None  # where the current visit began
        self.from_edge = False
        self.last_in: tuple[float, float] | None = None
        self.was_inside: bool | None = None
        self.best = 0.0  # the longest crossing seen, metres between its ends
        self.half: tuple[float, float] | None = None  # (metres from the edge where it began, metres driven)

    def _to_edge(self, xy: tuple[float, float]) -> float:
        return float(self.edge_line.distance(shapely.Point(xy)))

    def add(self, f: _Frames) -> None:
        super().add(f)
        if f.robot is None:
            return
        inside = self.at_place(f.robot[:, None, :2])[:, 0]
        for k in range(inside.size):
            xy = (float(f.robot[k, 0]), float(f.robot[k, 1]))
            if inside[k] and not self.was_inside:
                self.visit_from = xy
                # it came in through the boundary, or it sets off inside: at the edge only if near a wall
                self.from_edge = self.was_inside is False or self._to_edge(xy) <= self.edge
            elif not inside[k] and self.was_inside:
                self._end()
            if inside[k]:
                self.last_in = xy
            self.was_inside = bool(inside[k])

    def _end(self) -> None:
        if self.visit_from is None or self.last_in is None:
            return
        apart = math.dist(self.visit_from, self.last_in)
        if self.from_edge:
            self.best = max(self.best, apart)
        elif self.half is None or apart > self.half[1]:
            self.half = (self._to_edge(self.visit_from) if not self.from_edge else 0.0, apart)
        self.visit_from = None

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        if not self.seen_robot:
            return FAILS, "no robot in the run"
        if math.isinf(self.first):
            return FAILS, f"never passed through {self.where()}"
        best, half = self.best, self.half
        if self.was_inside and self.visit_from is not None and self.last_in is not None:
            # still inside at the end of the run (at its goal there, or on its way)
            apart = math.dist(self.visit_from, self.last_in)
            if self.from_edge:
                best = max(best, apart)
            elif half is None or apart > half[1]:
                half = (self._to_edge(self.visit_from) if not self.from_edge else 0.0, apart)
        need = CROSS_APART * self.width
        if best >= need:
            return HOLDS, f"crossed {self.where()} ({best:.0f} m from its edge; it is {self.width:.0f} m wide)"
        if half is not None and half[0] > 0.0:
            return FAILS, (f"set off inside {self.where()}, {half[0]:.1f} m from its edge, and drove {half[1]:.0f} m "
                           f"in it: not across it ({self.width:.0f} m wide)")
        text = f"in {self.where()} from {_when(self.first)}, but never across it from its edge"
        return FAILS, text + (f" (at most {max(best, half[1] if half else 0.0):.0f} m of the {need:.0f} m asked)")


class _RobotPatrolProbe(_Probe):
    """The robot goes to the far end of its round and comes back to where it started."""

    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        self.start: np.ndarray | None = None
        self.far_at = math.inf
        self.back_at = math.inf
        self.trail = _Trail()

    def add(self, f: _Frames) -> None:
        if f.robot is None:
            return
        xy = f.robot[:, :2]
        self.trail.add(f.t, xy[:, None, :])
        if self.start is None:
            self.start = xy[0].copy()
        far = self.at_place(xy[:, None, :])[:, 0]
        if math.isinf(self.far_at) and far.any():
            self.far_at = float(f.t[np.argmax(far)])
        if not math.isinf(self.far_at) and math.isinf(self.back_at):
            home = (np.hypot(xy[:, 0] - self.start[0], xy[:, 1] - self.start[1]) <= PATROL_RADIUS) & (f.t > self.far_at)
            if home.any():
                self.back_at = float(f.t[np.argmax(home)])

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        if self.start is None:
            return FAILS, "no robot in the run"
        if math.isinf(self.far_at):
            return FAILS, f"never reached the far end of its round ({self.where()})"
        if math.isinf(self.back_at):
            return FAILS, f"reached {self.where()} at {_when(self.far_at)} but did not come back"
        return HOLDS, f"went to {self.where()} ({_when(self.far_at)}) and back ({_when(self.back_at)})"

    def still_on_the_way(self) -> int:
        # out to the far end or back, slowed by people, and still driving when the run ended
        return 0 if not math.isinf(self.back_at) else _robot_driving(self.trail)


class _RobotPassesProbe(_Probe):
    """robot_passes ("the robot drives through the queue", "threads its way through the crowd of visitors in
    the waiting room"): the robot inside the place, within `distance` of one of the people there while they
    are there (in a queue: someone who has joined it; passing the counter before they queue is no passing)."""

    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        self.partner_cols = self.checker._cols(self.claim.partners)
        self.t: list[np.ndarray] = []  # the frames the robot was in the place...
        self.d: list[np.ndarray] = []  # ...and its distance to each of them then

    def add(self, f: _Frames) -> None:
        if f.robot is None or not self.partner_cols.size:
            return
        partners = f.pos[:, self.partner_cols]
        d = np.hypot(partners[..., 0] - f.robot[:, 0:1], partners[..., 1] - f.robot[:, 1:2])
        inside = self.at_place(f.robot[:, None, :2])[:, 0]
        if self.claim.low is not None:  # past them: the people standing there (one served walks off past it)
            speed = np.hypot(f.vel[:, self.partner_cols, 0], f.vel[:, self.partner_cols, 1])
            d = np.where(np.nan_to_num(speed, nan=np.inf) < _RobotBesideProbe.STANDING, d, np.inf)
        self.t.append(f.t[inside])
        self.d.append(np.where(np.isfinite(d[inside]), d[inside], np.inf))

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        n = int(self.partner_cols.size)
        t = np.concatenate(self.t) if self.t else np.zeros(0)
        d = np.concatenate(self.d) if self.d else np.zeros((0, n))
        there = np.zeros(n)  # from when each of them is there
        if self.claim.place is not None:  # people who queue there: from each one's join on
            for j, agent in enumerate(self.claim.partners[:n]):
                joins = [e.t for e in events.get(agent, ()) if e.kind == "queue_join" and e.detail == self.claim.place]
                there[j] = min(joins) if joins else math.inf
            if np.isinf(there).all():
                return FAILS, f"nobody queued at {self.claim.place} for it to pass"
        d = np.where(t[:, None] >= there[None, :], d, np.inf)
        reach = self.claim.distance or 2.0
        if self.claim.low is not None and self.claim.place is not None:
            # past a queue: the people in it, from their join until served (then they step aside, off it)
            served = np.full(n, np.inf)
            for j, agent in enumerate(self.claim.partners[:n]):
                done = [e.t for e in events.get(agent, ()) if e.kind == "queue_served" and e.detail == self.claim.place]
                served[j] = min(done) if done else math.inf
            d = np.where(t[:, None] < served[None, :], d, np.inf)
        if self.claim.low is not None:  # "drives past them": beside them, one claim (generation/past_queue.py)
            return _beside_verdict(self.claim, t, d, reach, checker.t_end)
        near = np.flatnonzero((d <= reach).any(axis=1)) if d.size else np.zeros(0, dtype=int)
        who = "of someone in the queue" if self.claim.place is not None else "of them"
        if near.size:
            return HOLDS, f"came within {reach:g} m {who} in {self.claim.zone} at {_when(float(t[near[0]]))}"
        text = f"never within {reach:g} m {who} in {self.claim.zone}"
        if d.size and np.isfinite(d).any():
            k = int(np.argmin(d.min(axis=1)))
            text += f"; closest {float(d[k].min()):.1f} m at {_when(float(t[k]))}"
        return FAILS, text


def _beside_verdict(claim: Claim, t: np.ndarray, d: np.ndarray, reach: float, t_end: float) -> tuple[str, str]:
    """robot_passes said "past them": the nearest it came to one of them while they were there, within
    `reach` (it did pass them) and no nearer than `claim.low` (beside them, not into them)."""
    low = float(claim.low or 0.0)
    who = f"someone standing in the queue at {claim.place}" if claim.place is not None else f"one of them in {claim.zone}"
    if not d.size or not np.isfinite(d).any():
        return FAILS, f"never passed them: the robot was never in {claim.zone} while they were there"
    k = int(np.argmin(d.min(axis=1)))
    j = int(np.argmin(d[k]))
    closest = float(d[k, j])
    agent = claim.partners[j] if j < len(claim.partners) else j
    at = f"{closest:.2f} m from {who} (agent {agent} at {_when(float(t[k]))})"
    if closest > reach:
        return FAILS, f"never passed them: the nearest it came was {at}, {reach:g} m or nearer asked"
    if closest < low:
        return FAILS, f"went into them, not beside them: {at}; {low:g} m or more asked"
    text = f"passed beside them: nearest {at}, between {low:g} and {reach:g} m"
    if t.size and float(t[-1]) >= t_end - 0.5 and t_end < (claim.needs_seconds or 0.0):
        # still among them when a run shorter than its way ended: it may yet go into them
        return UNCHECKED, f"{text} so far; the robot was still in {claim.zone} when the run ended: run it longer"
    return HOLDS, text


class _RobotBesideProbe(_Probe):
    """robot_beside ("the robot passes the ticket office" where people queue): it passes the people standing
    there beside them, never within `distance` of one of them while they stand still (generation/beside_queue.py)."""

    STANDING = 0.2  # m/s: slower than this someone is standing (in a queue, at a counter)

    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        self.partner_cols = self.checker._cols(self.claim.partners)
        self.closest = math.inf
        self.at = (0.0, -1)
        self.seen_robot = False

    def add(self, f: _Frames) -> None:
        if f.robot is None or not self.partner_cols.size:
            return
        self.seen_robot = True
        p = f.pos[:, self.partner_cols]
        speed = np.hypot(f.vel[:, self.partner_cols, 0], f.vel[:, self.partner_cols, 1])
        d = np.hypot(p[..., 0] - f.robot[:, 0:1], p[..., 1] - f.robot[:, 1:2])
        d = np.where(np.isfinite(d) & (np.nan_to_num(speed, nan=np.inf) < self.STANDING), d, np.inf)
        if not np.isfinite(d).any():
            return
        k = int(np.argmin(d))
        row, col = divmod(k, d.shape[1])
        if float(d[row, col]) < self.closest:
            self.closest = float(d[row, col])
            self.at = (float(f.t[row]), int(self.checker.ids[self.partner_cols[col]]))

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        if not self.seen_robot:
            return FAILS, "no robot in the run"
        if not math.isfinite(self.closest):
            return HOLDS, f"nobody stood still at {self.claim.place} while the robot was in the run"
        reach = self.claim.distance or 0.8
        text = (f"closest to someone standing at {self.claim.place}: {self.closest:.2f} m (agent {self.at[1]} at "
                f"{_when(self.at[0])}; {reach:g} m or more asked)")
        return (HOLDS if self.closest >= reach else FAILS), text


class _RobotFollowPersonProbe(_Probe):
    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        self.partner_cols = self.checker._cols(self.claim.partners)
        self.frames = 0
        self.near = 0

    def add(self, f: _Frames) -> None:
        if f.robot is None or not self.partner_cols.size:
            return
        partners = f.pos[:, self.partner_cols]
        d = np.hypot(partners[..., 0] - f.robot[:, 0:1], partners[..., 1] - f.robot[:, 1:2])
        d = np.where(np.isfinite(d), d, np.inf).min(axis=1)
        present = np.isfinite(d)
        self.frames += int(present.sum())
        self.near += int((present & (d <= (self.claim.distance or 3.0))).sum())

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        share = self.near / self.frames if self.frames else 0.0
        return (HOLDS if share >= FOLLOW_SHARE else FAILS), \
            f"within {self.claim.distance or 3.0:g} m of them {share:.0%} of the time"


class _RobotErrandProbe(_Probe):
    """robot_pickup / robot_dropoff: the two legs of the robot's errand (analysis/robot_errand.py)."""

    def __init__(self, claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int) -> None:
        super().__init__(claim, checker, cols, members)
        self.track = StopTrack(lambda p: self.at_place(p[:, None, :])[:, 0], claim.seconds or 0.0, checker.sample_dt)
        first = next((c for c in checker.planned.robot.claims if c.kind == "robot_pickup"), None) \
            if claim.kind == "robot_dropoff" and checker.planned.robot is not None else None
        self.pickup = _RobotErrandProbe(first, checker, cols, members) if first is not None else None
        self.seen_robot = False

    def add(self, f: _Frames) -> None:
        if f.robot is None:
            return
        self.seen_robot = True
        after = 0.0
        if self.pickup is not None:
            self.pickup.add(f)
            after = self.pickup.track.done
            if math.isinf(after):
                return
        self.track.add(f.t, f.robot, errand_speeds(f.robot, f.robot_vel, f.t), after)

    def verdict(self, checker: OutcomeChecker, events: dict[int, list[SimEvent]]) -> tuple[str, str]:
        if not self.seen_robot:
            return FAILS, "no robot in the run"
        if self.claim.kind == "robot_pickup":
            ok, text = pickup_verdict(self.track, self.where())
        else:
            done = self.pickup.track.done if self.pickup is not None else None
            ok, text = dropoff_verdict(self.track, self.where(), done,
                                       self.pickup.where() if self.pickup is not None else None)
        return (HOLDS if ok else FAILS), text


_PROBES: dict[str, type[_Probe]] = {
    "count": _CountProbe, "start": _StartProbe, "reach": _ReachProbe, "stay": _StayProbe, "wander": _WanderProbe,
    "move": _MoveProbe, "leave": _LeaveProbe, "keep_out": _KeepOutProbe, "pace": _PaceProbe, "queue": _QueueProbe,
    "converse": _ConverseProbe,
    "evacuate": _EvacuateProbe, "follow_person": _FollowPersonProbe, "robot_follow": _RobotFollowProbe,
    "robot_approach": _RobotApproachProbe, "robot_block": _RobotBlockProbe, "robot_avoid": _RobotAvoidProbe,
    "robot_look": _RobotLookProbe, "robot_reach": _RobotPlaceProbe, "robot_via": _RobotPlaceProbe,
    "robot_stay": _RobotPlaceProbe, "robot_patrol": _RobotPatrolProbe,
    "robot_follow_person": _RobotFollowPersonProbe, "robot_passes": _RobotPassesProbe,
    "robot_beside": _RobotBesideProbe,
    "robot_pickup": _RobotErrandProbe, "robot_dropoff": _RobotErrandProbe,
}


def _make_probe(claim: Claim, checker: OutcomeChecker, cols: np.ndarray, members: int,
                robot_row: bool = False) -> _Probe | None:
    kind = _RobotKeepOutProbe if robot_row and claim.kind == "keep_out" else _PROBES.get(claim.kind)
    if kind is None:
        return None
    if claim.status == FAILS and claim.kind != "count":
        return None  # the plan already contradicts it: ✗ stays, with its reason
    robot = checker.planned.robot
    # "drives through the queue to the cafeteria": what it goes through is the people (robot_passes), in and
    # out of their room by whichever door; a room it goes through for no one is crossed
    passed = {c.zone for c in robot.claims if c.kind == "robot_passes"} if robot is not None else set()
    crossing = robot is not None and robot.task == "cross" and claim.zone not in passed \
        or claim.asked.startswith("cross|")
    if claim.kind == "robot_via" and claim.point is None and claim.zone is not None and crossing:
        return _RobotCrossProbe(claim, checker, cols, members)
    return kind(claim, checker, cols, members)
