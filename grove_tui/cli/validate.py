"""`grove validate rimea`: the RiMEA verification tests on GROVE's crowd, as a pass/fail table."""

from __future__ import annotations

import click

from grove_tui.crowd.sfm import SFM_MODELS


@click.group()
def validate() -> None:
    """Verify the simulation against published test sets."""


@validate.command("rimea")
@click.option("--model", type=click.Choice(SFM_MODELS), default="grove", show_default=True,
              help="Pedestrian model: GROVE's default or HuNavSim's lightsfm forces.")
@click.option("--test", "tests", type=int, multiple=True, help="Run only these RiMEA test numbers (repeatable).")
@click.option("--jupedsim/--no-jupedsim", default=True, show_default=True,
              help="Run the building tests (9-12) in JuPedSim too, beside GROVE, when JuPedSim is installed.")
def rimea(model: str, tests: tuple[int, ...], jupedsim: bool) -> None:
    """Run RiMEA tests 1, 4, 5, 6, 7, 9, 10, 11, 12 and print the table; exit 1 when one of GROVE's fails."""
    from grove_tui.analysis.rimea import TESTS, jupedsim_version, run_rimea
    from grove_tui.errors import BadInputError

    unknown = [t for t in tests if t not in TESTS]
    if unknown:
        raise BadInputError(f"RiMEA test {unknown[0]} is not implemented",
                            hint=f"implemented: {', '.join(map(str, TESTS))}")
    version = jupedsim_version() if jupedsim else None
    rows = run_rimea(model, tests or tuple(TESTS), jupedsim=version is not None)
    click.echo(f"RiMEA tests, model {model}, dt 0.05 s"
               + (f"; JuPedSim {version} SocialForceModel at dt 0.01 s beside the building tests" if version
                  else "; JuPedSim not installed (./install.sh bench adds it for a column beside GROVE)"))
    header = f"{'test':<5} {'what':<40} {'measured':<50} {'criterion':<58} result"
    if version:
        header += f"  {'JuPedSim':<50} result"
    click.echo(header)
    for r, peer in rows:
        line = f"{r.test:<5} {r.name:<40} {r.measured:<50} {r.criterion:<58} {'pass' if r.passed else 'FAIL'}"
        if version:
            line += (f"    {peer.measured:<50} {'pass' if peer.passed else 'FAIL'}" if peer is not None
                     else f"    {'-':<50} -")
        click.echo(line)
    if not all(r.passed for r, _ in rows):
        raise SystemExit(1)
