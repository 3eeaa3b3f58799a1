"""`grove validate rimea` (the RiMEA verification tests) and `grove validate empirical` (measured crowds),
on GROVE's crowd, as pass/fail tables."""

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
                  else "; no JuPedSim column (--no-jupedsim)" if not jupedsim
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


@validate.command("empirical")
@click.option("--model", "models", type=click.Choice(SFM_MODELS), multiple=True,
              help="Pedestrian model(s) to check (repeatable); default: every model, the default one first.")
@click.option("--check", "checks", type=click.Choice(("fd", "bottleneck", "lanes")), multiple=True,
              help="Run only these checks (repeatable): fd (speed-density), bottleneck (flow vs width), lanes.")
def empirical(models: tuple[str, ...], checks: tuple[str, ...]) -> None:
    """Compare the crowd with measured crowds (Weidmann 1993; Seyfried 2009, Kretz 2006; Zhang 2012).

    Every model reports; the command exits 1 only when the default model ("grove") fails a check.
    The published values and their sources: grove_tui/analysis/data/empirical.yaml.
    """
    from grove_tui.analysis.empirical import CHECKS, run_empirical

    chosen = models or SFM_MODELS
    names = checks or tuple(CHECKS)
    failed_default = False
    for model in chosen:
        required = model == SFM_MODELS[0]
        click.echo(f"Empirical checks, model {model}, dt 0.05 s"
                   + (" (the default model: it must pass)" if required else " (reported, not required)"))
        click.echo(f"{'check':<11} {'what':<38} {'result':<6} measured   [criterion]")
        for r in run_empirical(model, names):
            click.echo(f"{r.check:<11} {r.name:<38} {'pass' if r.passed else 'FAIL':<6} {r.measured}   [{r.criterion}]")
            failed_default |= required and not r.passed
        click.echo("")
    if failed_default:
        raise SystemExit(1)
