"""Scoring a bundle's grounding report against outcomes written by hand (eval/grounding/suite.yaml).

For every case the suite says, per group of people the sentence describes, what a person reading the
sentence expects them to do (queue at the pharmacy counter, reach ward a, leave through the fire exit,
follow the robot, walk slowly), and what the robot should do. The hand outcomes are measured on the
bundle's run with the same measuring code as the report (analysis/outcomes.py), but with the places,
kinds and people the suite gives, not those the scenario planned: a scenario that read the sentence
wrong, or did something else, fails them however sure of itself its report is.

    report ✓ + hand outcome fails  -> a false ✓ (must never happen)
    report ✗ + hand outcome holds  -> a false ✗
    hand outcome holds             -> the group's outcome holds (the scenario does what was asked)

Suite format (one case):

    - id: station-queue-robot
      world: station
      preset: queuing
      seed: 3
      seconds: 150                 # how long the run is
      prompt: twelve travellers queue at the ticket office while a robot crosses the ticket hall to the platforms
      groups:
        - who: travellers          # words of the group as the sentence says it (matched to the report's groups)
          count: 12                # optional: people in the run
          expect: {queue: ticket_office}
      robot: {reach: [platform_1, platform_2]}   # optional; a list is any one of them

Outcome kinds (`expect`): reach, stay, queue, wander, leave, start, keep_out (a place or a list of places);
converse (true); evacuate (any, or exit names); move (true); pace (slow, fast); follow (the `who` of another
group: close to them while they walk); for (seconds: a stay or wander judged over that long after arriving,
a reach counted from then, as in "waits for a minute and then walks on"); robot (follow,
approach, block, avoid, look: one look of a second at least, stare: facing it most of the time it is near); at
(a place: where the robot reaction happens, for block and approach: "blocks the robot at the gateline" is
{robot: block, at: gateline}, a block elsewhere does not count; a door or thing counts 3 m round). The robot's: reach, via, cross (from its edge half its width across), stay, patrol
(a place), follow, passes (words of a group) and keep_out (a place: its trajectory never there).
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING

from grove_tui.analysis.metrics import iter_trajectory_chunks
from grove_tui.analysis.outcomes import GLANCE_SECONDS, OutcomeChecker
from grove_tui.errors import SuiteError
from grove_tui.jsontypes import JSONObject
from grove_tui.scenario.events import read_events
from grove_tui.scenario.report import FAILS, HOLDS, Claim, GroundingReport, GroupGrounding, RobotGrounding

from grove_tui.world import Door, Entity, World, Zone

if TYPE_CHECKING:
    from grove_tui.scenario.model import Scenario

GROUP_OUTCOMES = ("reach", "stay", "queue", "wander", "leave", "start", "converse", "evacuate", "move", "pace",
                  "robot", "keep_out", "follow", "for", "at")
ROBOT_OUTCOMES = ("reach", "via", "cross", "stay", "patrol", "follow", "passes", "keep_out")
REACTIONS = ("follow", "approach", "block", "avoid", "look", "stare")
BLOCK_AT_RADIUS = 3.0  # metres round a door or thing that count as blocking "at" it
# Hand thresholds: what a reader of the sentence would accept as done (the same measures as the report's).
REACTION_DISTANCE = {"follow": 3.0, "approach": 2.5, "block": 2.5, "avoid": 6.0, "look": 10.0, "stare": 10.0}
PACE_BANDS = {"slow": (0.2, 0.85), "fast": (1.15, 3.0)}  # times the preset's normal walking speed


@dataclass(frozen=True)
class ExpectedGroup:
    who: str
    expect: tuple[tuple[str, object], ...]  # (kind, value as the suite gives it) in the suite's order
    count: int | None = None


@dataclass(frozen=True)
class GroundingCase:
    id: str
    world: str
    preset: str
    prompt: str
    seed: int
    seconds: float
    groups: tuple[ExpectedGroup, ...]
    robot: tuple[tuple[str, object], ...] = ()
    tags: tuple[str, ...] = ()


def load_suite(path: str | Path) -> list[GroundingCase]:
    """The suite's cases, every problem named with the case it is in."""
    import yaml

    path = Path(path)
    try:
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
    except (OSError, yaml.YAMLError) as exc:
        raise SuiteError(f"{path}: cannot read the suite: {exc}") from None
    cases_data = data.get("cases") if isinstance(data, Mapping) else None
    if not isinstance(cases_data, list) or not cases_data:
        raise SuiteError(f"{path}: expected a mapping with a non-empty 'cases' list")
    cases: list[GroundingCase] = []
    seen: set[str] = set()
    for index, raw in enumerate(cases_data):
        where = f"{path}: cases[{index}]"
        if not isinstance(raw, Mapping):
            raise SuiteError(f"{where}: expected a mapping")
        try:
            case_id = str(raw["id"])
            groups = tuple(_expected_group(g, f"{where} ({case_id}).groups[{k}]")
                           for k, g in enumerate(raw.get("groups") or ()))
            robot = _outcomes(raw.get("robot") or {}, ROBOT_OUTCOMES, f"{where} ({case_id}).robot")
            case = GroundingCase(case_id, str(raw["world"]), str(raw["preset"]), str(raw["prompt"]),
                                 int(raw.get("seed", 0)), float(raw.get("seconds", 90.0)), groups, robot,
                                 tuple(str(t) for t in raw.get("tags", ())))
        except KeyError as exc:
            raise SuiteError(f"{where}: missing key {exc.args[0]!r}") from None
        except (TypeError, ValueError) as exc:
            raise SuiteError(f"{where}: {exc}") from None
        if case.id in seen:
            raise SuiteError(f"{where}: id {case.id!r} is used twice")
        if not case.groups and not case.robot:
            raise SuiteError(f"{where} ({case.id}): expects nothing")
        seen.add(case.id)
        cases.append(case)
    return cases


