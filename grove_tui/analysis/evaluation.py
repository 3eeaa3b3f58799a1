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

import dataclasses
import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import yaml

from grove_tui.bt.format.document import TreeDocument, TreeElement, TreeFiles
from grove_tui.bt.format.manifest import NODES, SUBTREE
from grove_tui.bt.format.ports import format_point_list
from grove_tui.bt.format.xml import check_document
from grove_tui.errors import EvalError, GroveError
from grove_tui.jsontypes import Parsed
from grove_tui.analysis.metrics import Trajectories, crowd_metrics
from grove_tui.scenario.events import SimEvent
from grove_tui.scenario.model import AgentSpec, Scenario

if TYPE_CHECKING:
    from grove_tui.navigation.grid import OccupancyGrid
    from grove_tui.navigation.theta_star import ThetaStarPlanner
    from grove_tui.world.model import World

# generation.json as read back: JSON written by generation, read here key by key with defaults.
GenerationReport = Parsed

METHODS = ("grove", "vanilla", "no-planner", "decoupled")
NEAR_POINT = 1.5  # an agent "targets" a door or entity when its final goal is this close to it
STOP_SPEED = 0.1
GO_SPEED = 0.5
STOP_SECONDS = 1.0


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
    except UnicodeDecodeError as exc:
        raise EvalError(f"{path}: not UTF-8 text (byte {exc.start})") from None
    except OSError as exc:
        raise EvalError(f"{path}: cannot read it: {exc.strerror}") from None
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
            if not isinstance(expect, dict):
                raise EvalError(f"{where}: expect must be a mapping like {{targets: [...], count: N}}")
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


def _matches_roi(world: World, point: Sequence[float], names: Sequence[str]) -> bool:
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


def _zone_matches(world: World, zone_name: str, names: Sequence[str]) -> bool:
    """A zone matches when it is named, or holds a named door or entity."""
    for name in names:
        if name == zone_name:
            return True
        try:
            roi = world.find(name)
        except GroveError:
            continue
        if getattr(roi, "zone", None) == zone_name:
            return True
    return False


def _roaming_zone(tree: TreeDocument | None) -> str | None:
    if tree is None:
        return None
    for el in tree.nodes():
        if el.id == "Wander" and el.get("zone"):
            return el.get("zone")
    return None


def grounding(world: World, agents: Sequence[AgentSpec], expect: Expectation,
              trees: Mapping[int, TreeDocument] | None = None) -> dict[str, float]:
    """Shares of agents whose target / spawn lie where the case says. An agent's target is its last
    goal; an agent with no fixed goal (roaming) targets the zone it roams, else its scenario zone."""
    out: dict[str, float] = {}
    if expect.targets:
        hits = 0
        for a in agents:
            if a.goals:
                hits += _matches_roi(world, a.goals[-1], expect.targets)
            else:
                zone = _roaming_zone((trees or {}).get(a.id)) or a.zone
                hits += _zone_matches(world, zone, expect.targets)
        out["target_grounding"] = hits / len(agents) if agents else 0.0
    if expect.spawns:
        hits = sum(_matches_roi(world, a.start, expect.spawns) for a in agents)
        out["spawn_grounding"] = hits / len(agents) if agents else 0.0
    return out


def count_accuracy(agents: Sequence[AgentSpec], expect: Expectation) -> float | None:
    if expect.count is None:
        return None
    return max(0.0, 1.0 - abs(len(agents) - expect.count) / expect.count)


def tree_node_types(trees: Mapping[int, TreeDocument]) -> set[str]:
    types: set[str] = set()
    for document in trees.values():
        types |= {el.id for el in document.nodes()}
    return types


def behavior_match(trees: Mapping[int, TreeDocument], expect: Expectation) -> float | None:
    if not expect.behaviors:
        return None
    present = tree_node_types(trees)
    return sum(b in present for b in expect.behaviors) / len(expect.behaviors)


def validity(world: World, trees: Mapping[int, TreeDocument]) -> dict[str, float]:
    """Trees that validate against the manifest, and names the model invented."""
    valid = 0
    hallucinated_nodes: set[str] = set()
    hallucinated_places: set[str] = set()
    known_places = {roi.name for roi in world.roi_index()}
    for document in trees.values():
        if not check_document(document):
            valid += 1
        for el in document.nodes():
            if el.id == SUBTREE:
                continue
            spec = NODES.get(el.id)
            if spec is None:
                hallucinated_nodes.add(el.id)
                continue
            for port in spec.ports:
                place = el.get(port.name)
                if port.type == "target" and place and place not in known_places:
                    hallucinated_places.add(place)
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


