"""Refining a scenario by talking to it: a follow-up edits the groups it names and nothing else.

    scene = scene_of(result, world)
    edit = read_followup("make the queue twice as long", world, [g.reading for g in scene.groups])
    refinement = plan_refinement(scene, edit)          # the diff, before anything runs
    print("\\n".join(refinement.diff.lines()))
    refined = apply_refinement(pipeline, scene, refinement)   # a GenerationResult

How an edit is applied:
- Untouched groups keep everything: their agents' entries in scenario.yaml, their tree files, their
  velocity fields and their generation.json records are copied as they are, byte for byte.
- Added groups, and changed groups whose behavior or places change, are generated: the model is asked
  for those groups alone (their reading is the request's numbered "Groups"), then reconciled.
- Changed groups whose count, pace, start, togetherness, wait or robot reaction change keep their tree
  (no model call): reconciliation sets what changed.
- Every new or changed group is post-processed beside the kept ones (ids, social groups, goal ids and
  queue places continue after theirs, nobody starts on a kept person) and planned; a changed group
  keeps its members' ids, and their start points while it starts in the same zone.
- The robot is kept, unless the follow-up speaks of it or a new queue or circle stands in its path.
Each edit is a step of the report's "history" (sentence, reading, diff), and the grounding report
covers every sentence, saying which one asked for each group.
"""

from __future__ import annotations

import hashlib
import re
import threading
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace

from grove_tui.bt.format.document import TreeFiles
from grove_tui.errors import AmbiguousEditError, EditError, GenerationError, GroveError
from grove_tui.generation.draft import Draft, DraftGroup, DraftNode
from grove_tui.generation.formations import PASSING_MARGIN, nearest_formation_gap, predict_formations
from grove_tui.generation.events import Event
from grove_tui.generation.pipeline import (GenerationPipeline, GenerationResult, GroupRecord, StageClock, check_trees,
                                           group_records, world_reference)
from grove_tui.generation.planning import CachedPlanner, plan_operational, plan_robot
from grove_tui.generation.postprocess import AgentPlan, GroupPlan, PostProcessed, place_groups, plan_groups
from grove_tui.generation.presets import load_preset
from grove_tui.generation.requests import RobotRequest
from grove_tui.generation.reconcile import grounding_report, tree_for
from grove_tui.generation.route_time import Leg, planned_routes, planning_mode
from grove_tui.generation.rois import select_rois
from grove_tui.generation.scene import Scene, SceneGroup, placed_scene
from grove_tui.generation.synthesis import describe_reading_groups
from grove_tui.language.edits import EditReading, GroupEdit, edited_reading
from grove_tui.language.model import GroupReading, PromptReading, RobotReading
from grove_tui.navigation.theta_star import PlanningError
from grove_tui.scenario.history import (ADDED, CHANGED, REMOVED, GroupChange, GroupSummary, HistoryStep, RefineDiff,
                                        RobotChange, StageTiming)
from grove_tui.scenario.model import AgentSpec, RobotSpec, Scenario
from grove_tui.scenario.report import GroundingReport
from grove_tui.jsontypes import JSONObject
from grove_tui.world.model import World

# Fields whose change the group's tree cannot absorb: the model writes it again.
REGENERATING_FIELDS = ("intent", "destination", "location", "via")
# Node documents retrieved per group the model writes in a refinement (a whole sentence gets the preset's).
DOCUMENTS_PER_GROUP = 3
# Fields reconciliation sets on the tree the group had (no model call).
KEPT_TREE_FIELDS = ("count", "start", "pace", "together", "wait_seconds", "robot_interaction")
KEPT, CHANGED_STATUS, ADDED_STATUS = "kept", "changed", "added"
_REACTION_NODES = frozenset({"IsRobotVisible", "IsRobotClose"})  # reconcile.with_reaction's cues