def _expected_group(data: object, where: str) -> ExpectedGroup:
    if not isinstance(data, Mapping) or "who" not in data:
        raise SuiteError(f"{where}: expected a mapping with 'who' and 'expect'")
    count = data.get("count")
    return ExpectedGroup(str(data["who"]), _outcomes(data.get("expect") or {}, GROUP_OUTCOMES, where),
                         None if count is None else int(count))


def _outcomes(data: object, kinds: Sequence[str], where: str) -> tuple[tuple[str, object], ...]:
    if not isinstance(data, Mapping):
        raise SuiteError(f"{where}: expected a mapping of outcomes ({', '.join(kinds)})")
    unknown = [k for k in data if k not in kinds]
    if unknown:
        raise SuiteError(f"{where}: unknown outcome(s) {unknown}; known: {', '.join(kinds)}")
    if "robot" in data and data["robot"] not in REACTIONS:
        raise SuiteError(f"{where}: robot: {data['robot']!r} is not one of {', '.join(REACTIONS)}")
    return tuple((str(k), v) for k, v in data.items())


# ---- scoring one bundle --------------------------------------------------------------------------

@dataclass
class GroupScore:
    who: str
    matched: str | None  # the report group's label it was matched to; None: the scenario has no such group
    report: str  # the report's verdict for that group: holds / fails / unchecked / planned / missing
    outcome: bool  # the hand outcome holds in the run
    evidence: list[str] = field(default_factory=list)

    @property
    def false_tick(self) -> bool:
        return self.report == HOLDS and not self.outcome

    @property
    def false_cross(self) -> bool:
        return self.report == FAILS and self.outcome


@dataclass
class CaseScore:
    case: GroundingCase
    groups: list[GroupScore] = field(default_factory=list)
    extra_ticks: list[str] = field(default_factory=list)  # report groups ✓ that the sentence does not have
    error: str = ""
    seconds: float = 0.0  # wall time of generate + simulate + score

    def to_dict(self) -> JSONObject:
        return {"id": self.case.id, "world": self.case.world, "preset": self.case.preset, "error": self.error,
                "seconds": round(self.seconds, 2), "extra_ticks": self.extra_ticks,
                "groups": [{"who": g.who, "matched": g.matched, "report": g.report, "outcome": g.outcome,
                            "evidence": g.evidence} for g in self.groups]}