def plausibility(traj: Trajectories, world: World, agents: Sequence[AgentSpec],
                 events: Sequence[SimEvent]) -> dict[str, float]:
    crowd = crowd_metrics(traj, walls=world.walls(), final_goals={a.id: a.goals[-1] for a in agents if a.goals},
                          events=events, walkable_area=float(world.walkable().area),
                          radius=max((a.radius for a in agents), default=0.35))
    out: dict[str, float] = {k: crowd[k] for k in ("wall_penetrations", "goal_reach_rate", "agent_overlaps")
                             if k in crowd}
    for key in ("queue_members", "queue_served", "queue_order_violations", "evacuation_completion",
                "evacuation_time"):
        if key in crowd:
            out[key] = crowd[key]
    out["stop_and_go"] = stop_and_go_share(traj)
    return out


# --- baselines -----------------------------------------------------------------------------------


def decoupled_agents(world: World, agents: Sequence[AgentSpec], seed: int, grid: OccupancyGrid) -> list[AgentSpec]:
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
        out.append(AgentSpec(id=agent.id, group=agent.group, start=start, goals=(goal,),
                             zone=goal_zone.name, tree=agent.tree, radius=agent.radius, max_vel=agent.max_vel,
                             label=agent.label, behavior=agent.behavior))
    return out


@dataclass
class CaseResult:
    case: EvalCase
    method: str
    scores: dict[str, float] = field(default_factory=dict)
    error: str = ""


def score_scenario(case: EvalCase, method: str, world: World, scenario: Scenario, trees: Mapping[int, TreeDocument],
                   traj: Trajectories | None, events: Sequence[SimEvent],
                   report: GenerationReport | None = None) -> CaseResult:
    scores: dict[str, float] = {"agents": float(len(scenario.agents))}
    scores.update(grounding(world, scenario.agents, case.expect, trees))
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
    scores.update(grounding_report_scores(report) if method == "grove" else {})
    return CaseResult(case=case, method=method, scores=scores)


def grounding_report_scores(report: Mapping[str, object] | None) -> dict[str, float]:
    """What the bundle's own grounding report says, checked on its run (grounding.json, else the
    planned report of generation.json, where nothing is ✓ yet): the share of the sentence's groups
    whose every claim held in the run (✓), and how many parts of the sentence it says it could not honour. The suite's expectations score the same
    scenario from outside; this is the product's account of itself, so the two can be compared."""
    grounding_entry = (report or {}).get("grounding")
    if not isinstance(grounding_entry, Mapping):
        return {}
    groups = [g for g in grounding_entry.get("groups", ()) if isinstance(g, Mapping)]
    scores = {"report_unhonoured": float(len(grounding_entry.get("unhonoured", ()) or ()))}
    if groups:
        scores["report_groups_ok"] = sum(bool(g.get("ok")) for g in groups) / len(groups)
    return scores


# --- running a suite -----------------------------------------------------------------------------

def _rewrite_trees(trees: Mapping[str, TreeDocument], agents: Sequence[AgentSpec],
                   edit: Callable[[AgentSpec, TreeDocument], None]) -> TreeFiles:
    """Apply `edit(agent, document)` to a copy of each agent's tree (GROVE's own stay as they are)."""
    by_path = {a.tree: a for a in agents}
    out = {}
    for rel, original in trees.items():
        document = original.copy()
        agent = by_path.get(rel)
        if agent is not None:
            edit(agent, document)
        out[rel] = document
    return out


def _navigation_tags() -> frozenset[str]:
    return frozenset(name for name, spec in NODES.items() if spec.navigates)


def without_planner(scenario: Scenario, trees: Mapping[str, TreeDocument]) -> tuple[Scenario, TreeFiles]:
    """The `no-planner` baseline: straight SFM goals, as HuNavSim runs behavior trees. Injected
    waypoints are dropped, velocity fields are replaced by a straight walk to the exit, and the
    simulation plans nothing at run time either (see simulate)."""
    nav = _navigation_tags()

    def edit(agent: AgentSpec, document: TreeDocument) -> None:
        for parent, index, el in document.nodes_with_parents():
            if el.id in nav and el.get("waypoints"):
                el.set("waypoints", "")
            if el.id == "FollowVelocityField":
                exit_point: dict[str, str] = {k: el.attributes[k] for k in ("x", "y") if k in el.attributes}
                parent.children[index] = TreeElement("GoTo", {"target": el.get("exit") or "exit", **exit_point,
                                                              "waypoints": "", "agent_id": "{id}"})

    new_trees = _rewrite_trees(trees, scenario.agents, edit)
    agents = tuple(dataclasses.replace(a, goals=a.goals[-1:]) for a in scenario.agents)
    return dataclasses.replace(scenario, agents=agents, fields={}), new_trees


