"""`grove rag ...`: the node database and its retrieval index."""

from __future__ import annotations

import sys
from pathlib import Path

import click

_INDEX_OPTION = click.option("--index-dir", type=click.Path(file_okay=False, path_type=Path), default=None,
                             help="Chroma index directory (default: <cache>/chroma).")
_NODE_DB_OPTION = click.option("--node-db", type=click.Path(file_okay=False, path_type=Path), default=None,
                               help="Node database directory (default: the shipped node_db/).")


@click.group()
def rag() -> None:
    """Node database and retrieval: sync documents, build the index, query, evaluate."""


@rag.command()
@_NODE_DB_OPTION
@click.option("--check", is_flag=True, help="Only report documents that are missing or stale; exit 1 if any.")
def sync(node_db: Path | None, check: bool) -> None:
    """Generate node_db/nodes/<Name>.md from the node manifest (and node_db/notes.yaml)."""
    from grove_tui.services.session import GroveSession

    written, removed, problems = GroveSession().sync_node_documents(node_db, check_only=check)
    if check:
        for problem in problems:
            click.echo(problem)
        click.echo(f"{len(problems)} problem(s)" if problems else "node database matches the manifest")
        sys.exit(1 if problems else 0)
    click.echo(f"wrote {len(written)} document(s){': ' + ', '.join(written) if written else ''}")
    if removed:
        click.echo(f"removed {len(removed)} document(s) of nodes no longer in the manifest: {', '.join(removed)}")
    for problem in problems:
        click.echo(problem, err=True)
    sys.exit(1 if problems else 0)


@rag.command()
@_NODE_DB_OPTION
@_INDEX_OPTION
@click.option("--force", is_flag=True, help="Rebuild even when the index is up to date.")
def build(node_db: Path | None, index_dir: Path | None, force: bool) -> None:
    """Build (or confirm) the retrieval index."""
    from grove_tui.services.session import GroveSession

    retriever = GroveSession().node_retriever(node_db, index_dir)
    state = retriever.ensure_index(force=force)
    verb = "built" if state.built else "up to date"
    click.echo(f"{verb}: {retriever.index_dir} ({state.documents} documents, {state.vectors} vectors, "
               f"{state.seconds:.2f} s, node_db {state.content_hash[:12]})")


@rag.command()
@click.argument("prompt")
@click.option("--preset", "-p", default=None, help="emergency, queuing, normal or vanilla (default: no filter).")
@click.option("-k", "k", default=8, show_default=True, type=click.IntRange(1, 100))
@click.option("--show", is_flag=True, help="Print each document as the model would read it.")
@_NODE_DB_OPTION
@_INDEX_OPTION
def query(prompt: str, preset: str | None, k: int, show: bool, node_db: Path | None, index_dir: Path | None) -> None:
    """Show the documents retrieved for PROMPT."""
    from grove_tui.services.session import GroveSession

    retriever = GroveSession().node_retriever(node_db, index_dir)
    results = retriever.retrieve(prompt, preset, k)
    for rank, item in enumerate(results, 1):
        uses = f"  uses {', '.join(item.nodes)}" if item.kind == "template" else ""
        click.echo(f"{rank:2d}. {item.score:6.3f}  {item.kind:8s} {item.name}{uses}")
        if show:
            click.echo("\n".join("      " + line for line in item.document.splitlines()))


@rag.command(name="eval")
@click.option("-k", "k", default=8, show_default=True, type=click.IntRange(1, 100))
@click.option("--cases", type=click.Path(dir_okay=False, path_type=Path), default=None,
              help="Labelled set (default: node_db/eval.yaml).")
@click.option("--verbose", "-v", is_flag=True, help="List every prompt with a missed node.")
@_NODE_DB_OPTION
@_INDEX_OPTION
def evaluate_command(k: int, cases: Path | None, verbose: bool, node_db: Path | None, index_dir: Path | None) -> None:
    """Recall@k of retrieval on the labelled set, per preset and overall."""
    from grove_tui.services.session import GroveSession

    session = GroveSession()
    result = session.evaluate_retrieval(session.node_retriever(node_db, index_dir), k, cases)
    for preset in result.presets():
        count = sum(1 for case, _, _ in result.per_case if case.preset == preset)
        click.echo(f"{preset:10s} recall@{k} = {result.recall(preset):.3f}  ({count} prompts)")
    click.echo(f"{'overall':10s} recall@{k} = {result.recall():.3f}  ({len(result.per_case)} prompts)")
    for case, recall, missing in result.per_case:
        if missing and verbose:
            click.echo(f"  {case.preset}: {case.prompt!r} misses {', '.join(missing)} (recall {recall:.2f})")