def score_bundle(case: GroundingCase, bundle: str | Path) -> CaseScore:
    """The bundle's checked report (grounding.json) against the case's hand outcomes on the same run."""
    from grove_tui.scenario.bundle import load_bundle_world, load_scenario

    bundle = Path(bundle)
    scenario = load_scenario(bundle)
    world = load_bundle_world(bundle, scenario)
    path = bundle / "grounding.json"
    if not path.is_file():
        raise SuiteError(f"{bundle}: no grounding.json (simulate the bundle first)")
    report = GroundingReport.from_dict(json.loads(path.read_text(encoding="utf-8")))
    pairs = match_groups(case.groups, report.groups)
    speed = _walking_speed(scenario)
    hand_groups: list[GroupGrounding] = []
    for expected, found in pairs:
        members = found.members if found is not None else ()
        hand_groups.append(GroupGrounding(expected.who, found.label if found else "-",
                                          tuple(_hand_claims(expected, world, speed, pairs)), members))
    robot_claims = tuple(_robot_claims(case.robot, world, scenario, report, pairs))
    hand = GroundingReport(case.prompt, tuple(hand_groups),
                           robot=RobotGrounding("expected", "", robot_claims) if robot_claims else None)
    checker = OutcomeChecker(hand, scenario, world)
    ids, _groups, chunks = iter_trajectory_chunks(bundle / "trajectories.csv")
    checker.set_ids(ids)
    for chunk in chunks:
        checker.add(chunk)
    events = read_events(bundle / "events.jsonl") if (bundle / "events.jsonl").exists() else []
    measured = checker.result(events)
    score = CaseScore(case)
    for (expected, found), hand_group in zip(pairs, measured.groups):
        outcome, evidence = _group_outcome(expected, hand_group)
        if found is None:
            outcome, evidence = False, ["the scenario has no group for them"] + evidence
        score.groups.append(GroupScore(expected.who, found.label if found else None,
                                       found.status if found else "missing", outcome, evidence))
    if measured.robot is not None:
        outcome, evidence = _alternatives(list(measured.robot.claims))
        asked_robot = report.robot.status if report.robot is not None and report.robot.claims else "missing"
        score.groups.append(GroupScore("the robot", "robot" if report.robot else None, asked_robot, outcome, evidence))
    matched = {id(found) for _, found in pairs if found is not None}
    score.extra_ticks = [g.who for g in report.groups if id(g) not in matched and g.status == HOLDS]
    return score


def match_groups(expected: Sequence[ExpectedGroup],
                 found: Sequence[GroupGrounding]) -> list[tuple[ExpectedGroup, GroupGrounding | None]]:
    """Each expected group with the report group whose words it shares most (then the same count);
    a report group is matched at most once. One of each: they are each other's."""
    from grove_tui.language.tokens import lemma, words

    def bag(text: str) -> set[str]:
        return {lemma(w) for w in words(text.replace("_", " "))} - {"a", "an", "the", "of", "and", "some", "few"}

    if len(expected) == 1 and len(found) == 1:
        return [(expected[0], found[0])]
    options = []
    for i, e in enumerate(expected):
        for j, g in enumerate(found):
            shared = len(bag(e.who) & (bag(g.who) | bag(g.label)))
            if shared:
                options.append((-shared, 0 if e.count == len(g.members) else 1, i, j))
    options.sort()
    chosen: dict[int, int] = {}
    taken: set[int] = set()
    for _, _, i, j in options:
        if i not in chosen and j not in taken:
            chosen[i] = j
            taken.add(j)
    return [(e, found[chosen[i]] if i in chosen else None) for i, e in enumerate(expected)]


def _walking_speed(scenario: Scenario) -> float:
    from grove_tui.generation.presets import load_preset

    try:
        return float(load_preset(scenario.preset).max_vel)
    except Exception:
        return 1.0


def _names(value: object) -> list[str]:
    return [str(v) for v in value] if isinstance(value, (list, tuple)) else [str(value)]


def _place(kind: str, name: str, world: World, n: int, stay: bool = False) -> Claim:
    obj = world.find(name)  # a WorldError for a suite naming no place of the world
    if isinstance(obj, Entity):
        point = obj.interaction_point
    elif isinstance(obj, Door):
        point = obj.inward_point(0.6)
    else:
        return Claim(kind, name, "expected", zone=obj.name, place=name)
    radius = (2.0 if stay else 1.0) + 0.5 * math.sqrt(max(n, 1))
    return Claim(kind, name, "expected", place=name, point=(float(point[0]), float(point[1])), radius=radius)


def _zone_of(world: World, name: str) -> str:
    """The zone a place is in (a zone is its own)."""
    obj = world.find(name)
    return (obj.zone if not isinstance(obj, Zone) else None) or obj.name