@dataclass(frozen=True)
class PlannedGroup:
    """One group of the scenario after the edit."""

    reading: GroupReading
    status: str  # "kept", "changed" or "added"
    source: SceneGroup | None = None  # the group it was; None for an added group
    regenerate: bool = False  # the model writes its tree
    asked_by: int = 0
    changed_by: tuple[int, ...] = ()
    fields: tuple[str, ...] = ()  # what changed (changed groups)


@dataclass(frozen=True)
class RobotPlan:
    kind: str  # "keep", "remove", "default" (placed by the pipeline) or "task"
    task: RobotReading | None = None


@dataclass(frozen=True)
class Refinement:
    edit: EditReading
    step: int  # this follow-up's number: the first sentence is 0
    groups: tuple[PlannedGroup, ...]
    removed: tuple[SceneGroup, ...]
    robot: RobotPlan
    diff: RefineDiff

    @property
    def touched(self) -> int:
        return sum(1 for g in self.groups if g.status != KEPT) + len(self.removed)

    @property
    def calls_model(self) -> bool:
        return any(g.regenerate for g in self.groups)


def step_seed(seed: int, step: int) -> int:
    """The seed of follow-up `step` of a scenario of seed `seed`: the same bundle and follow-up always
    give the same result, and two follow-ups do not share their samples."""
    digest = hashlib.blake2b(f"grove-refine:{seed}:{step}".encode(), digest_size=4).digest()
    return int.from_bytes(digest, "big")


# ---- planning the edit (no model, no geometry) -------------------------------------------------------------

def plan_refinement(scene: Scene, edit: EditReading, evacuation_field: bool | None = None) -> Refinement:
    """What the follow-up does to the scene's groups and robot, as a diff; EditError when it changes
    nothing or leaves nobody, AmbiguousEditError when it names a group that could be several.

    `evacuation_field`: the scenario's preset evacuates along velocity fields (default: read from
    its preset), so an evacuating group's tree is the field to its exit and needs no model."""
    if evacuation_field is None:
        evacuation_field = _evacuates_by_field(scene.scenario.preset)
    if edit.ambiguities():
        raise ambiguity_error(scene, edit)
    step = scene.steps + 1
    current: dict[int, GroupReading] = {g.index: g.reading for g in scene.groups}
    removed: set[int] = set()
    added: list[GroupReading] = []
    notes = list(edit.notes)
    for e in edit.edits:
        targets = e.target.targets if e.target is not None else ()
        if e.kind == "add":
            if e.group is not None:
                added.append(e.group)
            continue
        for t in targets:
            if t >= len(scene.groups):
                added_index = t - len(scene.groups)  # a group this sentence itself adds ("... and make it slow")
                if e.kind == "remove" and added_index < len(added):
                    added[added_index] = replace(added[added_index], count=replace(added[added_index].count, value=0))
                elif e.kind == "change" and added_index < len(added):
                    added[added_index] = edited_reading(added[added_index], e)
                continue
            if e.kind == "remove" or (e.count is not None and e.count.removes(current[t].count.value)):
                removed.add(t)
            elif t not in removed:
                current[t] = edited_reading(current[t], e)
    added = [g for g in added if g.count.value > 0]
    planned: list[PlannedGroup] = []
    for g in scene.groups:
        if g.index in removed:
            continue
        fields = _changed_fields(g.reading, current[g.index])
        if not fields:
            planned.append(PlannedGroup(g.reading, KEPT, g, False, g.asked_by, g.changed_by))
            continue
        regenerate = any(f in REGENERATING_FIELDS for f in fields) and \
            not _fixed_by_reading(current[g.index], evacuation_field)
        planned.append(PlannedGroup(current[g.index], CHANGED_STATUS, g, regenerate, g.asked_by,
                                    g.changed_by + (step,), tuple(fields)))
    planned += [PlannedGroup(r, ADDED_STATUS, None, not _fixed_by_reading(r, evacuation_field), step)
                for r in added]
    robot = _robot_plan(scene, edit)
    if not planned:
        raise EditError(f"'{edit.sentence}' would leave nobody in the scenario", hint="Keep at least one group.")
    gone = tuple(g for g in scene.groups if g.index in removed)
    diff = _diff(scene, edit, planned, gone, robot, notes)
    if diff.empty:
        reason = "; ".join(notes) if notes else "every group it names already does that"
        raise EditError(f"'{edit.sentence}' changes nothing in the scenario: {reason}")
    return Refinement(edit, step, tuple(planned), gone, robot, diff)


