"""`grove open BUNDLE`: the app, opened on a saved bundle's inspect screen."""

from __future__ import annotations

import sys
from pathlib import Path

import click


@click.command("open")
@click.argument("bundle", type=click.Path(path_type=Path))
@click.pass_context
def open_command(ctx: click.Context, bundle: Path) -> None:
    """Open a saved scenario bundle (e.g. one under the runs folder) in the app's inspect screen."""
    from grove_tui.services.session import GroveSession

    # Check the bundle (and its world) before the app takes the terminal: a wrong path is the usual
    # one-line error (BundleError, exit 2, printed by the `grove` group), not a failure inside the app.
    GroveSession().open_bundle(bundle)
    from grove_tui.cli import open_app

    options = ctx.obj or {}
    sys.exit(open_app(model=options.get("model"), roi_model=options.get("roi_model"), bt_model=options.get("bt_model"),
                      open_bundle=bundle.resolve()))
