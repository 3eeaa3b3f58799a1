"""A sentence planned from a hand-written draft (the reader, reconciliation, post-processing, Theta* and
the grounding report; no model) and written as a bundle a real simulation can run."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from grove_tui.analysis.metrics import iter_trajectory_chunks
from grove_tui.analysis.outcomes import OutcomeChecker, check_bundle
from grove_tui.generation.draft import Draft, DraftGroup
from grove_tui.generation.pipeline import GenerationResult
from grove_tui.generation.planning import OperationalPlan, plan_operational
from grove_tui.generation.postprocess import postprocess
from grove_tui.generation.presets import load_preset
from grove_tui.generation.reconcile import grounding_report, with_followed_person
from grove_tui.generation.rois import select_rois
from grove_tui.generation.route_time import Leg, planned_routes, planning_mode
from grove_tui.language.reading import read_prompt
from grove_tui.navigation.grid import build_grid
from grove_tui.scenario.bundle import load_scenario, write_bundle
from grove_tui.scenario.events import read_events
from grove_tui.scenario.model import Scenario
from grove_tui.scenario.report import GroundingReport
from grove_tui.services.session import GroveSession
from grove_tui.world.model import World

NODES = ("Sequence", "GoTo", "Wait", "Queue", "Converse", "Wander", "FollowVelocityField", "JoinGroup")


@dataclass
class PlannedRun:
    op: OperationalPlan
    routes: dict[int, tuple[Leg, ...]]
    report: GroundingReport
    bundle: Path

    def run(self, seconds: float) -> GroundingReport:
        """Simulate the bundle for `seconds` and check its report on the run."""
        GroveSession().simulate(self.bundle, seconds)
        return check_bundle(self.bundle, write=False)[0]

    def check(self, planned: GroundingReport, world: World) -> GroundingReport:
        """Another planned report (claims moved to other members) checked on the run `run` made."""
        checker = OutcomeChecker(planned, load_scenario(self.bundle), world)
        ids, _, chunks = iter_trajectory_chunks(self.bundle / "trajectories.csv")
        checker.set_ids(ids)
        for chunk in chunks:
            checker.add(chunk)
        return checker.result(read_events(self.bundle / "events.jsonl"))


def plan_by_hand(world: World, preset_name: str, prompt: str, groups: tuple[DraftGroup, ...],
                 out: Path, as_the_pipeline: bool = False) -> PlannedRun:
    """`as_the_pipeline`: the reading completed as the pipeline does (people followed, subsets) before planning."""
    preset = load_preset(preset_name)
    grid = build_grid(world)
    reading = read_prompt(prompt, world)
    if as_the_pipeline:
        reading = with_followed_person(reading, world)
    post = postprocess(world, grid, preset, Draft(groups), select_rois(world, preset, reading), 0, reading, NODES)
    op = plan_operational(world, grid, preset, post, 0, reading=reading)
    routes = planned_routes(op.agents, op.trees, planning_mode(preset.velocity, preset.planner.enabled))
    report = grounding_report(reading, post.groups, post.agents, world, post.notes + op.notes, robot=op.robot,
                              walking_speed=preset.max_vel, routes=routes)
    scenario = Scenario(world=str(world.source), preset=preset.name, prompt=prompt, seed=0, models={"bt": "hand"},
                        agents=tuple(op.agents), robot=op.robot,
                        fields={fid: f"fields/{fid}.npz" for fid in op.fields})
    result = GenerationResult(scenario, op.trees, op.fields, grid,
                              {"stages": {}, "notes": post.notes, "grounding": report.to_dict()})
    return PlannedRun(op, routes, report, write_bundle(result, out))