def ambiguity_error(scene: Scene, edit: EditReading) -> AmbiguousEditError:
    """The question to ask: per ambiguous phrase, its candidate groups as the user sees them."""
    choices = []
    lines = []
    for _, ref in edit.ambiguities():
        options = tuple((c, describe_group(scene, c)) for c in ref.candidates)
        choices.append((ref.phrase, options))
        lines.append(f"'{ref.phrase}' could be " + "; ".join(f"group {c + 1} ({text})" for c, text in options))
    first = choices[0]
    return AmbiguousEditError(". ".join(lines), choices=tuple(choices),
                              hint=f"say which: name its place (\"{first[0]} at ...\") or pass --group "
                                   f"{first[1][0][0] + 1} (the group's number)")


def describe_group(scene: Scene, index: int) -> str:
    if index >= len(scene.groups):
        return "a group this sentence adds"
    g = scene.groups[index]
    return summary_of(g.reading, g.count).text()


def _evacuates_by_field(preset_name: str) -> bool:
    try:
        return load_preset(preset_name).velocity == "field"
    except GroveError:  # a preset this installation does not have: the model writes every tree
        return False


def _fixed_by_reading(reading: GroupReading, evacuation_field: bool) -> bool:
    """Whether the reading alone gives the group's tree, so asking the model would only cost time:
    evacuees under a preset that evacuates along fields follow the field to their exit (reconciliation
    keeps nothing else of a model's evacuation tree)."""
    return evacuation_field and reading.intent == "evacuate"


def _changed_fields(old: GroupReading, new: GroupReading) -> list[str]:
    fields = []
    if old.count.value != new.count.value:
        fields.append("count")
    for name in ("intent", "start", "destination", "location", "via", "pace", "together", "wait_seconds",
                 "robot_interaction"):
        if getattr(old, name) != getattr(new, name):
            fields.append(name)
    return fields


def _robot_plan(scene: Scene, edit: EditReading) -> RobotPlan:
    robot = edit.robot
    if robot is None:
        return RobotPlan("keep")
    if robot.kind == "remove":
        return RobotPlan("remove") if scene.scenario.robot is not None else RobotPlan("keep")
    if robot.robot is None:
        return RobotPlan("default") if scene.scenario.robot is None or robot.kind == "add" else RobotPlan("keep")
    return RobotPlan("task", robot.robot)


# ---- the diff ---------------------------------------------------------------------------------------------

def behavior_text(r: GroupReading) -> str:
    """What a reading asks a group to do, in a few words ("queue at pharmacy_counter")."""
    base = r.intent
    place = r.location or r.destination
    if base == "queue":
        text = f"queue at {place}" if place else "queue"
    elif base == "wait":
        text = f"wait at {place}" if place else "wait"
    elif base == "wander":
        text = f"wander in {place or r.start}" if (place or r.start) else "wander"
    elif base == "converse":
        text = f"chat in {place}" if place else "chat"
    elif base == "evacuate":
        text = f"evacuate through {r.destination}" if r.destination else "evacuate"
    elif base == "follow":
        text = f"follow {r.follows}" if r.follows else "follow"
    elif base == "robot":
        text = f"walk to {r.destination}" if r.destination else "stay"
    else:
        text = f"walk to {r.destination}" if r.destination else "walk"
    if r.via:
        text += " via " + ", ".join(r.via)
    if r.wait_seconds:
        text += f" for {r.wait_seconds:g} s"
    if r.together and r.count.value > 1:
        text += ", together"
    return text


