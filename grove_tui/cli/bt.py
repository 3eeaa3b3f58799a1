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
    from grove_tui.bt.format.manifest import NODES, nodes_for_preset, treenodes_model_xml

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

    Exit status, as linters have it: 0 when every file is fine, 1 when a file has problems, 2 when a
    file could not be read at all (missing, a folder, device or pipe, over the size limit). Every file
    is still checked; the highest status wins.
    """
    from grove_tui.bt.format.source import MAX_BYTES, read_file_bytes
    from grove_tui.bt.format.xml import check_tree_bytes
    from grove_tui.errors import EXIT_BAD_INPUT, BTError, print_error

    bad = unreadable = 0
    for path in files:
        try:
            data = read_file_bytes(path)
        except BTError as error:
            # Nothing to check: one `error:` line naming the file ("PATH: does not exist").
            unreadable += 1
            print_error(BTError(error.message,
                                hint=f"give readable tree XML files (regular files of at most {MAX_BYTES:,} bytes)"))
            continue
        problems = check_tree_bytes(path, data)
        if problems:
            bad += 1
            for problem in problems:
                click.echo(str(problem), err=True)
        else:
            click.echo(f"{path}: ok")
    if bad:
        unread = f"; {unreadable} could not be read" if unreadable else ""
        click.echo(f"{bad} of {len(files)} file(s) have problems{unread}", err=True)
    if unreadable:
        sys.exit(EXIT_BAD_INPUT)
    if bad:
        sys.exit(1)
