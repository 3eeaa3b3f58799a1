"""The `grove` command: with no subcommand it opens the TUI; subcommands run the headless core.

Subcommands live one per module in this package and are imported only when used, so
`grove --help` and the TUI start fast.
"""

from __future__ import annotations

import errno
import importlib
import os
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import click

# name -> ("module:attribute" of a click command or group, one-line help shown by `grove --help`)
SUBCOMMANDS: dict[str, tuple[str, str]] = {
    "worlds": ("grove_tui.cli.worlds:worlds", "List, draw and check semantic worlds."),
    "bt": ("grove_tui.cli.bt:bt", "Behavior trees: print the node manifest, validate XML files."),
    "rag": ("grove_tui.cli.rag:rag", "Node database: build the index, query it, measure recall."),
    "models": ("grove_tui.cli.models:models", "Local GGUF models: list what is found, pull Qwen3."),
    "generate": ("grove_tui.cli.generate:generate", "Generate a scenario bundle from a prompt (--no-ui)."),
    "refine": ("grove_tui.cli.refine:refine", "Edit a bundle by a follow-up sentence (--out NEW or --in-place)."),
    "batch": ("grove_tui.cli.generate:batch", "Generate many scenarios from a JSONL file, loading models once."),
    "dataset": ("grove_tui.cli.dataset:dataset", "Datasets written by `grove batch`: print an index's totals."),
    "simulate": ("grove_tui.cli.generate:simulate", "Simulate a bundle and write its trajectories."),
    "export": ("grove_tui.cli.export:export", "Export a bundle: HuNavSim agents.yaml + BT XML, PedPy trajectories."),
    "import": ("grove_tui.cli.importing:import_group", "Import a HuNavSim scenario (agents yaml + trees) as a bundle."),
    "metrics": ("grove_tui.cli.export:metrics", "Robot and crowd metrics of a simulated bundle."),
    "picture": ("grove_tui.cli.export:picture", "PNG/SVG picture of a scenario and its trajectories."),
    "eval": ("grove_tui.cli.evaluate:evaluate", "Run an evaluation suite against the baselines."),
    "understanding": ("grove_tui.cli.understanding:understanding",
                      "Score prompt understanding: each field of the reading, and scenarios for a sample."),
    "open": ("grove_tui.cli.open:open_command", "Open a saved scenario bundle in the app (inspect screen)."),
    "validate": ("grove_tui.cli.validate:validate", "Verify the simulation: RiMEA tests as a pass/fail table."),
}


# Writing failed for lack of room or a broken device: stdout on /dev/full, a full disk, a dead terminal.
_OUTPUT_ERRNOS = frozenset({errno.ENOSPC, errno.EDQUOT, errno.EIO})


class LazyGroup(click.Group):
    """The `grove` group: lazy subcommands, and one way every subcommand fails.

    A subcommand raises `GroveError` (or click rejects its arguments); `main` prints one line,
    `error: ...`, through `grove_tui.errors.print_error` and exits with the error's code (the
    README's exit-code table). No subcommand ends in a traceback on bad input.
    """

    def main(self, args: Sequence[str] | None = None, prog_name: str | None = None, complete_var: str | None = None,
             standalone_mode: bool = True,
             **extra: Any,  # Any: click.Command.main's own signature (make_context's keyword arguments)
             ) -> Any:  # Any: click.Command.main's own return type
        from grove_tui.errors import EXIT_BAD_INPUT, BadInputError, Cancelled, GroveError, RuntimeFailure, print_error

        try:
            result = super().main(args, prog_name, complete_var, standalone_mode=False, **extra)
        except GroveError as error:
            sys.exit(print_error(error))
        except click.exceptions.Abort:  # Ctrl+C at a click prompt or while a command runs
            sys.exit(print_error(Cancelled("cancelled")))
        except KeyboardInterrupt:
            sys.exit(print_error(Cancelled("cancelled")))
        except OSError as error:
            if error.errno not in _OUTPUT_ERRNOS:
                raise
            # stdout on /dev/full or a full disk: one line, then stdout goes to /dev/null so the
            # interpreter's final flush of the same unwritable stream prints no traceback after it.
            code = print_error(RuntimeFailure(f"cannot write the output: {error.strerror}",
                                              hint="free some space or write somewhere else"))
            try:
                os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
            except (OSError, ValueError):
                pass
            sys.exit(code)
        except click.ClickException as error:
            # Usage errors (missing option, bad value) are bad input: one line, like every other error.
            command = getattr(getattr(error, "ctx", None), "command_path", None) or "grove"
            print_error(BadInputError(error.format_message(), hint=f"see {command} --help"))
            sys.exit(EXIT_BAD_INPUT)
        # standalone_mode=False returns a command's exit code from ctx.exit() / sys.exit() as the result.
        sys.exit(result if isinstance(result, int) else 0)

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted(SUBCOMMANDS)

    def format_commands(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        # Listing must not import the subcommands: they pull in numba, torch and llama.cpp.
        rows = [(name, SUBCOMMANDS[name][1]) for name in self.list_commands(ctx)]
        with formatter.section("Commands"):
            formatter.write_dl(rows)

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        entry = SUBCOMMANDS.get(cmd_name)
        if entry is None:
            return None
        module_name, attribute = entry[0].split(":")
        module = importlib.import_module(module_name)
        return getattr(module, attribute)


@click.group(cls=LazyGroup, invoke_without_command=True, context_settings={"help_option_names": ["-h", "--help"]})
@click.option("--model", "model", type=click.Path(dir_okay=False), help="GGUF for both roles (roi and bt).")
@click.option("--roi-model", type=click.Path(dir_okay=False), help="GGUF for RoI selection.")
@click.option("--bt-model", type=click.Path(dir_okay=False), help="GGUF for behavior-tree synthesis.")
@click.option("--world", "world", default=None, help="World to open: a shipped name or a path to a world YAML.")
@click.option("--preset", "preset", default=None, help="Preset to select: emergency, queuing, normal, vanilla or a user preset.")
@click.version_option(package_name="grove-tui")
@click.pass_context
def main(ctx: click.Context, model: str | None, roi_model: str | None, bt_model: str | None,
         world: str | None, preset: str | None) -> None:
    """GROVE-TUI: type a sentence, get a runnable pedestrian scenario.

    With no subcommand, opens the terminal app.
    """
    ctx.ensure_object(dict)
    ctx.obj.update(model=model, roi_model=roi_model, bt_model=bt_model)
    if ctx.invoked_subcommand is None:
        sys.exit(open_app(model=model, roi_model=roi_model, bt_model=bt_model, world=world, preset=preset))


def open_app(*, model: str | None = None, roi_model: str | None = None, bt_model: str | None = None,
             world: str | None = None, preset: str | None = None, open_bundle: Path | None = None) -> int:
    """Run the terminal app (the one way from the command line into the TUI); returns its exit code."""
    from grove_tui.tui.app import run_app

    return run_app(model=model, roi_model=roi_model, bt_model=bt_model, world=world, preset=preset,
                   open_bundle=open_bundle)
