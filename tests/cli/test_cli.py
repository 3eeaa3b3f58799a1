"""The `grove` entry point: help lists every subcommand without importing heavy modules."""

from __future__ import annotations

import subprocess
import sys

from click.testing import CliRunner

from grove_tui.cli import SUBCOMMANDS, main


def test_help_lists_every_subcommand():
    result = CliRunner().invoke(main, ["--help"])
    assert result.exit_code == 0, result.output
    for name in SUBCOMMANDS:
        assert name in result.output


def test_every_subcommand_resolves_to_a_click_command():
    import click

    for name in SUBCOMMANDS:
        command = main.get_command(None, name)  # type: ignore[arg-type]
        assert isinstance(command, click.Command), name


def test_help_does_not_import_the_heavy_stack():
    code = (
        "import sys\n"
        "from click.testing import CliRunner\n"
        "from grove_tui.cli import main\n"
        "CliRunner().invoke(main, ['--help'])\n"
        "heavy = [m for m in ('numba', 'torch', 'llama_cpp', 'chromadb', 'textual') if m in sys.modules]\n"
        "print(','.join(heavy))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == ""
