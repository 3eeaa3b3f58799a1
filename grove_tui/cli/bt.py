"""`grove bt`: the behavior-tree node manifest and tree validation."""

from __future__ import annotations

import sys
from pathlib import Path

import click


@click.group("bt")
def bt() -> None:
    """Behavior trees: node manifest (Groot2 TreeNodesModel) and validation of tree files."""


@bt.command("manifest")
@click.option("--list", "as_list", is_flag=True, help="One line per node (category, origin, ports) instead of XML.")
@click.option("--preset", default=None, help="Only the nodes the model may use in this preset.")
def manifest(as_list: bool, preset: str | None) -> None:
    """Print every node as a Groot2/BehaviorTree.CPP v4 TreeNodesModel."""
    from grove_tui.bt.manifest import NODES, nodes_for_preset, treenodes_model_xml

    if not as_list and preset is None:
        click.echo(treenodes_model_xml(), nl=False)
        return
    specs = nodes_for_preset(preset) if preset else list(NODES.values())
    for spec in specs:
        ports = ", ".join(f"{p.name}{'*' if p.auto else ''}:{p.type}" for p in spec.ports)
        nav = " navigates" if spec.navigates else ""
        click.echo(f"{spec.name:24} {spec.category:9} {spec.origin:8}{nav}  ({ports})")


@bt.command("validate")
@click.argument("files", nargs=-1, required=True, type=click.Path(dir_okay=False))
def validate(files: tuple[str, ...]) -> None:
    """Check behavior-tree XML files against the manifest; print every problem with its line.

    Exit status 1 when any file has a problem, 2 when a file is missing (the others are still checked).
    """
    import os

    from grove_tui.bt.xml import check_tree_file
    from grove_tui.errors import BadInputError

    missing = [path for path in files if not os.path.lexists(path)]
    if len(missing) == len(files):
        # Nothing to check is bad input (exit 2), unlike a tree with problems (exit 1).
        raise BadInputError(f"{missing[0]}: no such tree file" + (f" (and {len(missing) - 1} more)" if len(missing) > 1 else ""))
    # Like a linter: every file is checked and every problem listed (devices, pipes and links to them
    # are problems of their own, named by check_tree_file), then the worst status wins.
    bad = 0
    for path in files:
        problems = check_tree_file(path)
        if problems:
            bad += 1
            for problem in problems:
                click.echo(str(problem), err=True)
        else:
            click.echo(f"{path}: ok")
    if bad:
        click.echo(f"{bad} of {len(files)} file(s) have problems", err=True)
        sys.exit(2 if missing else 1)
