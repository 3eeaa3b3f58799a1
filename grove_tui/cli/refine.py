"""`grove refine`: edit a scenario bundle by a follow-up sentence.

    grove refine out/pharmacy --prompt "add a cleaner mopping the corridor" --out out/pharmacy-2
    grove refine out/pharmacy --prompt "make the queue twice as long" --in-place

The diff (groups added, changed, removed; the robot) is printed first, then applied: only the groups
the sentence adds or changes are generated, the others are kept byte for byte. A group name that
could mean several groups ("the nurse" with two nurse groups) exits 2 with the choices; `--group N`
picks one. Like every subcommand it builds nothing itself: `services.session.GroveSession.refine`
does the work.
"""

from __future__ import annotations

import json
from pathlib import Path

import click

from grove_tui.cli.generate import Progress, _err, _out, session_for, summary_lines


@click.command("refine")
@click.argument("bundle", type=click.Path(file_okay=False))
@click.option("--prompt", "followup", required=True,
              help='The follow-up: "add two guards at the entrance", "the visitors walk slowly", "no robot".')
@click.option("--out", "out_dir", type=click.Path(), default=None,
              help="Write the refined scenario here (a new bundle; an existing bundle there is replaced).")
@click.option("--in-place", is_flag=True, help="Replace BUNDLE itself, atomically.")
@click.option("--group", "groups", type=click.IntRange(1, None), multiple=True,
              help="Which group an ambiguous name means (its number in the choices); repeat for several.")
@click.option("--dry-run", is_flag=True, help="Print what the follow-up would change, and change nothing.")
@click.option("--overwrite", is_flag=True, help="Replace --out even when it is a folder that is not a bundle.")
@click.option("--roi-model", type=click.Path(dir_okay=False), default=None, help="GGUF for RoI selection.")
@click.option("--bt-model", type=click.Path(dir_okay=False), default=None, help="GGUF for behavior-tree synthesis.")
@click.option("--json", "as_json", is_flag=True, help="Print the diff and result as one JSON object on stdout.")
@click.pass_context
def refine(ctx: click.Context, bundle: str, followup: str, out_dir: str | None, in_place: bool,
           groups: tuple[int, ...], dry_run: bool, overwrite: bool, roi_model: str | None, bt_model: str | None,
           as_json: bool) -> None:
    """Edit BUNDLE by a follow-up sentence; groups it does not name stay byte-identical."""
    if not dry_run and (out_dir is None) == (not in_place):
        raise click.UsageError("say where the refined scenario goes: --out NEW or --in-place (one of them)")
    target = Path(bundle) if in_place else Path(out_dir) if out_dir is not None else None
    with session_for(ctx, roi_model, bt_model) as session:
        generated = session.open_bundle(bundle)
        refinement = session.read_refinement(generated, followup, choices=[g - 1 for g in groups])
        out = _out()
        if not as_json:
            out.print(f"follow-up {refinement.step}: {refinement.diff.sentence}", markup=False)
            for line in refinement.diff.lines():
                out.print(f"  {line}", markup=False)
        if dry_run or target is None:
            if as_json:
                click.echo(json.dumps({"diff": refinement.diff.to_dict(), "applied": False}))
            return
        progress = Progress(_err())
        try:
            refined = session.refine(generated, refinement, target, overwrite=overwrite or in_place,
                                     on_event=progress)
        except BaseException:
            progress.stop()  # the spinner must not overwrite the error line the grove group prints
            raise
    if as_json:
        report = refined.result.report
        click.echo(json.dumps({"diff": refinement.diff.to_dict(), "applied": True, "bundle": str(refined.bundle_dir),
                               "agents": len(refined.scenario.agents),
                               "report": {k: report[k] for k in ("stages", "total_seconds", "groups", "grounding",
                                                                 "history") if k in report}}))
        return
    for line in summary_lines(refined.result, refined.bundle_dir):
        out.print(line, markup=False)
