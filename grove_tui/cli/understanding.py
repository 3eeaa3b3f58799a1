"""`grove understanding CASES --out DIR`: score the reading of every prompt of the understanding suite
and, with --scenarios N, the scenarios the local model builds for N of them."""

from __future__ import annotations

import shlex
import sys
from pathlib import Path

import click
from rich.console import Console
from rich.table import Table


@click.command("understanding")
@click.argument("cases_file", type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.option("--out", "out_dir", required=True, type=click.Path(file_okay=False, path_type=Path),
              help="Directory for results.csv, RESULTS.md, summary.json and the sample's bundles.")
@click.option("--scenarios", type=click.IntRange(min=0), default=0, show_default=True,
              help="Also generate and score this many cases (spread over the suite) with the local model.")
@click.option("--model", "model", type=click.Path(dir_okay=False), default=None,
              help="GGUF that writes the trees for --scenarios (default: the bt role's model).")
@click.option("--world", "worlds", multiple=True, help="Only cases in this world (repeatable).")
def understanding(cases_file: Path, out_dir: Path, scenarios: int, model: str | None, worlds: tuple[str, ...]) -> None:
    """How well prompts are understood: each field of the reading, and the final scenario for a sample."""
    from grove_tui.services.session import GroveSession

    err = Console(stderr=True, highlight=False)
    # GroveErrors propagate to the `grove` group's printer (title, message, hint, exit code).
    reader = GroveSession()
    cases = reader.load_understanding_cases(cases_file)
    if worlds:
        cases = [c for c in cases if c.world in worlds]
        if not cases:
            raise click.BadParameter(f"no case in world(s) {', '.join(worlds)}", param_hint="--world")
    err.print(f"reading {len(cases)} prompts")
    reading = reader.read_cases(cases)
    scenario_scores = []
    if scenarios:
        sample = reader.understanding_sample(cases, scenarios)

        def progress(index: int, total: int, score) -> None:
            status = f"[red]failed: {score.error}[/]" if score.error else (
                "ok" if not score.misses else "; ".join(score.misses))
            err.print(f"[{index}/{total}] {score.case.id} ({score.seconds:.0f} s): {status}")

        with GroveSession(bt_model=model) as session:
            scenario_scores = session.understand(sample, out_dir, on_progress=progress)
    args = sys.argv[sys.argv.index("understanding") + 1:] if "understanding" in sys.argv else [
        str(cases_file), "--out", str(out_dir)]
    command = "grove understanding " + " ".join(shlex.quote(a) for a in args)
    report = reader.understanding_report(reading, scenario_scores, out_dir, command=command)
    table = Table(title=f"Reading of {len(cases)} prompts")
    for col in ("field", "passed", "scored", "share"):
        table.add_column(col)
    for name, (passed, total) in report.reading.items():
        table.add_row(name, str(passed), str(total), f"{100 * passed / total:.1f} %" if total else "n/a")
    Console().print(table)
    if scenario_scores:
        table = Table(title=f"Scenarios of {len(scenario_scores)} cases")
        for col in ("check", "passed", "scored"):
            table.add_column(col)
        for name, (passed, total) in report.scenarios.items():
            table.add_row(name, str(passed), str(total))
        Console().print(table)
    for line in report.below_the_bar:
        err.print(f"[yellow]below the bar:[/] {line}")
    for path in report.paths:
        click.echo(str(path))