# Each hand outcome becomes one or more claims; a list of places gives alternatives (any of them).
def _hand_claims(expected: ExpectedGroup, world: World, speed: float,
                 pairs: Sequence[tuple[ExpectedGroup, GroupGrounding | None]] = ()) -> list[Claim]:
    n = expected.count or 1
    claims: list[Claim] = []
    if expected.count is not None:
        claims.append(Claim("count", str(expected.count), "expected"))
    # "waits in the kitchen for a minute and then walks on": the stay or wander is judged over those
    # seconds after arriving, and the reach counts from then (`for: 60`)
    asked_for = next((float(v) for k, v in expected.expect if k == "for"), None)  # type: ignore[arg-type]
    for kind, value in expected.expect:
        tag = f"{kind}|"
        if kind in ("reach", "stay", "start", "leave", "wander", "keep_out"):
            for name in _names(value):
                claim = _place(kind, name, world, n, stay=kind == "stay")
                if kind == "keep_out":
                    claim = replace(claim, share=1.0)
                if kind in ("wander", "leave") and claim.zone is None:
                    claim = Claim(kind, name, "expected", zone=_zone_of(world, name))
                if kind == "start":
                    claim = Claim("start", name, "expected", zone=claim.zone or _zone_of(world, name), share=1.0)
                claims.append(Claim(claim.kind, tag + claim.asked, claim.plan, zone=claim.zone, place=claim.place,
                                    point=claim.point, radius=claim.radius, share=claim.share,
                                    seconds=asked_for if kind in ("stay", "wander", "reach") else None))
        elif kind == "queue":
            for name in _names(value):
                obj = world.find(name)
                # "sit for a minute before queuing" (`for: 60`): only joins after the wait count
                if isinstance(obj, Entity):
                    claims.append(Claim("queue", tag + name, "expected", place=name, zone=obj.zone, seconds=asked_for))
                else:
                    claims.append(Claim("queue", tag + name, "expected", zone=_zone_of(world, name), seconds=asked_for))
        elif kind == "converse":
            claims.append(Claim("converse", tag + "talk", "expected"))
        elif kind == "evacuate":
            exits = () if value in (True, "any", None) else tuple(_names(value))
            claims.append(Claim("evacuate", tag + ("any exit" if not exits else ",".join(exits)), "expected",
                                exits=exits))
        elif kind == "move":
            claims.append(Claim("move", tag + "walk", "expected"))
        elif kind == "pace":
            low, high = PACE_BANDS[str(value)]
            claims.append(Claim("pace", tag + str(value), "expected", low=round(low * speed, 2) if value == "fast" else low,
                                high=round(high * speed, 2) if value == "slow" else high))
        elif kind == "follow":
            # they follow another group of the case (its `who`): close to them while those walk
            partners = next((found.members for other, found in pairs if found is not None and other.who == str(value)),
                            ())
            claims.append(Claim("follow_person", tag + str(value), "expected", partners=tuple(partners),
                                distance=round(3.0 + 0.5 * math.sqrt(max(n - 1, 0)), 1)))
        elif kind == "robot":
            share = 0.5 if value == "block" else 0.9
            # look: at least once, a short while (one look of GLANCE_SECONDS); stare: most of the time it is near
            claim = Claim("robot_look" if value == "stare" else f"robot_{value}", tag + str(value), "expected",
                          distance=REACTION_DISTANCE[str(value)], share=share,
                          seconds=GLANCE_SECONDS if value == "look" else None)
            at = next((str(v) for k, v in expected.expect if k == "at"), None)
            if at is not None and value in ("block", "approach"):
                there = _place("reach", at, world, n)
                claim = replace(claim, asked=claim.asked + f" at {at}", zone=there.zone if there.point is None
                                else None, place=at, point=there.point,
                                radius=max(there.radius, BLOCK_AT_RADIUS) if there.point is not None else 0.0)
            claims.append(claim)
    return claims


def _robot_claims(robot: Iterable[tuple[str, object]], world: World, scenario: Scenario, report: GroundingReport,
                  pairs: Sequence[tuple[ExpectedGroup, GroupGrounding | None]]) -> list[Claim]:
    claims: list[Claim] = []
    for kind, value in robot:
        tag = f"{kind}|"
        if kind in ("reach", "via", "cross", "stay"):
            for name in _names(value):
                # "cross|..." is checked as a crossing (outcomes._RobotCrossProbe)
                claim = _place("robot_via" if kind == "cross" else f"robot_{kind}", name, world, 1)
                claims.append(Claim(claim.kind, tag + name, "expected", zone=claim.zone, place=claim.place,
                                    point=claim.point, radius=1.5 if claim.point else 0.0))
        elif kind == "patrol":
            # it patrols the place: it is there, drives to the far end of its round and comes back
            for name in _names(value):
                claim = _place("robot_via", name, world, 1)
                claims.append(Claim("robot_via", tag + name, "expected", zone=claim.zone, point=claim.point,
                                    radius=1.5 if claim.point else 0.0))
                goal = scenario.robot.goal if scenario.robot is not None else (0.0, 0.0)
                claims.append(Claim("robot_patrol", tag + name, "expected", point=goal, radius=1.5))
        elif kind == "follow":
            partners: tuple[int, ...] = ()
            for expected, found in pairs:
                if found is not None and expected.who == str(value):
                    partners = found.members
            claims.append(Claim("robot_follow_person", tag + str(value), "expected", partners=partners, distance=3.0))
        elif kind == "passes":
            claims.append(_passes_claim(tag, str(value), world, pairs))
        elif kind == "keep_out":
            # "..., avoiding the cafeteria": the robot never there (outcomes._RobotKeepOutProbe); a list, as elsewhere
            for name in _names(value):
                claim = _place("keep_out", name, world, 1)
                claims.append(Claim("keep_out", f"{tag}{name}", "expected", zone=claim.zone, place=claim.place,
                                    point=claim.point, radius=claim.radius, share=1.0))
    return claims


