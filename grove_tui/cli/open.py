"""`grove open BUNDLE`: the app, opened on a saved bundle's inspect screen."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from grove_tui.errors import GroveError

EXIT_BAD_INPUT = 2


@click.command("open")
@click.argument("bundle", type=click.Path(path_type=Path))
@click.pass_context
def open_command(ctx: click.Context, bundle: Path) -> None:
    """Open a saved scenario bundle (e.g. one under the runs folder) in the app's inspect screen."""
    from grove_tui.scenario.bundle import load_bundle

    # Check the bundle before the app takes the terminal, so a wrong path is one line on stderr.
    try:
        load_bundle(bundle)
    except GroveError as exc:
        hint = getattr(exc, "hint", "") or "give a folder GROVE wrote (it holds scenario.yaml, trees/, grid.npz)"
        click.echo(f"error: {exc}\nhint: {hint}", err=True)
        sys.exit(getattr(exc, "exit_code", EXIT_BAD_INPUT) or EXIT_BAD_INPUT)
    from grove_tui.cli import open_app

    options = ctx.obj or {}
    sys.exit(open_app(model=options.get("model"), roi_model=options.get("roi_model"), bt_model=options.get("bt_model"),
                      open_bundle=bundle.resolve()))
