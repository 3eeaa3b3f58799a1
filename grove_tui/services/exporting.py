"""The one list of export formats: what `grove export KIND`, a batch job's `export` list and the app's
export dialog write, each format once (`FORMATS`).

A format has up to two writers:
- `write(bundle, out, **options)`: one format of a bundle into `out` (`GroveSession.export`; `grove export`
  and batch jobs), returning that exporter's result;
- `in_app(ctx)`: its step of the app's "export everything" (`GroveSession.export_all`), into a fresh folder
  that holds a copy of the bundle, the run the app played, and every other format beside it.
Heavy exporters are imported when a format is written, never when this list is read.
"""

from __future__ import annotations

import shutil
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from grove_tui.services.session import GeneratedScenario, GroveSession
    from grove_tui.simulation.simulation import Simulation
    from grove_tui.exports.foxglove import FoxgloveExport
    from grove_tui.exports.hunav import HunavExport
    from grove_tui.exports.rosbag import RosbagExport


@dataclass(frozen=True)
class ExportedFile:
    kind: str
    path: Path
    note: str = ""  # why it is missing, when an exporter could not write it


@dataclass
class ExportContext:
    """What the app's export steps share: the scenario, the run it played (None before playing), and the
    folder they write into (the bundle's copy is `bundle`; later steps read what earlier ones wrote)."""

    generated: GeneratedScenario
    simulation: Simulation | None
    out_dir: Path
    session: GroveSession
    files: list[ExportedFile] = field(default_factory=list)

    @property
    def bundle(self) -> Path:
        return self.out_dir / "bundle"

    @property
    def trajectories(self) -> Path:
        return self.bundle / "trajectories.csv"

    def add(self, kind: str, path: Path, note: str = "") -> None:
        self.files.append(ExportedFile(kind, path, note))


Exporter = Callable[[ExportContext], None]
BundleExporter = Callable[..., object]  # (bundle, out, **options) -> the exporter's result


# --- one format of a bundle (`grove export`, batch jobs) --------------------------------------------------
def _write_hunav(bundle: Path, out: Path, **options: Any) -> HunavExport:  # Any: export_hunav's options
    from grove_tui.exports.hunav import export_hunav

    return export_hunav(bundle, out, **options)


def _write_trajectories(bundle: Path, out: Path, **options: Any) -> list[Path]:  # Any: its writer's options
    from grove_tui.exports.trajectories import export_trajectories

    return export_trajectories(bundle, out, **options)


def _write_rosbag(bundle: Path, out: Path, **options: Any) -> RosbagExport:  # Any: export_rosbag's options
    from grove_tui.exports.rosbag import export_rosbag

    return export_rosbag(bundle, out, **options)


def _write_foxglove(bundle: Path, out: Path, **options: Any) -> FoxgloveExport:  # Any: its writer's options
    from grove_tui.exports.foxglove import export_foxglove

    return export_foxglove(bundle, out, **options)


# --- the app's export steps ------------------------------------------------------------------------------
def export_bundle(ctx: ExportContext) -> None:
    shutil.copytree(ctx.generated.bundle_dir, ctx.bundle)
    ctx.add("bundle", ctx.bundle)


def export_run(ctx: ExportContext) -> None:
    """Trajectories and the event log go into the exported bundle, so `grove metrics` reads it as is."""
    if ctx.simulation is None:
        return
    from grove_tui.scenario.events import write_events

    recorder = getattr(ctx.simulation, "recorder", None)
    if recorder is None:
        ctx.add("trajectories", ctx.trajectories, "not recorded: this simulation has no trajectory recorder")
    else:
        recorder.write_csv(ctx.trajectories)
        ctx.add("trajectories", ctx.trajectories)
    events = write_events(ctx.bundle / "events.jsonl", ctx.simulation.events)
    ctx.add("events", Path(events))


def export_metrics(ctx: ExportContext) -> None:
    if ctx.simulation is None or not ctx.trajectories.exists():
        return
    from grove_tui.analysis.bundle_metrics import bundle_metrics

    _report, path = bundle_metrics(ctx.bundle)
    ctx.add("metrics", Path(path))


def export_hunav_files(ctx: ExportContext) -> None:
    result = ctx.session.export("hunav", ctx.bundle, ctx.out_dir / "hunav")
    ctx.add("hunav", Path(result.agents_yaml), f"+ {len(result.trees)} agent trees")


