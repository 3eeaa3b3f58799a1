"""`grove export`, `grove metrics`, `grove picture`: what a researcher carries on from a bundle."""

from __future__ import annotations

import json
import math
from pathlib import Path

import click
from rich.console import Console
from rich.table import Table

from grove_tui.jsontypes import JSONObject
from grove_tui.services.session import GroveSession

_bundle_argument = click.argument("bundle", type=click.Path(exists=True, file_okay=False, path_type=Path))


@click.group()
def export() -> None:
    """Export a bundle for HuNavSim (Gazebo, Isaac Sim), PedPy, ROS 2 (bags) and Foxglove."""


@export.command("hunav")
@_bundle_argument
@click.option("--out", "out_dir", required=True, type=click.Path(file_okay=False, path_type=Path),
              help="Folder to write agents yaml and BT XML files into (created; a previous export is replaced, "
                   "any other non-empty folder is refused).")
@click.option("--overwrite", is_flag=True, help="Replace --out even when it is a folder that is not an export.")
@click.option("--keep-grove-nodes", is_flag=True,
              help="Keep GROVE-only nodes (Queue, FollowVelocityField...) and write their TreeNodesModel, "
                   "instead of lowering them to HuNavSim nodes.")
@click.option("--simulator", default=None,
              type=click.Choice(["Gazebo Classic", "Gazebo Fortress", "Isaac Sim", "Webots"]),
              help="HuNavSim wrapper the files are for (default: an imported scenario's own, else Gazebo Classic).")
@click.option("--base-name", default=None,
              help="yaml_base_name (default: an imported scenario's own, else agents_<world>).")
def export_hunav_command(bundle: Path, out_dir: Path, overwrite: bool, keep_grove_nodes: bool, simulator: str,
                         base_name: str | None) -> None:
    """HuNavSim agents yaml and one BehaviorTree.CPP v4 file per agent (2.0), with the world and map.

    A bundle imported from HuNavSim gets its own file back: its layout (1.0 or 2.0), parameters and trees."""
    result = GroveSession().export("hunav", bundle, out_dir, lower=not keep_grove_nodes, simulator=simulator,
                                   base_name=base_name, overwrite=overwrite, trajectories=True)
    copied = result.trajectories
    click.echo(str(result.agents_yaml))
    for path in result.trees:
        click.echo(str(path))
    if result.nodes_model is not None:
        click.echo(str(result.nodes_model))
    for path in (result.world_file, result.map_yaml, result.readme):
        if path is not None:
            click.echo(str(path))
    for path in copied:
        click.echo(str(path))


@export.command("trajectories")
@_bundle_argument
@click.option("--out", "out_dir", required=True, type=click.Path(file_okay=False, path_type=Path),
              help="Folder for trajectories.csv, .sqlite (PedPy / JuPedSim schema) and .txt (created; a previous "
                   "trajectories export is replaced, any other non-empty folder is refused).")
@click.option("--overwrite", is_flag=True, help="Replace --out even when it is a folder that is not a trajectories "
                                                 "export.")
def export_trajectories_command(bundle: Path, out_dir: Path, overwrite: bool) -> None:
    """Trajectories as CSV and as a JuPedSim sqlite file that PedPy loads, with the walkable area."""
    paths = GroveSession().export("trajectories", bundle, out_dir, overwrite=overwrite)
    for path in paths:
        click.echo(str(path))


def _format(value: float) -> str:
    if isinstance(value, float) and math.isnan(value):
        return "n/a"
    return f"{value:.3f}".rstrip("0").rstrip(".") if isinstance(value, float) else str(value)


@click.command()
@_bundle_argument
@click.option("--json", "as_json", is_flag=True,
              help="Print the metrics as JSON instead of tables (with the checked grounding report under "
                   "\"grounding\" when the bundle has one).")
