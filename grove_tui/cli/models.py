"""`grove models list|pull`: which GGUF models are found, which role uses each, and fetching Qwen3."""

from __future__ import annotations

import sys

import click
from rich.console import Console
from rich.table import Table


def _console() -> Console:
    # click.testing.CliRunner swaps sys.stdout; bind to the current one each call.
    return Console(file=sys.stdout, width=160)


def _size(num_bytes: int) -> str:
    return f"{num_bytes / 2**20:.0f} MB" if num_bytes < 2**30 else f"{num_bytes / 2**30:.2f} GB"


@click.group()
def models() -> None:
    """Local GGUF models: list what is found, pull an official Qwen3 file."""


@models.command("list")
@click.pass_context
def list_command(ctx: click.Context) -> None:
    """Show every model found (models dir, embedded, chosen paths) and the role using it."""
    from grove_tui.services.session import GroveSession
    from grove_tui.settings import models_dir

    options = (ctx.find_root().obj or {}) if ctx.find_root().obj is not None else {}
    session = GroveSession(model=options.get("model"), roi_model=options.get("roi_model"),
                           bt_model=options.get("bt_model"))
    found, choices = session.list_models()
    table = Table(title=f"GGUF models (models dir: {models_dir()})")
    for column in ("roles", "file", "architecture", "quantization", "size", "context", "found via"):
        table.add_column(column)
    for model in found:
        info = model.info
        table.add_row(
            ", ".join(model.roles) or "-", str(model.path),
            info.architecture if info else "?", info.quantization if info else "?",
            _size(info.size_bytes) if info else "?",
            str(info.context_length) if info and info.context_length else "?",
            model.origin + (f" [red]({model.problem})[/red]" if model.problem else ""))
    console = _console()
    console.print(table)
    if isinstance(choices, str):
        console.print(f"[red]role resolution failed:[/red] {choices}")
        raise SystemExit(1)
    for role, choice in choices.items():
        console.print(f"{role}: {choice.path} [dim](from {choice.source})[/dim]")


@models.command("pull")
@click.argument("name")
@click.option("--endpoint", default=None, help="Hub endpoint or mirror (default: HF_ENDPOINT or https://huggingface.co).")
@click.option("--force", is_flag=True, help="Download again even if the file is already there.")
def pull_command(name: str, endpoint: str | None, force: bool) -> None:
    """Download an official Qwen3 GGUF (qwen3-0.6b, qwen3-1.7b, qwen3-4b) into the models directory."""
    from grove_tui.services.session import GroveSession

    console = _console()
    last_shown = [-1]

    def start(url: str, size: int) -> None:
        console.print(f"downloading {url} ({_size(size)}) ...")

    def progress(received: int, total: int) -> None:
        percent = received * 100 // max(total, 1)
        if percent >= last_shown[0] + 10:
            last_shown[0] = percent
            console.print(f"  {percent}%")

    path = GroveSession().pull_model(name, endpoint=endpoint, force=force, on_start=start, on_progress=progress)
    console.print(f"verified (size, sha256, GGUF header) and saved: {path}")
