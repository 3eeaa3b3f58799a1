"""`grove dataset summary DIR`: the totals of a batch's dataset index (services.dataset)."""

from __future__ import annotations

import sys

import click
from rich.console import Console


@click.group("dataset")
def dataset() -> None:
    """Datasets written by `grove batch`: one row per scenario in DIR/dataset.sqlite."""


@dataset.command("summary")
@click.argument("directory", type=click.Path(file_okay=False))
def summary(directory: str) -> None:
    """Print the totals of DIR/dataset.sqlite: scenarios, failures, agents, grounding, worlds, presets."""
    from grove_tui.services.dataset import summarize

    totals = summarize(directory)
    out = Console(file=sys.stdout, highlight=False, soft_wrap=True)
    lines = [
        f"scenarios: {totals.scenarios} (ok {totals.ok}, failed {totals.failed}, pending {totals.pending})",
        f"prompts: {totals.prompts}",
        f"agents: {totals.agents}",
        f"grounded as asked (checked on their run): {totals.grounded}/{totals.ok}",
        f"simulated: {totals.simulated}/{totals.ok}",
        f"generation seconds: {totals.generation_seconds:.2f}",
        "worlds: " + ", ".join(f"{name} {count}" for name, count in totals.worlds.items()),
        "presets: " + ", ".join(f"{name} {count}" for name, count in totals.presets.items()),
    ]
    lines += [f"failed {name} (exit {code}): {message}" for name, code, message in totals.failures]
    for line in lines:
        out.print(line, markup=False)