def metrics(bundle: Path, as_json: bool) -> None:
    """Robot (HuNavSim evaluator) and crowd metrics of a simulated bundle, and the sentence's grounding
    report checked on its run; writes metrics.json and grounding.json."""
    from grove_tui.scenario.report import GroundingReport

    written = GroveSession().metrics(bundle)
    report, path, checked, grounding_path = written.metrics, written.metrics_file, written.grounding, \
        written.grounding_file
    if as_json:
        data: JSONObject = dict(report.to_dict())
        if checked is not None:
            data["grounding"] = checked
        click.echo(json.dumps(data, indent=2, sort_keys=True, allow_nan=True, ensure_ascii=False))
        return
    console = Console()
    for title, values in (("Robot", report.robot), ("Crowd", report.crowd)):
        if not values:
            continue
        table = Table(title=title, title_justify="left", show_header=False, box=None, padding=(0, 2))
        for key in sorted(values):
            table.add_row(key.replace("_", " "), _format(values[key]))
        console.print(table)
    if checked is not None:
        console.print("[bold]Grounding[/] (the sentence's claims checked on this run)", highlight=False)
        for line in GroundingReport.from_dict(checked).lines():
            console.print("  " + line, markup=False, highlight=False)
    console.print(f"[dim]written to {path}" + (f" and {grounding_path}" if checked is not None else "") + "[/]",
                  highlight=False)


@click.command()
@_bundle_argument
@click.option("--out", "out_path", type=click.Path(dir_okay=False, path_type=Path),
              help="PNG, SVG or PDF file to write. Without it, the scenario is drawn in the terminal.")
@click.option("--trajectories/--no-trajectories", default=True, show_default=True,
              help="Draw the simulated trajectories when the bundle has them.")
@click.option("--width", default=None, type=int, help="Terminal drawing width in columns.")
@click.option("--overwrite", is_flag=True, help="Replace --out even when it is a file GROVE did not draw.")
def picture(bundle: Path, out_path: Path | None, trajectories: bool, width: int | None, overwrite: bool) -> None:
    """Picture of a scenario: map, zones, spawns, goals, waypoints, velocity fields, trajectories."""
    if out_path is None:
        console = Console()
        console.print(GroveSession().picture(bundle, width=width or console.width))
        return
    written = GroveSession().picture(bundle, out_path, trajectories=trajectories, overwrite=overwrite)
    click.echo(str(written))


@export.command("rosbag")
@_bundle_argument
@click.option("--out", "out_dir", required=True, type=click.Path(file_okay=False, path_type=Path),
              help="Bag folder to write (metadata.yaml and the storage file; a previous bag export is replaced, "
                   "any other non-empty folder is refused).")
@click.option("--storage", type=click.Choice(["mcap", "sqlite3"]), default="mcap", show_default=True,
              help="rosbag2 storage plugin.")
@click.option("--overwrite", is_flag=True, help="Replace --out even when it is a folder that is not a bag export.")
@click.option("--hunav-msgs", "hunav_msgs", type=click.Choice(["2.0", "1.0"]), default="2.0", show_default=True,
              help="HuNavSim's message version for /human_states and /robot_states: 2.0 (Agent with a nested "
                   "AgentBehavior) or 1.0 (uint8 behavior, behavior_state).")
def export_rosbag_command(bundle: Path, out_dir: Path, storage: str, overwrite: bool, hunav_msgs: str) -> None:
    """ROS 2 bag of a simulated bundle: hunav_msgs/Agents on /human_states, markers, /map, /plan, /tf, events."""
    result = GroveSession().export("rosbag", bundle, out_dir, storage=storage, overwrite=overwrite,
                                   hunav_msgs_version=hunav_msgs)
    click.echo(str(result.directory))
    for topic, count in result.counts.items():
        click.echo(f"  {topic}: {count}", err=True)


@export.command("foxglove")
@_bundle_argument
@click.option("--out", "out_path", required=True, type=click.Path(dir_okay=False, path_type=Path),
              help="The .mcap file to write; its Foxglove layout goes beside it as <name>.layout.json (a previous "
                   "export is replaced; any other file is refused).")
@click.option("--overwrite", is_flag=True, help="Replace --out and its layout file even when GROVE did not write them.")
def export_foxglove_command(bundle: Path, out_path: Path, overwrite: bool) -> None:
    """Foxglove MCAP of a simulated bundle (SceneUpdate, Grid, Log) and a layout that shows it in 3D."""
    result = GroveSession().export("foxglove", bundle, out_path, overwrite=overwrite)
    click.echo(str(result.mcap))
    click.echo(str(result.layout))