def summary_of(r: GroupReading, count: int | None = None) -> GroupSummary:
    return GroupSummary(r.label, int(count if count is not None else r.count.value), behavior_text(r), r.start or "",
                        r.pace, r.robot_reaction or "")


def _diff(scene: Scene, edit: EditReading, planned: Sequence[PlannedGroup], removed: Sequence[SceneGroup],
          robot: RobotPlan, notes: list[str]) -> RefineDiff:
    changes: list[GroupChange] = []
    for p in planned:
        if p.status == CHANGED_STATUS and p.source is not None:
            before, after = summary_of(p.source.reading, p.source.count), summary_of(p.reading)
            changes.append(GroupChange(CHANGED, before, after, p.fields, p.regenerate))
        elif p.status == ADDED_STATUS:
            changes.append(GroupChange(ADDED, None, summary_of(p.reading), (), True))
    changes += [GroupChange(REMOVED, summary_of(g.reading, g.count), None) for g in removed]
    robot_change = None
    current: RobotSpec | None = scene.scenario.robot
    if robot.kind == "remove":
        robot_change = RobotChange(REMOVED, describe_robot(current), "none")
    elif robot.kind == "default":
        robot_change = RobotChange(ADDED if current is None else CHANGED, describe_robot(current),
                                   "crosses the scene (placed by GROVE)")
    elif robot.kind == "task" and robot.task is not None:
        robot_change = RobotChange(ADDED if current is None else CHANGED, describe_robot(current),
                                   describe_task(robot.task))
    kept = sum(1 for p in planned if p.status == KEPT)
    return RefineDiff(edit.sentence, tuple(changes), robot_change, kept, tuple(dict.fromkeys(notes)))


def describe_robot(robot: RobotSpec | None) -> str:
    if robot is None:
        return "none"
    if robot.start == robot.goal:
        return f"waits at ({robot.start[0]:.1f}, {robot.start[1]:.1f})"
    return f"({robot.start[0]:.1f}, {robot.start[1]:.1f}) to ({robot.goal[0]:.1f}, {robot.goal[1]:.1f})"


def describe_task(task: RobotReading) -> str:
    if task.task == "wait":
        return f"waits at {task.location or task.start or 'its start'}"
    if task.task == "patrol":
        return f"patrols {task.location}"
    if task.task == "follow":
        return "follows someone"
    parts = ["crosses"]
    if task.start:
        parts.append(f"from {task.start}")
    if task.via:
        parts.append("via " + ", ".join(task.via))
    if task.destination:
        parts.append(f"to {task.destination}")
    return " ".join(parts)


# ---- applying the edit -----------------------------------------------------------------------------------