def decoupled(scenario: Scenario, trees: Mapping[str, TreeDocument], world: World, grid: OccupancyGrid,
              planner: ThetaStarPlanner) -> tuple[Scenario, TreeFiles]:
    """The `decoupled` baseline: same population and behaviors, but starts and goals drawn from zone
    centres independently of the prompt; paths are still planned (Text-Crowd plans its roadmap too)."""
    from grove_tui.generation.waypoints import plan_waypoints

    agents = decoupled_agents(world, scenario.agents, scenario.seed, grid)
    by_id = {a.id: a for a in agents}
    nav = _navigation_tags()

    def edit(agent: AgentSpec, document: TreeDocument) -> None:
        goal_x, goal_y = format_point_list([by_id[agent.id].goals[-1]]).split(",")
        for parent, index, el in document.nodes_with_parents():
            if el.id == "FollowVelocityField":
                parent.children[index] = TreeElement("GoTo", {"target": "sampled", "x": goal_x, "y": goal_y,
                                                              "waypoints": "", "agent_id": "{id}"})
            elif el.id in nav or el.id == "Queue":
                el.set("x", goal_x)
                el.set("y", goal_y)
                if el.get("waypoints") is not None:
                    el.set("waypoints", "")

    new_trees = _rewrite_trees(trees, scenario.agents, edit)
    start_of = {a.tree: by_id[a.id].start for a in scenario.agents}
    planned = {rel: plan_waypoints(document, start_of[rel], planner) if rel in start_of else document
               for rel, document in new_trees.items()}
    return dataclasses.replace(scenario, agents=tuple(agents), fields={}), planned


def baseline_variant(method: str, world: World, scenario: Scenario,
                     trees: Mapping[str, TreeDocument]) -> tuple[Scenario, TreeFiles]:
    """The `no-planner` or `decoupled` rewrite of GROVE's scenario and trees (the services layer writes
    it as a bundle derived from GROVE's: `scenario.bundle.derive_bundle`)."""
    from grove_tui.navigation.grid import build_grid
    from grove_tui.navigation.theta_star import ThetaStarPlanner

    if method == "no-planner":
        variant, new_trees = without_planner(scenario, trees)
    elif method == "decoupled":
        grid = build_grid(world, scenario.resolution, scenario.grid_inflation)
        variant, new_trees = decoupled(scenario, trees, world, grid, ThetaStarPlanner(grid))
    else:
        raise EvalError(f"{method!r} is not a baseline rewrite of GROVE's bundle (no-planner, decoupled)")
    return variant, dict(new_trees)


# --- tables --------------------------------------------------------------------------------------

GROUNDING_KEYS = ("target_grounding", "spawn_grounding", "count_accuracy", "behavior_match")
PLAUSIBILITY_KEYS = ("wall_penetrations", "goal_reach_rate", "agent_overlaps", "queue_order_violations",
                     "evacuation_completion", "stop_and_go")
VALIDITY_KEYS = ("valid_trees", "hallucinated_node_types", "hallucinated_places")
COST_KEYS = ("prompt_tokens", "completion_tokens", "eval_seconds")
# What the bundle says of itself (its grounding report), beside what the suite measures from outside.
REPORT_KEYS = ("report_groups_ok", "report_unhonoured")
SUMMARY_KEYS = GROUNDING_KEYS + PLAUSIBILITY_KEYS + VALIDITY_KEYS + COST_KEYS + REPORT_KEYS


FAILED_SCORES = {"target_grounding": 0.0, "spawn_grounding": 0.0, "count_accuracy": 0.0, "behavior_match": 0.0,
                 "goal_reach_rate": 0.0, "evacuation_completion": 0.0, "valid_trees": 0.0}


def summarize(results: Sequence[CaseResult]) -> dict[tuple[str, str], dict[str, float]]:
    """Mean of each score per (preset, method), over the cases where the score applies. A scenario
    that could not be generated aligns with nothing: its grounding, reach and validity count as 0."""
    table: dict[tuple[str, str], dict[str, list[float]]] = {}
    for r in results:
        row = table.setdefault((r.case.preset, r.method), {})
        row.setdefault("failed", []).append(1.0 if r.error else 0.0)
        if r.error:
            expect = r.case.expect
            applicable = {"target_grounding": bool(expect.targets), "spawn_grounding": bool(expect.spawns),
                          "count_accuracy": expect.count is not None, "behavior_match": bool(expect.behaviors)}
            for key, value in FAILED_SCORES.items():
                if applicable.get(key, True):
                    row.setdefault(key, []).append(value)
            continue
        for key in SUMMARY_KEYS:
            score = r.scores.get(key)
            if score is not None and not (isinstance(score, float) and math.isnan(score)):
                row.setdefault(key, []).append(float(score))
    return {k: {m: float(np.mean(v)) for m, v in row.items()} for k, row in table.items()}


