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
def rimea(model: str, tests: tuple[int, ...]) -> None:
    """Run RiMEA tests 1, 4, 5, 6, 7 and print the table; exit 1 when one fails."""
    from grove_tui.analysis.rimea import TESTS, run_rimea
    from grove_tui.errors import BadInputError

    unknown = [t for t in tests if t not in TESTS]
    if unknown:
        raise BadInputError(f"RiMEA test {unknown[0]} is not implemented",
                            hint=f"implemented: {', '.join(map(str, TESTS))}")
    results = run_rimea(model, tests or tuple(TESTS))
    click.echo(f"RiMEA tests, model {model}, dt 0.05 s")
    click.echo(f"{'test':<5} {'what':<38} {'measured':<36} {'criterion':<58} result")
    for r in results:
        click.echo(f"{r.test:<5} {r.name:<38} {r.measured:<36} {r.criterion:<58} {'pass' if r.passed else 'FAIL'}")
    if not all(r.passed for r in results):
        raise SystemExit(1)