def apply_refinement(pipeline: GenerationPipeline, scene: Scene, refinement: Refinement, *,
                     on_event: Callable[[Event], None] | None = None,
                     cancel: threading.Event | None = None) -> GenerationResult:
    """The scenario with the refinement applied (module doc). The scene is not changed."""
    scenario = scene.scenario
    if scenario.preset != pipeline.preset.name or scenario.world != world_reference(pipeline.world):
        raise GenerationError(f"this pipeline is for world '{world_reference(pipeline.world)}' with preset "
                              f"'{pipeline.preset.name}', but the scenario is '{scenario.world}' with '{scenario.preset}'")
    pipeline.adopt_grid(scene.result.grid, scenario.resolution)  # the grid the scenario was planned on
    world, preset = pipeline.world, pipeline.preset
    seed = step_seed(int(scenario.seed), refinement.step)
    stages: dict[str, StageTiming] = {}
    clock = StageClock(on_event or (lambda event: None), cancel, stages)
    started = time.perf_counter()
    text = refinement.edit.sentence
    notes: list[str] = []
    models = dict(scenario.models)

    # 1. Trees: the model for groups whose behavior or places change, the old tree for the others.
    first_index = _first_free_index(scene)
    regenerated = [p for p in refinement.groups if p.regenerate]
    reused = [p for p in refinement.groups if p.status == CHANGED_STATUS and not p.regenerate]
    # Added groups the model does not write: their tree is the reading's own (`_fixed_by_reading`).
    fixed = [p for p in refinement.groups if p.status == ADDED_STATUS and not p.regenerate]
    plans: dict[int, GroupPlan] = {}  # id(PlannedGroup) -> its GroupPlan
    tokens = (0, 0)
    selection = None
    if regenerated:
        partial = PromptReading(text, tuple(p.reading for p in regenerated))
        # Retrieval asks for what the groups do ("cleaner x1: wander, location main_corridor"), not only
        # the follow-up's words ("add a cleaner mopping ..."), and for a few cards per group.
        query = f"{text}; {describe_reading_groups(partial)}"
        drafted = pipeline.draft(text, seed, clock, on_event, cancel, reading=partial, query=query,
                                 documents=DOCUMENTS_PER_GROUP * len(regenerated))
        selection = drafted.selection
        tokens = (drafted.synthesis.prompt_tokens, drafted.synthesis.completion_tokens)
        made = plan_groups(world, preset, drafted.synthesis.draft, selection, partial, notes, first_index=first_index)
        by_reading = {g.reading_index: g for g in made}
        for i, p in enumerate(regenerated):
            if i not in by_reading:
                raise GenerationError(f"the model's draft left out group '{p.reading.label}'; try again")
            plans[id(p)] = by_reading[i]
        first_index += len(made)
    t0 = clock.begin("postprocess")
    if selection is None:
        selection = select_rois(world, preset, PromptReading(text, tuple(p.reading for p in reused + fixed)))
    for p in fixed:
        tree = tree_for(p.reading, world, evacuation_field=preset.velocity == "field")
        spawn = p.reading.start or (selection.zones[0] if selection.zones else world.zones[0].name)
        draft = Draft((DraftGroup(p.reading.label, p.reading.count.value, spawn, tree),))
        (made_one,) = plan_groups(world, preset, draft, selection, PromptReading(text, (p.reading,)), notes,
                                  first_index=first_index)
        plans[id(p)] = made_one
        first_index += 1
    for p in reused:
        assert p.source is not None
        tree = _routine(p.source.tree)
        if not p.reading.together:
            tree = _without(tree, "JoinGroup")
        draft = Draft((DraftGroup(p.source.label, p.reading.count.value, p.source.spawn, tree),))
        (made_one,) = plan_groups(world, preset, draft, selection, PromptReading(text, (p.reading,)), notes,
                                  first_index=first_index)
        plans[id(p)] = made_one
        first_index += 1

    # 2. Placement beside the kept groups, then planning of the new agents only.
    placing = [p for p in refinement.groups if p.status != KEPT]
    groups = [plans[id(p)] for p in placing]
    for k, g in enumerate(groups):
        g.reading_index = k  # the combined reading below
    placing_reading = PromptReading(text, tuple(p.reading for p in placing))
    kept = [p.source for p in refinement.groups if p.status == KEPT and p.source is not None]
    changed = {plans[id(p)].index: p.source for p in placing if p.source is not None}
    occupied = placed_scene(scene, kept, changed)
    post = place_groups(world, pipeline.grid, preset, groups, selection, seed, placing_reading, notes, scene=occupied)
    clock.end("postprocess", t0, f"{len(post.agents)} agents placed, {sum(len(g.members) for g in kept)} kept")

    t0 = clock.begin("planning")
    plan = plan_operational(world, pipeline.grid, preset, post, seed, RobotRequest(enabled=False),
                            planner=pipeline.planner, cache=pipeline.plan_cache, cancel=cancel)
    check_trees(plan.trees)
    robot = _robot(pipeline, scene, refinement, post, kept, seed, notes)
    clock.end("planning", t0, f"{len(plan.agents)} agents planned")

    # 3. The scenario: kept agents and fields as they were, the new ones, in group order.
    new_agents = {a.id: a for a in plan.agents}
    agents: list[AgentSpec] = []
    trees: TreeFiles = {}  # the kept groups' documents as they were: written again, byte for byte
    fields = {}
    for p in refinement.groups:
        if p.status == KEPT and p.source is not None:
            for agent in scene.agents_of(p.source):
                agents.append(agent)
                trees[agent.tree] = scene.result.trees[agent.tree]
            for fid in _fields_of(scene, p.source):
                fields[fid] = scene.result.fields[fid]
        else:
            for member in plans[id(p)].member_ids:
                agent = new_agents[member]
                agents.append(agent)
                trees[agent.tree] = plan.trees[agent.tree]
    fields.update(plan.fields)
    refined = Scenario(world=scenario.world, preset=scenario.preset, prompt=scenario.prompt, seed=scenario.seed,
                       models=models, agents=tuple(agents), robot=robot,
                       fields={fid: f"fields/{fid}.npz" for fid in sorted(fields)}, resolution=scenario.resolution,
                       global_goals=dict(scenario.global_goals))

    # 4. The report: kept records as they were, the new ones, the history step, the grounding of all.
    stages_seconds = round(time.perf_counter() - started, 4)
    report = {k: v for k, v in scene.report.items()}
    records: list[GroupRecord] = []
    new_records = iter(group_records(post.groups, placing_reading, refinement.step))
    for p in refinement.groups:
        if p.status == KEPT and p.source is not None:
            records.append(p.source.record)
            continue
        record = next(new_records)
        record["asked_by"] = p.asked_by
        if p.changed_by:
            record["changed_by"] = list(p.changed_by)
        records.append(record)
    report["groups"] = records
    report["goals"] = [list(g) for g in post.goals]
    report["exits"] = sorted(set(report.get("exits") or ()) | set(post.exits))
    step_notes = post.notes + plan.notes + notes
    report["notes"] = list(report.get("notes", ())) + [f"follow-up {refinement.step}: {n}"
                                                       for n in dict.fromkeys(step_notes)]
    report["stages"] = stages
    report["total_seconds"] = stages_seconds
    report["prompt_tokens"], report["completion_tokens"] = tokens
    history = list(report.get("history", ()))
    history.append(HistoryStep(refinement.step, text, refinement.edit.to_dict(), refinement.diff, seed,
                               stages_seconds, stages).to_dict())
    report["history"] = history
    routes = planned_routes(agents, trees, planning_mode(preset.velocity, preset.planner.enabled))
    report["grounding"] = _grounding(scene, refinement, records, agents, post.agents, step_notes, world, robot,
                                     preset.max_vel, routes)
    return GenerationResult(refined, trees, fields, scene.result.grid, report, None)


