"""`grove import`: bring another tool's scenario into GROVE as a bundle."""

from __future__ import annotations

from pathlib import Path

import click


@click.group("import")
def import_group() -> None:
    """Import a scenario written for another simulator as a GROVE bundle."""


@import_group.command("hunav")
@click.argument("agents_yaml", type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.option("--out", "out_dir", required=True, type=click.Path(file_okay=False, path_type=Path),
              help="Bundle folder to write (a previous bundle is replaced, any other non-empty folder refused).")
@click.option("--world", default=None,
              help="GROVE world (name or YAML) the scenario plays in; default: the YAML's `map` when GROVE knows "
                   "it, else an open floor around the agents and goals.")
@click.option("--trees", "trees_dir", default=None, type=click.Path(exists=True, file_okay=False, path_type=Path),
              help="Folder of <yaml_base_name>__agent_<id>_bt.xml; default: beside the YAML, then ../behavior_trees.")
@click.option("--overwrite", is_flag=True, help="Replace --out even when it is a folder that is not a bundle.")
def import_hunav_command(agents_yaml: Path, out_dir: Path, world: str | None, trees_dir: Path | None,
                         overwrite: bool) -> None:
    """A HuNavSim scenario (1.0 or 2.0 layout: agents, goals, behavior trees) as a bundle GROVE simulates.

    Nothing HuNavSim's loader reads is lost: `grove export hunav` on the bundle writes the same file back."""
    from grove_tui.exports.hunav_import import import_hunav

    bundle = import_hunav(agents_yaml, out_dir, world=world, trees_dir=trees_dir, overwrite=overwrite)
    click.echo(str(bundle))
