"""`grove eval SUITE --out DIR`: generate, simulate and score a suite against the baselines."""

from __future__ import annotations

import shlex
import sys
from pathlib import Path

import click
from rich.console import Console
from rich.table import Table


@click.command("eval")
@click.argument("suite", type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.option("--out", "out_dir", required=True, type=click.Path(file_okay=False, path_type=Path),
              help="Directory for bundles, results.csv and RESULTS.md.")
@click.option("--model", "model", type=click.Path(dir_okay=False), default=None,
              help="GGUF that writes the trees (default: the bt role's model, the embedded one unless configured).")
@click.option("--methods", default="grove,vanilla,no-planner,decoupled", show_default=True,
              help="Comma-separated methods to run.")
@click.option("--cases", "case_ids", default=None, help="Comma-separated case ids to run (default: all).")
@click.option("--seconds", type=click.FloatRange(min=1.0), default=30.0, show_default=True,
              help="Simulated seconds per scenario.")
def evaluate(suite: Path, out_dir: Path, model: str | None, methods: str, case_ids: str | None,
             seconds: float) -> None:
    """Prompt alignment, plausibility and cost of every case, for GROVE and the baselines."""
    from grove_tui.files import absolute_path
    from grove_tui.services.session import GroveSession

    err = Console(stderr=True, highlight=False)
    cases = GroveSession().load_eval_suite(suite)
    if case_ids:
        wanted = [c.strip() for c in case_ids.split(",") if c.strip()]
        unknown = sorted(set(wanted) - {c.id for c in cases})
        if unknown:
            raise click.BadParameter(f"unknown case id(s): {', '.join(unknown)}", param_hint="--cases")
        cases = [c for c in cases if c.id in wanted]

    def progress(index: int, total: int, result) -> None:
        status = f"[red]failed: {result.error}[/]" if result.error else "ok"
        err.print(f"[{index}/{total}] {result.case.id} {result.method}: {status}")

    args = sys.argv[sys.argv.index("eval") + 1:] if "eval" in sys.argv else [str(suite), "--out", str(out_dir)]
    command = "grove eval " + " ".join(shlex.quote(a) for a in args)
    with GroveSession(bt_model=model) as session:
        results = session.evaluate(cases, out_dir, methods=[m.strip() for m in methods.split(",") if m.strip()],
                                   sim_seconds=seconds, command=command, on_progress=progress)
        summary = session.evaluation_summary(results)
    table = Table(title="GROVE vs baselines (means per preset)")
    for col in ("preset", "method", "grounding", "plausibility", "wall pen.", "prompt tokens", "failed"):
        table.add_column(col)
    for line in summary:
        row = line.means
        table.add_row(line.preset, line.method, f"{line.grounding:.2f}", f"{line.plausibility:.2f}",
                      f"{row.get('wall_penetrations', float('nan')):.1f}", f"{row.get('prompt_tokens', 0):.0f}",
                      f"{row.get('failed', 0):.2f}")
    Console().print(table)
    for name in ("results.csv", "RESULTS.md"):  # what evaluate wrote
        click.echo(str(absolute_path(Path(out_dir) / name)))