def _passes_claim(tag: str, who: str, world: World,
                  pairs: Sequence[tuple[ExpectedGroup, GroupGrounding | None]]) -> Claim:
    """The robot goes through a group where it stays (the group's own queue or stay place): within 2 m of one
    of them there while they are there, in a queue from each one's join on."""
    expected = next((e for e, _ in pairs if e.who == who), None)
    if expected is None:
        raise SuiteError(f"robot passes {who!r}: no group of the case has that 'who'")
    members = next((found.members for e, found in pairs if e is expected and found is not None), ())
    outcomes = dict(expected.expect)
    queue = next(iter(_names(outcomes["queue"])), None) if "queue" in outcomes else None
    stays = [n for n in _names(outcomes.get("stay") or outcomes.get("start") or "") if n]
    place = queue or (stays[0] if stays else None)
    if place is None:
        raise SuiteError(f"robot passes {who!r}: the group expects no queue, stay or start place")
    return Claim("robot_passes", tag + who, "expected", zone=_zone_of(world, place), place=queue,
                 partners=tuple(members), distance=2.0)


def _group_outcome(expected: ExpectedGroup, measured: GroupGrounding) -> tuple[bool, list[str]]:
    return _alternatives(list(measured.claims))


def _alternatives(claims: list[Claim]) -> tuple[bool, list[str]]:
    """Every outcome must hold; the alternatives of one outcome ("kind|place", from a list) any of them."""
    by_outcome: dict[str, list[Claim]] = {}
    for c in claims:
        key = c.asked.split("|", 1)[0] if "|" in c.asked else c.kind
        # robot patrol gives two claims under one outcome: both must hold
        by_outcome.setdefault(f"{key}:{c.kind}" if key == "patrol" else key, []).append(c)
    holds = True
    evidence: list[str] = []
    for outcome, options in by_outcome.items():
        ok = any(c.status == HOLDS for c in options)
        holds = holds and ok
        best = next((c for c in options if c.status == HOLDS), options[0])
        evidence.append(f"{'✓' if ok else '✗'} {best.kind} {best.asked.split('|')[-1]}: {best.evidence}")
    return holds, evidence


# ---- the figures -----------------------------------------------------------------------------------

@dataclass
class SuiteFigures:
    cases: int
    failed_cases: int
    groups: int  # expected groups and robots, over the cases that ran
    outcomes_held: int
    report_ticks: int
    false_ticks: int  # report ✓ whose hand outcome fails (extra ✓ groups counted too)
    report_crosses: int
    false_crosses: int  # report ✗ whose hand outcome holds
    unchecked: int  # report "not checked" or "planned"
    extra_ticks: int

    @property
    def held_share(self) -> float:
        return self.outcomes_held / self.groups if self.groups else 0.0

    @property
    def false_tick_share(self) -> float:
        return self.false_ticks / self.report_ticks if self.report_ticks else 0.0

    @property
    def false_cross_share(self) -> float:
        return self.false_crosses / self.report_crosses if self.report_crosses else 0.0


def figures(scores: Sequence[CaseScore]) -> SuiteFigures:
    ran = [s for s in scores if not s.error]
    groups = [g for s in ran for g in s.groups]
    extra = sum(len(s.extra_ticks) for s in ran)
    return SuiteFigures(
        cases=len(scores), failed_cases=len(scores) - len(ran), groups=len(groups) + sum(
            len(s.case.groups) + (1 if s.case.robot else 0) for s in scores if s.error),
        outcomes_held=sum(g.outcome for g in groups),
        report_ticks=sum(g.report == HOLDS for g in groups) + extra,
        false_ticks=sum(g.false_tick for g in groups) + extra,
        report_crosses=sum(g.report == FAILS for g in groups),
        false_crosses=sum(g.false_cross for g in groups),
        unchecked=sum(g.report not in (HOLDS, FAILS) for g in groups),
        extra_ticks=extra)
