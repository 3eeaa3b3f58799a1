"""`grove worlds list|show|check`: browse the shipped worlds and validate your own."""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

import click
from rich.console import Console
from rich.table import Table
from rich.text import Text

from grove_tui.errors import WorldError
from grove_tui.services.session import GroveSession

if TYPE_CHECKING:
    from grove_tui.services.session import World  # the type the session's load_world returns


def _console() -> Console:
    # click.testing.CliRunner swaps sys.stdout; bind to the current one each call.
    return Console(file=sys.stdout, highlight=False, soft_wrap=False)


def _size(world: World) -> str:
    xmin, ymin, xmax, ymax = world.bounds()
    return f"{xmax - xmin:g} x {ymax - ymin:g} m"


@click.group()
def worlds() -> None:
    """Semantic worlds: zones, doors, entities (the places prompts can name)."""


@worlds.command("list")
def list_command() -> None:
    """List the shipped worlds."""
    console = _console()
    table = Table(title="Shipped worlds", title_justify="left")
    for column in ("name", "size", "zones", "doors", "exits", "entities", "description"):
        table.add_column(column, overflow="fold", no_wrap=column != "description")
    failures = []
    session = GroveSession()
    for name in session.list_worlds():
        try:
            world = session.load_world(name)
        except WorldError as error:
            failures.append(str(error))
            table.add_row(name, "", "", "", "", "", Text("does not load; run `grove worlds check`", style="red"))
            continue
        table.add_row(world.name, _size(world), str(len(world.zones)), str(len(world.doors())),
                      str(len(world.exits())), str(len(world.entities())), world.description)
    console.print(table)
    if failures:
        raise SystemExit(1)


@worlds.command("show")
@click.argument("name")
@click.option("--width", type=int, default=None, help="Map width in columns (default: the terminal width).")
@click.option("--height", type=int, default=None, help="Largest map height in rows (default: as tall as needed).")
@click.option("--rois/--no-rois", default=False, help="Also list every zone, door and entity by name.")
def show_command(name: str, width: int | None, height: int | None, rois: bool) -> None:
    """Draw a world (a shipped NAME or a path): walls, doors, exits, zone labels, entities."""
    console = _console()
    session = GroveSession()
    world = session.load_world(name)
    drawing, legend = session.world_map(world, width or console.width, height)
    console.print(Text.assemble((world.name, "bold"), f"  {_size(world)}, {len(world.zones)} zones, "
                                f"{len(world.doors())} doors ({len(world.exits())} exits), "
                                f"{len(world.entities())} entities"))
    if world.description:
        console.print(Text(world.description, style="dim"))
    console.print(drawing, crop=True)
    console.print(legend)
    if rois:
        console.print(_roi_table(world))


def _roi_table(world: World) -> Table:
    table = Table(title="Regions of interest", title_justify="left")
    table.add_column("kind", no_wrap=True, min_width=6)
    for column in ("name", "zone", "type", "point"):
        table.add_column(column, no_wrap=True)
    table.add_column("aliases", overflow="fold", ratio=1)
    for roi in world.roi_index():
        extra = f" -> {roi.leads_to}" if roi.kind == "door" else ""
        table.add_row(roi.kind, roi.name, roi.zone, roi.type + extra, f"({roi.point[0]:g}, {roi.point[1]:g})",
                      ", ".join(roi.aliases))
    return table


@worlds.command("check")
@click.argument("files", nargs=-1, required=True)
def check_command(files: tuple[str, ...]) -> None:
    """Validate world YAML FILES (or shipped names) and print every problem.

    Exit status, as linters have it: 0 when every file is fine, 1 when a file has problems (each
    listed with its line), 2 when a file could not be read at all (missing, an unknown name, not a
    regular file, over the size limit, not UTF-8). Every file is still checked; the highest status wins.
    """
    from grove_tui.errors import EXIT_BAD_INPUT, print_error

    console = _console()
    session = GroveSession()
    total = unreadable = 0
    for item in files:
        try:
            # One parse reports every problem (a 20,000-zone world parsed twice took twice as long).
            path, world, problems = session.check_world_file(item)
        except WorldError as error:
            # Nothing to lint: one `error:` line naming the file, and the others are still checked.
            unreadable += 1
            print_error(error)
            continue
        if world is not None:  # parse_world returns a world only when it found no problem
            console.print(Text.assemble(("ok ", "bold green"), f"{path}: {len(world.zones)} zones, "
                                        f"{len(world.doors())} doors, {len(world.entities())} entities"))
            continue
        total += len(problems)
        console.print(Text.assemble((f"{len(problems)} problem{'s' if len(problems) != 1 else ''} ", "bold red"),
                                    f"in {path}:"))
        for problem in problems:
            console.print(Text("  " + str(problem)), soft_wrap=True)
    if unreadable:
        raise SystemExit(EXIT_BAD_INPUT)
    if total:
        raise SystemExit(1)