def _first_free_index(scene: Scene) -> int:
    """GroupPlan indices for new groups: past every group and velocity field the scenario has
    (field ids are group_<index + 1>)."""
    numbers = [int(m.group(1)) for fid in scene.scenario.fields for m in [re.match(r"group_(\d+)", fid)] if m]
    return max([len(scene.groups)] + numbers)


def _fields_of(scene: Scene, group: SceneGroup) -> list[str]:
    first = group.record.get("field")
    if not first:
        return []
    prefix = re.match(r"group_\d+", str(first))
    stem = prefix.group(0) if prefix else str(first)
    return [fid for fid in scene.scenario.fields if fid == stem or fid.startswith(stem + "_")]


def _routine(tree: DraftNode) -> DraftNode:
    """A tree without the robot-reaction wrapper reconciliation put around it (it wraps it again, with the
    reaction the reading asks for now)."""
    if tree.node == "ReactiveFallback" and len(tree.children) == 2:
        cue = tree.children[0]
        if cue.node == "Sequence" and any(n.node in _REACTION_NODES for n in cue.walk()):
            return tree.children[1]
    return tree


def _without(tree: DraftNode, node: str) -> DraftNode:
    children = tuple(_without(c, node) for c in tree.children if c.node != node)
    if tree.node == "Sequence" and len(children) == 1 and tree.children and len(tree.children) == 2:
        return children[0]
    return DraftNode(tree.node, dict(tree.ports), children)