def grounding_score(row: Mapping[str, float]) -> float:
    keys = [k for k in ("target_grounding", "spawn_grounding", "count_accuracy", "behavior_match") if k in row]
    return float(np.mean([row[k] for k in keys])) if keys else math.nan


def plausibility_score(row: Mapping[str, float]) -> float:
    """One number per row: goal reach and stop-and-go up, penetrations and overlaps down (0..1)."""
    parts = []
    if "goal_reach_rate" in row:
        parts.append(row["goal_reach_rate"])
    if "wall_penetrations" in row:
        parts.append(1.0 / (1.0 + row["wall_penetrations"]))
    if "agent_overlaps" in row:
        parts.append(1.0 / (1.0 + row["agent_overlaps"] / 100.0))
    if "evacuation_completion" in row:
        parts.append(row["evacuation_completion"])
    return float(np.mean(parts)) if parts else math.nan


def results_markdown(results: Sequence[CaseResult], command: str = "") -> str:
    summary = summarize(results)
    presets = sorted({p for p, _ in summary})
    methods = [m for m in METHODS if any(m == mm for _, mm in summary)]
    lines = ["# Evaluation results", ""]
    if command:
        lines += ["Made by:", "", "```", command, "```", ""]
    cols = ["preset", "method", "grounding", "plausibility", "target", "spawn", "count", "behavior",
            "wall pen.", "goal reach", "overlaps", "evac.", "stop&go", "valid", "halluc.", "prompt tok", "report ✓",
            "unhonoured", "failed"]
    lines += ["| " + " | ".join(cols) + " |", "|" + "---|" * len(cols)]

    def fmt(row: Mapping[str, float], key: str, digits: int = 2) -> str:
        v = row.get(key)
        return "-" if v is None or (isinstance(v, float) and math.isnan(v)) else f"{v:.{digits}f}"

    for preset in presets:
        for method in methods:
            row = summary.get((preset, method))
            if row is None:
                continue
            halluc = row.get("hallucinated_node_types", 0.0) + row.get("hallucinated_places", 0.0)
            lines.append("| " + " | ".join([
                preset, method, f"{grounding_score(row):.2f}", f"{plausibility_score(row):.2f}",
                fmt(row, "target_grounding"), fmt(row, "spawn_grounding"), fmt(row, "count_accuracy"),
                fmt(row, "behavior_match"), fmt(row, "wall_penetrations", 1), fmt(row, "goal_reach_rate"),
                fmt(row, "agent_overlaps", 1), fmt(row, "evacuation_completion"), fmt(row, "stop_and_go"),
                fmt(row, "valid_trees"), f"{halluc:.1f}", fmt(row, "prompt_tokens", 0), fmt(row, "report_groups_ok"),
                fmt(row, "report_unhonoured", 1), fmt(row, "failed"),
            ]) + " |")
    lines += ["", "grounding = mean of target/spawn grounding, count accuracy and behavior match; "
              "plausibility = mean of goal reach, 1/(1+wall penetrations), 1/(1+overlaps/100) and "
              "evacuation completion. report ✓ = share of the sentence's groups the bundle's own grounding report "
              "marks ✓ (count, start, destination, behavior, robot reaction all hold); unhonoured = parts of the "
              "sentence it says it could not honour, per case. Means over the cases of each preset.", ""]
    failures = [r for r in results if r.error]
    if failures:
        lines += ["## Failures", ""] + [f"- {r.case.id} / {r.method}: {r.error}" for r in failures] + [""]
    return "\n".join(lines)


def write_results(results: Sequence[CaseResult], out_dir: Path, command: str = "") -> list[Path]:
    import csv
    import io

    from grove_tui.files import write_text_atomic

    keys = sorted({k for r in results for k in r.scores})
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["case", "world", "preset", "method", "error", *keys])
    for r in results:
        writer.writerow([r.case.id, r.case.world, r.case.preset, r.method, r.error,
                         *[("" if r.scores.get(k) is None else r.scores[k]) for k in keys]])
    return [write_text_atomic(Path(out_dir) / "results.csv", buffer.getvalue()),
            write_text_atomic(Path(out_dir) / "RESULTS.md", results_markdown(results, command))]
