"""The edit-chain set's scorer: after each step of a chain, does the scenario have the groups written
by hand, and did the follow-up leave every group it does not touch byte for byte as it was?

Chains come from `eval/refine/chains.yaml` (its header documents the format). A step is scored from
its bundle alone:
- every expected group is matched to one group of generation.json's "groups" (in order, the first
  unmatched group that agrees on every field), and no group is left over;
- label and head count (the group's members in scenario.yaml); what its tree does (the draft-form
  tree of its record: queue or converse when it has those nodes; walking to a place and staying there
  is both walking there and waiting or wandering there; following the evacuation field is evacuating
  and walking out) and where (the zone of the place that activity names; "exit" is any exit door; an
  evacuation's place is every member's exit);
  its pace (the members' speed against the preset's) and robot reaction (the members' HuNavSim
  behavior);
- the robot: none, placed, waiting in a zone, or headed for one.
A group whose expected entry is the same as at the step before is untouched: its generation.json
record, its agents' entries in scenario.yaml, its tree files and its velocity fields must be equal
to the bytes of the bundle before.
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
import yaml

from grove_tui.bt.format.manifest import NODES
from grove_tui.bt.format.xml import read_tree
from grove_tui.errors import EvalError
from grove_tui.jsontypes import Parsed
from grove_tui.scenario.bundle import load_report, load_scenario, read_bundle_text
from grove_tui.scenario.model import AgentSpec, Scenario
from grove_tui.world import World

DOES = ("queue", "wait", "wander", "converse", "walk", "evacuate")
GROUP_KEYS = ("label", "count", "does", "at", "pace", "reaction")
SLOW_BELOW, FAST_ABOVE = 0.85, 1.15  # members' speed / the preset's, for "slow" and "fast"
THRESHOLD = 0.95  # the issue's: at least 95 % of steps right


@dataclass(frozen=True)
class ExpectedGroup:
    label: str
    count: int | None
    does: str
    at: str | None = None
    pace: str = "normal"
    reaction: str = "Regular"

    def describe(self) -> str:
        text = f"{self.label} x{self.count if self.count is not None else '?'} {self.does}"
        text += f" at {self.at}" if self.at else ""
        text += f" {self.pace}" if self.pace != "normal" else ""
        return text + (f" {self.reaction}" if self.reaction != "Regular" else "")


@dataclass(frozen=True)
class ExpectedStep:
    say: str
    groups: tuple[ExpectedGroup, ...]
    robot: str | dict[str, str]  # "yes", "none", {"waits": place} or {"to": place}


@dataclass(frozen=True)
class Chain:
    id: str
    world: str
    preset: str
    seed: int
    steps: tuple[ExpectedStep, ...]


def load_chains(path: str | Path) -> list[Chain]:
    """The chains of a chains file; EvalError naming the chain and step of anything malformed."""
    path = Path(path)
    try:
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise EvalError(f"{path}: no such chains file") from None
    except yaml.YAMLError as exc:
        raise EvalError(f"{path}: not valid YAML: {exc}") from None
    if not isinstance(data, dict) or not isinstance(data.get("chains"), list):
        raise EvalError(f"{path}: expected a mapping with a `chains` list")
    chains = []
    for index, raw in enumerate(data["chains"]):
        where = f"{path}: chains[{index}]"
        try:
            steps = tuple(_step(s, f"{where}.steps[{k}]") for k, s in enumerate(raw["steps"]))
            if not 2 <= len(steps) <= 5:
                raise EvalError(f"{where}: a chain has 2 to 5 sentences, this one {len(steps)}")
            chains.append(Chain(str(raw["id"]), str(raw["world"]), str(raw["preset"]), int(raw.get("seed", 0)), steps))
        except (KeyError, TypeError, ValueError) as exc:
            raise EvalError(f"{where}: {exc!r}") from None
    ids = [c.id for c in chains]
    if len(set(ids)) != len(ids):
        raise EvalError(f"{path}: chain ids repeat: {sorted({i for i in ids if ids.count(i) > 1})}")
    return chains


def _step(raw: Parsed, where: str) -> ExpectedStep:
    groups = []
    for k, g in enumerate(raw["groups"]):
        unknown = set(g) - set(GROUP_KEYS)
        if unknown or g.get("does") not in DOES:
            raise EvalError(f"{where}.groups[{k}]: unknown keys {sorted(unknown)} or does {g.get('does')!r} "
                            f"not one of {', '.join(DOES)}")
        groups.append(ExpectedGroup(str(g["label"]), int(g["count"]) if g.get("count") is not None else None,
                                    str(g["does"]), str(g["at"]) if g.get("at") else None,
                                    str(g.get("pace", "normal")), str(g.get("reaction", "Regular"))))
    robot = raw.get("robot", "yes")
    robot = "yes" if robot is True else "none" if robot in (False, None) else robot
    return ExpectedStep(str(raw["say"]), tuple(groups), robot)


# ---- what a bundle's groups do ----------------------------------------------------------------------------

@dataclass(frozen=True)
class ActualGroup:
    index: int  # position in generation.json's "groups"
    label: str
    count: int
    activities: Mapping[str, frozenset[str]]  # what it does -> zones (and exit door names) where; main first
    pace: str
    reaction: str
    members: tuple[int, ...]

    @property
    def does(self) -> str:
        return next(iter(self.activities), "idle")

    def describe(self) -> str:
        where = "/".join(sorted(self.activities.get(self.does, ()))) or "-"
        return f"{self.label} x{self.count} {self.does} at {where} {self.pace} {self.reaction}"


@dataclass
class Bundle:
    path: Path
    scenario: Scenario
    report: Parsed  # generation.json
    groups: list[ActualGroup]


def read_bundle(path: str | Path, world: World, preset_max_vel: float) -> Bundle:
    path = Path(path)
    scenario = load_scenario(path)
    report = load_report(path)
    by_id = {a.id: a for a in scenario.agents}
    groups = []
    for index, record in enumerate(report.get("groups", ())):
        members = tuple(int(m) for m in record.get("members", ()))
        agents = [by_id[m] for m in members if m in by_id]
        activities = _activities(record.get("tree") or {}, world)
        if "evacuate" in activities:
            exits = {str(e) for e in {_exit_of(path, a) for a in agents} - {None}}
            out = frozenset(exits) | frozenset(_zone(world, e) or e for e in exits)
            activities = {"evacuate": out, "walk": out | {"exit"}}
        speeds = [a.max_vel / preset_max_vel for a in agents] or [1.0]
        speed = sum(speeds) / len(speeds)
        pace = "slow" if speed < SLOW_BELOW else "fast" if speed > FAST_ABOVE else "normal"
        reactions = {a.behavior for a in agents} or {"Regular"}
        groups.append(ActualGroup(index, str(record.get("label", "")), len(agents), activities, pace,
                                  "/".join(sorted(reactions)), members))
    return Bundle(path, scenario, report, groups)


def _activities(tree: Parsed, world: World) -> dict[str, frozenset[str]]:
    """What a draft-form tree makes its people do, each activity with the zones where; first the main one.

    Queueing and conversing are what a tree with those nodes does, nothing else. Arriving is walking:
    a tree that walks to a place and then stays there (waits, wanders in that zone) both walks there
    and waits or wanders there. Following the evacuation field is evacuating, and walking out through
    the exits it leads to (the members' exits are filled in by `read_bundle`)."""
    nodes = list(_walk(tree))
    names = [n.get("node") for n in nodes]
    if "FollowVelocityField" in names:
        return {"evacuate": frozenset(), "walk": frozenset({"exit"})}
    for node_name, does in (("Queue", "queue"), ("Converse", "converse"), ("ConversationFormation", "converse")):
        if node_name in names:
            return {does: _zones(world, [_place(nodes[names.index(node_name)])])}
    last_go = max((k for k, n in enumerate(names) if n == "GoTo"), default=-1)
    arrived = _walked_to(_place(nodes[last_go]), world) if last_go >= 0 else frozenset()
    if "Wander" in names:
        wander = _zones(world, [_place(nodes[names.index("Wander")])])
        return {"wander": wander, **({"walk": arrived} if arrived and wander <= arrived else {})}
    last_wait = max((k for k, n in enumerate(names) if n in ("Wait", "StopAndWaitTimerAction")), default=-1)
    if last_wait > last_go:
        return {"wait": arrived - {"exit"}, **({"walk": arrived} if arrived else {})}
    if last_go >= 0:
        return {"walk": arrived}
    return {"idle": frozenset()}


def _walked_to(place: str | None, world: World) -> frozenset[str]:
    """The zone of a place walked to, and "exit" with the door's name when it is an exit door."""
    zones = _zones(world, [place])
    if place is not None and place in {d.name for d in world.exits()}:
        return zones | {place, "exit"}
    return zones


def _walk(node: Parsed) -> list[Parsed]:
    out = [node]
    # a robot reaction's branch (IsRobotVisible or IsRobotClose -> reaction) is how they react, not what they do
    children = list(node.get("children") or ())
    if node.get("node") == "ReactiveFallback" and len(children) == 2 and \
            any(c.get("node") in ("IsRobotVisible", "IsRobotClose") for c in _flat(children[0])):
        children = children[1:]
    for child in children:
        out += _walk(child)
    return out


def _flat(node: Parsed) -> list[Parsed]:
    return [node] + [n for c in node.get("children") or () for n in _flat(c)]


def _place(node: Parsed) -> str | None:
    spec = NODES.get(str(node.get("node")))
    for port in spec.ports if spec is not None else ():
        if port.type == "target" and node.get(port.name):
            return str(node[port.name])
    return None


def _zone(world: World, name: str | None) -> str | None:
    if not name:
        return None
    try:
        obj = world.find(name)
    except Exception:  # noqa: BLE001 - a name the world lacks is no zone
        return None
    zone = getattr(obj, "zone", None)
    return zone if isinstance(zone, str) and zone else getattr(obj, "name", None)


def _zones(world: World, names: Sequence[str | None]) -> frozenset[str]:
    return frozenset(z for z in (_zone(world, n) for n in names) if z)


def _exit_of(path: Path, agent: AgentSpec) -> str | None:
    document = read_tree(read_bundle_text(path, agent.tree, f"agent {agent.id}'s tree"), agent.tree)
    return next((e.get("exit") for e in document.nodes() if e.id == "FollowVelocityField"), None)


# ---- scoring ----------------------------------------------------------------------------------------------

def _matches(expected: ExpectedGroup, actual: ActualGroup, world: World) -> list[str]:
    """Why an actual group is not the expected one (empty: it is)."""
    problems = []
    if expected.label != actual.label:
        problems.append(f"label {actual.label}")
    if expected.count is not None and expected.count != actual.count:
        problems.append(f"count {actual.count}")
    at = actual.activities.get(expected.does)
    if at is None:
        problems.append(f"does {actual.does}")
    elif expected.at:
        if expected.does == "evacuate":  # every member through that exit
            ok = expected.at in at and at <= {expected.at, _zone(world, expected.at)}
        elif expected.at == "exit":
            ok = "exit" in at
        else:
            ok = (_zone(world, expected.at) or expected.at) in at
        if not ok:
            problems.append(f"at {'/'.join(sorted(at)) or '-'}")
    if expected.pace != actual.pace:
        problems.append(f"pace {actual.pace}")
    if expected.reaction != actual.reaction:
        problems.append(f"reaction {actual.reaction}")
    return problems


def match_groups(expected: Sequence[ExpectedGroup], actual: Sequence[ActualGroup],
                 world: World) -> tuple[dict[int, ActualGroup], list[str]]:
    """Expected index -> the actual group it is, and the problems (missing, wrong, left over)."""
    used: set[int] = set()
    found: dict[int, ActualGroup] = {}
    problems: list[str] = []
    for i, e in enumerate(expected):
        pick = next((a for a in actual if a.index not in used and not _matches(e, a, world)), None)
        if pick is None:
            same = [a for a in actual if a.index not in used and a.label == e.label]
            near = min(same or [a for a in actual if a.index not in used], default=None,
                       key=lambda a: len(_matches(e, a, world)))
            why = f" (closest: {near.describe()}: {', '.join(_matches(e, near, world))})" if near else ""
            problems.append(f"expected {e.describe()}{why}")
            continue
        used.add(pick.index)
        found[i] = pick
    if len(actual) > len(expected):
        problems += [f"unexpected group {a.describe()}" for a in actual if a.index not in used]
    return found, problems


def robot_problems(expected: str | Mapping[str, str], scenario: Scenario, world: World) -> list[str]:
    robot = scenario.robot
    if expected == "none":
        return [] if robot is None else ["a robot is there, none was expected"]
    if robot is None:
        return ["no robot"]
    if expected == "yes":
        return []
    assert isinstance(expected, Mapping)
    if "waits" in expected:
        zone = world.zone_at(*robot.start)
        want = _zone(world, expected["waits"])
        ok = robot.start == robot.goal and zone is not None and zone.name == want
        return [] if ok else [f"the robot does not wait in {want} (start {robot.start}, goal {robot.goal})"]
    want = _zone(world, expected.get("to"))
    zone = world.zone_at(*robot.goal)
    return [] if zone is not None and zone.name == want else [f"the robot's goal is not in {want} ({robot.goal})"]


@dataclass
class StepResult:
    chain: str
    step: int
    say: str
    problems: list[str] = field(default_factory=list)
    untouched: int = 0  # groups the follow-up must leave as they were
    identical: int = 0  # of those, byte-identical
    untouched_problems: list[str] = field(default_factory=list)
    seconds: float = 0.0
    error: str = ""

    @property
    def ok(self) -> bool:
        return not self.problems and not self.error


def score_step(chain: Chain, number: int, bundle: Bundle, world: World, previous: Bundle | None = None,
               matched_before: Mapping[int, ActualGroup] | None = None) -> tuple[StepResult, dict[int, ActualGroup]]:
    """One step of a chain against its bundle (and the untouched groups against the bundle before)."""
    step = chain.steps[number]
    found, problems = match_groups(step.groups, bundle.groups, world)
    problems += robot_problems(step.robot, bundle.scenario, world)
    result = StepResult(chain.id, number, step.say, problems)
    if previous is not None and matched_before is not None:
        before_step = chain.steps[number - 1]
        taken: set[int] = set()
        claimed_old = {a.index for a in matched_before.values()}
        claimed_new = {a.index for a in found.values()}
        for i, e in enumerate(step.groups):
            # the same entry before: a group this follow-up does not touch
            j = next((k for k, b in enumerate(before_step.groups) if b == e and k not in taken), None)
            if j is None:
                continue
            taken.add(j)
            result.untouched += 1
            # a group that is not as expected is still found by its label, to check it was left alone
            old = matched_before.get(j) or _by_label(e, previous.groups, claimed_old)
            new = found.get(i) or _by_label(e, bundle.groups, claimed_new)
            if old is None or new is None:
                result.untouched_problems.append(f"{e.describe()}: not found in both bundles")
                continue
            differences = byte_differences(previous, old, bundle, new)
            if differences:
                result.untouched_problems.append(f"{e.describe()}: " + "; ".join(differences))
            else:
                result.identical += 1
    return result, found


def _by_label(expected: ExpectedGroup, groups: Sequence[ActualGroup], claimed: set[int]) -> ActualGroup | None:
    for a in groups:
        if a.index not in claimed and a.label == expected.label and expected.count in (None, a.count):
            claimed.add(a.index)
            return a
    return None


def byte_differences(before: Bundle, old: ActualGroup, after: Bundle, new: ActualGroup) -> list[str]:
    """Where an untouched group differs between two bundles: its record, agents, trees, fields."""
    out = []
    if _canonical(before.report["groups"][old.index]) != _canonical(after.report["groups"][new.index]):
        out.append("generation.json record")
    if old.members != new.members:
        out.append(f"members {list(old.members)} -> {list(new.members)}")
        return out
    a = {x.id: x for x in before.scenario.agents}
    b = {x.id: x for x in after.scenario.agents}
    for m in old.members:
        if a[m] != b.get(m):
            out.append(f"agent {m} in scenario.yaml")
            continue
        if _bytes(before.path / a[m].tree) != _bytes(after.path / b[m].tree):
            out.append(f"tree of agent {m}")
    fields = {fid for m in old.members for fid in _fields_named(before.path / a[m].tree)}
    for fid in sorted(fields):
        rel_a, rel_b = before.scenario.fields.get(fid), after.scenario.fields.get(fid)
        if rel_a is None or rel_b is None or _bytes(before.path / rel_a) != _bytes(after.path / rel_b):
            out.append(f"velocity field {fid}")
    return out


def _canonical(record: object) -> str:
    return json.dumps(record, sort_keys=True)


def _bytes(path: Path) -> bytes:
    return path.read_bytes() if path.is_file() else b""


def _fields_named(tree: Path) -> set[str]:
    if not tree.is_file():
        return set()
    document = read_tree(tree.read_text(encoding="utf-8"), str(tree))
    return {str(e.get("field")) for e in document.nodes() if e.id == "FollowVelocityField" and e.get("field")}


# ---- the summary ------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Summary:
    chains: int
    steps: int
    right: int
    follow_ups: int
    follow_ups_right: int
    untouched: int
    identical: int
    chains_all_identical: int
    errors: int

    @property
    def rate(self) -> float:
        return self.right / self.steps if self.steps else 0.0

    @property
    def passes(self) -> bool:
        return self.rate >= THRESHOLD and self.identical == self.untouched

    def line(self) -> str:
        return (f"chains={self.chains} steps={self.steps} steps_right={self.right} rate={self.rate:.3f} "
                f"follow_ups_right={self.follow_ups_right}/{self.follow_ups} untouched={self.untouched} "
                f"identical={self.identical} chains_identical={self.chains_all_identical}/{self.chains} "
                f"errors={self.errors}")


def summarize(results: Sequence[StepResult]) -> Summary:
    chains = sorted({r.chain for r in results})
    follow = [r for r in results if r.step > 0]
    per_chain_ok = [all(r.identical == r.untouched for r in results if r.chain == c) for c in chains]
    return Summary(len(chains), len(results), sum(r.ok for r in results), len(follow), sum(r.ok for r in follow),
                   sum(r.untouched for r in results), sum(r.identical for r in results), sum(per_chain_ok),
                   sum(1 for r in results if r.error))