# ---- the robot -------------------------------------------------------------------------------------------

def _robot(pipeline: GenerationPipeline, scene: Scene, refinement: Refinement, post: PostProcessed,
           kept: Sequence[SceneGroup], seed: int, notes: list[str]) -> RobotSpec | None:
    current: RobotSpec | None = scene.scenario.robot
    plan = refinement.robot
    if plan.kind == "remove":
        return None
    if plan.kind == "keep" and current is None:
        return None
    world, grid = pipeline.world, pipeline.grid
    everyone = _everyone(scene, kept, post)
    reading: PromptReading | None = None
    if plan.kind == "keep" and current is not None:
        if current.task != "cross":
            return current  # it waits, patrols or follows where it did: nothing of its path to move
        formations = predict_formations(world, grid, [a.document for a in post.agents if a.document is not None],
                                        post.goals)
        clearance = current.radius + PASSING_MARGIN
        if not formations or nearest_formation_gap(formations, current.path or (current.start, current.goal)) >= clearance:
            return current
        notes.append("the robot's path was planned again around the new groups (same start and goal)")
        request = RobotRequest(current.start, current.goal)
    elif plan.kind == "default" or plan.task is None:
        request = RobotRequest()
    else:
        task = plan.task
        if task.task == "wait" and not (task.location or task.destination or task.start) and current is not None:
            return RobotSpec(start=current.start, goal=current.start, path=(current.start,), task="wait")
        # The follow-up's robot clause, planned as a sentence's is; a crossing that names only one end
        # keeps the other where the robot had it.
        request = RobotRequest()
        if task.task == "cross" and current is not None:
            if task.destination and not (task.start or task.via):
                request = RobotRequest(start=current.start)
            elif (task.start or task.via) and not task.destination:
                request = RobotRequest(goal=current.goal)
        reading = PromptReading(refinement.edit.sentence, (), robot=task)
        if task.task == "follow":  # whom it follows is a group of the scenario, kept or new
            reading, everyone = _whole_view(scene, refinement, everyone, task)
    try:
        return plan_robot(world, grid, CachedPlanner(world.name, pipeline.planner, pipeline.plan_cache), everyone,
                          request, seed, notes, reading=reading)
    except PlanningError as exc:
        raise GenerationError(f"the robot cannot be planned as asked: {exc}") from None


def _everyone(scene: Scene, kept: Sequence[SceneGroup], post: PostProcessed) -> PostProcessed:
    """Kept and new agents as the robot's planner reads them: starts, zones and trees."""
    world = scene.world
    agents: list[AgentPlan] = []
    for g in kept:
        for a in scene.agents_of(g):
            zone = world.zone_at(*a.start)
            spawn = zone.name if zone is not None else a.zone
            agents.append(AgentPlan(a.id, -1, a.group, a.label, a.start, spawn, [], a.zone or spawn, g.tree,
                                    document=scene.document(a)))
    agents += post.agents
    return PostProcessed(agents, list(post.groups), post.exit, list(post.goals), [], list(post.exits))