def export_picture(ctx: ExportContext) -> None:
    from grove_tui.exports.pictures import draw_scenario

    trajectories = ctx.trajectories if ctx.trajectories.exists() else None
    path = draw_scenario(ctx.generated.world, ctx.generated.scenario, ctx.bundle, ctx.out_dir / "scenario.png",
                         trajectories=trajectories, title=ctx.generated.prompt[:80])
    ctx.add("picture", Path(path))


def _ros_export_possible(ctx: ExportContext, kind: str, out: Path, missing: Callable[[], str | None]) -> bool:
    """Whether an export of the run that needs the `ros` extra can be written; False after noting why
    not (no run; the extra missing)."""
    if ctx.simulation is None or not ctx.trajectories.exists():
        return False
    why = missing()
    if why is not None:
        ctx.add(kind, out, f"not written: {why}")
        return False
    return True


def export_rosbag_files(ctx: ExportContext) -> None:
    """A ROS 2 bag of the run; a note instead when the `ros` extra is missing."""
    from grove_tui.exports.rosbag import missing_dependency

    out = ctx.out_dir / "rosbag"
    if _ros_export_possible(ctx, "rosbag", out, missing_dependency):
        result: RosbagExport = ctx.session.export("rosbag", ctx.bundle, out)
        ctx.add("rosbag", result.directory, f"{result.frames} frames")


def export_foxglove_files(ctx: ExportContext) -> None:
    """A Foxglove MCAP of the run and its layout; a note instead when the `ros` extra is missing."""
    from grove_tui.exports.foxglove import missing_dependency

    out = ctx.out_dir / "scenario.mcap"
    if _ros_export_possible(ctx, "foxglove", out, missing_dependency):
        result: FoxgloveExport = ctx.session.export("foxglove", ctx.bundle, out)
        ctx.add("foxglove", result.mcap, f"+ layout {result.layout.name}")


@dataclass(frozen=True)
class ExportFormat:
    kind: str
    what: str
    write: BundleExporter | None = None  # `grove export KIND` and batch jobs; None: the app's step only
    in_app: Exporter | None = None  # the app's export-everything step; None: `grove export` only
    needs_run: bool = False  # reads the simulated run (trajectories.csv)
    batch_suffixes: tuple[str, ...] = ()  # what a batch job's export of it is named beside its bundle


# In the app's order: a step reads what the steps before it wrote into the exported bundle (the run's
# trajectories before metrics, picture, bag and MCAP).
FORMATS: tuple[ExportFormat, ...] = (
    ExportFormat("bundle", "a copy of the scenario bundle", in_app=export_bundle),
    ExportFormat("hunav", "HuNavSim agents YAML and one BehaviorTree.CPP file per agent, with world and map",
                 write=_write_hunav, in_app=export_hunav_files, batch_suffixes=(".hunav",)),
    ExportFormat("trajectories", "the run's trajectories (CSV; `grove export`: also PedPy's sqlite and txt)",
                 write=_write_trajectories, in_app=export_run, needs_run=True, batch_suffixes=(".trajectories",)),
    ExportFormat("metrics", "robot and crowd metrics of the run (metrics.json)", in_app=export_metrics,
                 needs_run=True),
    ExportFormat("picture", "a picture of the scenario and its trajectories", in_app=export_picture),
    ExportFormat("rosbag", "a ROS 2 bag of the run (hunav_msgs, markers, map, tf)", write=_write_rosbag,
                 in_app=export_rosbag_files, needs_run=True, batch_suffixes=(".rosbag",)),
    ExportFormat("foxglove", "a Foxglove MCAP of the run and its layout", write=_write_foxglove,
                 in_app=export_foxglove_files, needs_run=True, batch_suffixes=(".mcap", ".layout.json")),
)
BY_KIND = {f.kind: f for f in FORMATS}
# `grove export` formats, also what a batch job's "export" key may list.
EXPORT_FORMATS = tuple(f.kind for f in FORMATS if f.write is not None)
NEEDS_RUN = frozenset(f.kind for f in FORMATS if f.write is not None and f.needs_run)
EXPORT_SUFFIXES = tuple(suffix for f in FORMATS for suffix in f.batch_suffixes)
# The app's export-everything steps, in order.
APP_EXPORTERS: list[tuple[str, Exporter]] = [(f.kind, f.in_app) for f in FORMATS if f.in_app is not None]
