"""Evaluation: prompt alignment, plausibility and cost of generated scenarios, against baselines.

The paper scores scenarios with a cloud VLM; we compute checks anyone can reproduce offline from the
scenario and its simulation:
- grounding: agents whose target lies where the prompt says (the case's zones), and whose spawn does;
- counts: the population against the quantities in the prompt;
- behavior match: the node types the case expects (a queue, a conversation, an evacuation field...);
- validity: trees that validate, hallucinated node types or place names (must be 0);
- plausibility: wall penetrations (must be 0), goal-reach rate, overlaps, queue order and progress,
  evacuation completion and time, stop-and-go where the prompt implies it;
- cost: prompt/completion tokens and seconds per stage.

Baselines run on the same cases and seeds:
- `vanilla`: the vanilla preset (whole world in the prompt, all nodes, no guidance);
- `no-planner`: GROVE's trees without waypoint injection (straight SFM goals, as HuNavSim runs them);
- `decoupled`: starts and goals sampled from zone centres independently of the prompt's semantics
  (Text-Crowd's sampling, as the paper describes it).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import yaml
from lxml import etree

from grove_tui.engine.errors import GroveError
from grove_tui.engine.metrics import SimEvent, Trajectories, crowd_metrics
from grove_tui.engine.scenario import AgentSpec, Scenario

METHODS = ("grove", "vanilla", "no-planner", "decoupled")
NEAR_POINT = 1.5  # an agent "targets" a door or entity when its final goal is this close to it
STOP_SPEED = 0.1
GO_SPEED = 0.5
STOP_SECONDS = 1.0


class EvalError(GroveError):
    pass


@dataclass(frozen=True)
class Expectation:
    targets: tuple[str, ...] = ()  # RoI names (zones, doors, entities) agents should head for
    spawns: tuple[str, ...] = ()  # zones where agents should start
    count: int | None = None  # total people the prompt asks for
    behaviors: tuple[str, ...] = ()  # node types that must appear in the trees
    stop_and_go: bool = False


@dataclass(frozen=True)
class EvalCase:
    id: str
    world: str
    preset: str
    prompt: str
    seed: int
    expect: Expectation
    tags: tuple[str, ...] = ()


def load_suite(path: str | Path) -> list[EvalCase]:
    path = Path(path)
    try:
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise EvalError(f"{path}: no such suite file") from None
    except yaml.YAMLError as exc:
        raise EvalError(f"{path}: not valid YAML: {exc}") from None
    if not isinstance(data, dict) or not isinstance(data.get("cases"), list):
        raise EvalError(f"{path}: expected a mapping with a `cases` list")
    cases: list[EvalCase] = []
    seen: set[str] = set()
    for i, raw in enumerate(data["cases"]):
        where = f"{path}: cases[{i}]"
        if not isinstance(raw, dict):
            raise EvalError(f"{where}: expected a mapping")
        try:
            case_id = str(raw["id"])
            expect = raw.get("expect") or {}
            case = EvalCase(
                id=case_id,
                world=str(raw["world"]),
                preset=str(raw["preset"]),
                prompt=str(raw["prompt"]),
                seed=int(raw.get("seed", 0)),
                expect=Expectation(
                    targets=tuple(str(t) for t in expect.get("targets", ())),
                    spawns=tuple(str(s) for s in expect.get("spawns", ())),
                    count=None if expect.get("count") is None else int(expect["count"]),
                    behaviors=tuple(str(b) for b in expect.get("behaviors", ())),
                    stop_and_go=bool(expect.get("stop_and_go", False)),
                ),
                tags=tuple(str(t) for t in raw.get("tags", ())),
            )
        except KeyError as exc:
            raise EvalError(f"{where}: missing key {exc.args[0]!r}") from None
        except (TypeError, ValueError) as exc:
            raise EvalError(f"{where}: {exc}") from None
        if case.id in seen:
            raise EvalError(f"{where}: duplicate case id {case.id!r}")
        seen.add(case.id)
        cases.append(case)
    return cases


# --- alignment ---------------------------------------------------------------------------------


def _matches_roi(world: Any, point: Sequence[float], names: Sequence[str]) -> bool:
    """Does `point` lie in one of the named zones, or near one of the named doors/entities?"""
    import shapely

    p = shapely.Point(float(point[0]), float(point[1]))
    for name in names:
        try:
            roi = world.find(name)
        except GroveError:
            continue
        polygon = getattr(roi, "polygon", None)
        boundary = getattr(roi, "boundary", None)
        if polygon is not None and boundary is not None and polygon.buffer(0.3).contains(p):
            return True
        anchor = getattr(roi, "interaction_point", None) or getattr(roi, "position", None)
        if anchor is not None and math.dist(anchor, (p.x, p.y)) <= NEAR_POINT:
            return True
        footprint = getattr(roi, "footprint", None)
        if footprint is not None and shapely.Polygon(footprint).distance(p) <= NEAR_POINT:
            return True
    return False


def grounding(world: Any, agents: Sequence[AgentSpec], expect: Expectation) -> dict[str, float]:
    """Shares of agents whose final target / spawn lie where the case says."""
    out: dict[str, float] = {}
    if expect.targets:
        scored = [a for a in agents if a.goals]
        hits = sum(_matches_roi(world, a.goals[-1], expect.targets) for a in scored)
        out["target_grounding"] = hits / len(scored) if scored else 0.0
    if expect.spawns:
        hits = sum(_matches_roi(world, a.start, expect.spawns) for a in agents)
        out["spawn_grounding"] = hits / len(agents) if agents else 0.0
    return out


def count_accuracy(agents: Sequence[AgentSpec], expect: Expectation) -> float | None:
    if expect.count is None:
        return None
    return max(0.0, 1.0 - abs(len(agents) - expect.count) / expect.count)


def tree_node_types(trees: Mapping[int, str]) -> set[str]:
    types: set[str] = set()
    parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False)
    for xml in trees.values():
        root = etree.fromstring(xml.encode("utf-8"), parser)
        for tree in root.iter("BehaviorTree"):
            types |= {el.tag for el in tree.iter() if isinstance(el.tag, str) and el.tag != "BehaviorTree"}
    return types


def behavior_match(trees: Mapping[int, str], expect: Expectation) -> float | None:
    if not expect.behaviors:
        return None
    present = tree_node_types(trees)
    return sum(b in present for b in expect.behaviors) / len(expect.behaviors)


def validity(world: Any, trees: Mapping[int, str]) -> dict[str, float]:
    """Trees that validate against the manifest, and names the model invented."""
    from grove_tui.engine.bt.manifest import NODES
    from grove_tui.engine.bt.xml import check_tree_text

    valid = 0
    hallucinated_nodes: set[str] = set()
    hallucinated_places: set[str] = set()
    known_places = {roi.name for roi in world.roi_index()}
    parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False)
    for agent_id, xml in trees.items():
        if not check_tree_text(xml, source=f"agent {agent_id}"):
            valid += 1
        root = etree.fromstring(xml.encode("utf-8"), parser)
        for tree in root.iter("BehaviorTree"):
            for el in tree.iter():
                if not isinstance(el.tag, str) or el.tag in ("BehaviorTree", "SubTree"):
                    continue
                spec = NODES.get(el.tag)
                if spec is None:
                    hallucinated_nodes.add(el.tag)
                    continue
                for port in spec.ports:
                    if port.type == "target" and el.get(port.name) and el.get(port.name) not in known_places:
                        hallucinated_places.add(el.get(port.name))
    n = len(trees)
    return {
        "valid_trees": valid / n if n else 0.0,
        "hallucinated_node_types": float(len(hallucinated_nodes)),
        "hallucinated_places": float(len(hallucinated_places)),
    }


# --- plausibility --------------------------------------------------------------------------------


def stop_and_go_share(traj: Trajectories) -> float:
    """Share of people who stood still for at least a second and then walked on."""
    if traj.ids.size == 0 or traj.frames < 3:
        return 0.0
    dt = float(np.median(np.diff(traj.t)))
    need = max(1, int(round(STOP_SECONDS / dt)))
    speed = np.hypot(traj.people_vel[:, :, 0], traj.people_vel[:, :, 1])
    count = 0
    for k in range(traj.ids.size):
        s = speed[:, k]
        s = s[np.isfinite(s)]
        run = 0
        stopped = False
        for v in s:
            if v < STOP_SPEED:
                run += 1
                if run >= need:
                    stopped = True
            else:
                if stopped and v > GO_SPEED:
                    count += 1
                    break
                run = 0
    return count / traj.ids.size


def plausibility(traj: Trajectories, world: Any, agents: Sequence[AgentSpec],
                 events: Sequence[SimEvent]) -> dict[str, float]:
    crowd = crowd_metrics(traj, walls=world.walls(), final_goals={a.id: a.goals[-1] for a in agents if a.goals},
                          events=events, walkable_area=float(world.walkable().area),
                          radius=max((a.radius for a in agents), default=0.35))
    out = {k: crowd[k] for k in ("wall_penetrations", "goal_reach_rate", "agent_overlaps") if k in crowd}
    for key in ("queue_members", "queue_served", "queue_order_violations", "evacuation_completion",
                "evacuation_time"):
        if key in crowd:
            out[key] = crowd[key]
    out["stop_and_go"] = stop_and_go_share(traj)
    return out


# --- baselines -----------------------------------------------------------------------------------


def decoupled_agents(world: Any, agents: Sequence[AgentSpec], seed: int, grid: Any) -> list[AgentSpec]:
    """Text-Crowd-style sampling: each agent starts and ends at zone centres drawn independently of
    the prompt (nearest free point to a random zone's centroid), keeping count and trees."""
    rng = np.random.default_rng(seed)
    zones = list(world.zones)
    out = []
    for agent in agents:
        picks = rng.choice(len(zones), size=2, replace=len(zones) < 2)
        start_zone, goal_zone = zones[int(picks[0])], zones[int(picks[1])]
        start = grid.nearest_free(*start_zone.centroid) or agent.start
        jitter = rng.normal(0.0, 0.4, size=2)
        start = grid.nearest_free(start[0] + jitter[0], start[1] + jitter[1]) or start
        goal = grid.nearest_free(*goal_zone.centroid) or (agent.goals[-1] if agent.goals else start)
        out.append(AgentSpec(id=agent.id, group=agent.group, start=tuple(start), goals=(tuple(goal),),
                             zone=goal_zone.name, tree=agent.tree, radius=agent.radius, max_vel=agent.max_vel,
                             label=agent.label, behavior=agent.behavior))
    return out


@dataclass
class CaseResult:
    case: EvalCase
    method: str
    scores: dict[str, float] = field(default_factory=dict)
    error: str = ""


def score_scenario(case: EvalCase, method: str, world: Any, scenario: Scenario, trees: Mapping[int, str],
                   traj: Trajectories | None, events: Sequence[SimEvent],
                   report: Mapping[str, Any] | None = None) -> CaseResult:
    scores: dict[str, float] = {"agents": float(len(scenario.agents))}
    scores.update(grounding(world, scenario.agents, case.expect))
    count = count_accuracy(scenario.agents, case.expect)
    if count is not None:
        scores["count_accuracy"] = count
    match = behavior_match(trees, case.expect)
    if match is not None:
        scores["behavior_match"] = match
    scores.update(validity(world, trees))
    if traj is not None:
        scores.update(plausibility(traj, world, scenario.agents, events))
    for stage, info in (report or {}).get("stages", {}).items():
        scores[f"{stage}_seconds"] = float(info.get("seconds", 0.0))
    scores["prompt_tokens"] = float(sum(i.get("prompt_tokens", 0) for i in (report or {}).get("stages", {}).values()))
    scores["completion_tokens"] = float(
        sum(i.get("completion_tokens", 0) for i in (report or {}).get("stages", {}).values()))
    return CaseResult(case=case, method=method, scores=scores)