def _whole_view(scene: Scene, refinement: Refinement, everyone: PostProcessed,
                robot: RobotReading) -> tuple[PromptReading, PostProcessed]:
    """The refined scenario as one sentence's reading and groups (reading_index into it), for the
    robot's planner to find the group its clause names among kept and new groups alike."""
    readings = tuple(p.reading for p in refinement.groups)
    new_groups = iter(everyone.groups)  # in the order of the groups placed (added and changed)
    groups: list[GroupPlan] = []
    for i, p in enumerate(refinement.groups):
        if p.status == KEPT and p.source is not None:
            g = p.source
            groups.append(GroupPlan(-1000 - i, g.label, len(g.members), g.spawn, g.tree, p.reading.who,
                                    member_ids=list(g.members), reading_index=i))
        else:
            groups.append(replace(next(new_groups), reading_index=i))
    view = PostProcessed(everyone.agents, groups, everyone.exit, list(everyone.goals), [], list(everyone.exits))
    return PromptReading(refinement.edit.sentence, readings, robot=robot), view


# ---- the grounding report --------------------------------------------------------------------------------

@dataclass
class _Grounded:
    """A group as the grounding report reads it (post-processing's GroupPlan fields it uses)."""

    index: int
    reading_index: int
    label: str
    count: int
    spawn: str
    tree: DraftNode
    behavior: str
    member_ids: list[int]
    spawn_zones: dict[str, int]
    added: tuple[str, ...] = ()


@dataclass
class _GroundedAgent:
    """An agent as the grounding report reads it (post-processing's AgentPlan fields it uses)."""

    id: int
    group_index: int
    label: str
    start: tuple[float, float]
    targets: list[tuple[str, tuple[float, float]]]
    zone: str
    max_vel: float
    behavior: str


def _grounding(scene: Scene, refinement: Refinement, records: Sequence[GroupRecord], agents: Sequence[AgentSpec],
               new_agents: Sequence[AgentPlan], repairs: Sequence[str], world: World, robot: RobotSpec | None,
               walking_speed: float, routes: Mapping[int, Sequence[Leg]]) -> JSONObject:
    """The grounding report of the refined scenario: every group against the reading it realises now
    (its sentence's, or a follow-up's), which sentence asked for it and which changed it."""
    from grove_tui.generation.scene import node_from_dict, targets_of

    sentences = scene.sentences + [refinement.edit.sentence]
    readings = tuple(p.reading for p in refinement.groups)
    asked_robot = refinement.robot.task if refinement.robot.kind == "task" else None
    combined = PromptReading(" / ".join(sentences), readings, robot=asked_robot)
    grounded = [_Grounded(i, i, str(r["label"]), int(r["count"]), str(r.get("spawn", "")),
                          node_from_dict(r["tree"]) if r.get("tree") else p.source.tree if p.source else DraftNode("Wait"),
                          str(r.get("behavior", "Regular")), [int(m) for m in r.get("members", ())],
                          dict(r.get("spawn_zones") or {}), tuple(str(a) for a in r.get("added", ())))
                for i, (r, p) in enumerate(zip(records, refinement.groups))]
    group_of = {m: g.index for g in grounded for m in g.member_ids}
    placed = {a.id: a for a in new_agents}
    people = []
    for a in agents:
        targets = list(placed[a.id].targets) if a.id in placed else targets_of(scene.document(a))
        people.append(_GroundedAgent(a.id, group_of.get(a.id, -1), a.label, a.start, targets, a.zone, a.max_vel,
                                     a.behavior))
    report = grounding_report(combined, grounded, people, world, repairs, robot=robot, walking_speed=walking_speed,
                              routes=routes)
    asked = {tuple(g.member_ids): p for g, p in zip(grounded, refinement.groups)}
    groups = tuple(replace(g, asked_by=asked[g.members].asked_by, changed_by=asked[g.members].changed_by)
                   if g.members in asked else g for g in report.groups)
    robot_row = report.robot
    if refinement.robot.kind == "keep" and robot is not None:
        before = scene.report.get("grounding")
        robot_row = GroundingReport.from_dict(before).robot if isinstance(before, dict) else robot_row
    from grove_tui.generation.run_length import with_run_length

    return with_run_length(replace(report, groups=groups, robot=robot_row, sentences=tuple(sentences),
                                   unsure=report.unsure)).to_dict()
