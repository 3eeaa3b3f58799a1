"""One way in (issue 36): bundle folders are written only by the services layer, through the one writer
it delegates to (scenario/bundle.py), and that writer keeps the write guards."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest
from helpers.paths import REPO

from grove_tui.bt.format.document import TreeDocument, node
from grove_tui.bt.format.xml import write_tree
from grove_tui.errors import GroveError
from grove_tui.scenario.bundle import derive_bundle, is_bundle, load_scenario

PACKAGE = REPO / "grove_tui"
WRITER = PACKAGE / "scenario" / "bundle.py"
SERVICES = PACKAGE / "services"
# What writes a bundle folder: the writer's functions, and the guarded swap with a bundle's ownership test.
BUNDLE_WRITERS = frozenset({"write_bundle", "write_bundle_files", "derive_bundle", "replace_run_outputs"})
FOLDER_WRITERS = frozenset({"atomic_directory", "write_files_atomic"})


def _name(node: ast.expr) -> str:
    return node.id if isinstance(node, ast.Name) else node.attr if isinstance(node, ast.Attribute) else ""


def bundle_writes(path: Path) -> list[str]:
    """Where a module writes a bundle folder: a use of the writer's functions (imported or by attribute),
    or an atomic folder swap guarded by `is_bundle` (the ownership test of bundles)."""
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            found += [f"line {node.lineno}: imports {a.name}" for a in node.names if a.name in BUNDLE_WRITERS]
        elif isinstance(node, ast.Attribute) and node.attr in BUNDLE_WRITERS:
            found.append(f"line {node.lineno}: uses .{node.attr}")
        elif isinstance(node, ast.Call) and _name(node.func) in FOLDER_WRITERS:
            owned = [k.value for k in node.keywords if k.arg == "owned"]
            if any(_name(value) == "is_bundle" for value in owned):
                found.append(f"line {node.lineno}: {_name(node.func)}(owned=is_bundle)")
    return found


def test_no_module_outside_services_writes_a_bundle_folder():
    offenders = []
    for path in sorted(PACKAGE.rglob("*.py")):
        if path == WRITER or SERVICES in path.parents:
            continue
        offenders += [f"{path.relative_to(REPO)} {where}" for where in bundle_writes(path)]
    assert not offenders, "bundle folders are written by the services layer only:\n" + "\n".join(offenders)


def test_the_writer_and_the_services_are_where_bundles_are_written():
    """The scan finds writes (it is not vacuous): the writer swaps folders guarded by is_bundle, and the
    services layer calls the writer."""
    assert any("atomic_directory(owned=is_bundle)" in where for where in bundle_writes(WRITER))
    assert any("imports write_bundle" in where for where in bundle_writes(SERVICES / "session.py"))


def test_a_module_that_swaps_a_bundle_folder_itself_is_found(tmp_path):
    rogue = tmp_path / "rogue.py"
    rogue.write_text("from grove_tui.files import atomic_directory\nfrom grove_tui.scenario import bundle\n"
                     "def save(out):\n    with atomic_directory(out, owned=bundle.is_bundle) as stage:\n"
                     "        bundle.write_bundle(None, stage)\n", encoding="utf-8")
    assert sorted(w.split(": ", 1)[1] for w in bundle_writes(rogue)) == [
        "atomic_directory(owned=is_bundle)", "uses .write_bundle"]


@pytest.fixture(scope="module")
def _built(tmp_path_factory):
    from helpers.handmade import build_hospital_bundle

    root = build_hospital_bundle(tmp_path_factory.mktemp("built") / "source")
    (root / "trajectories.csv").write_text("t,id\n", encoding="utf-8")
    return root


@pytest.fixture()
def source(_built, tmp_path_factory):
    import shutil

    return Path(shutil.copytree(_built, tmp_path_factory.mktemp("copy") / "source"))


def test_a_derived_bundle_never_writes_through_a_link_into_its_source(source, tmp_path):
    """The new tree is written over a kept file: a hard link to the source's would change the source too."""
    scenario = load_scenario(source)
    tree = scenario.agents[0].tree
    before = (source / tree).read_bytes()
    document = TreeDocument.single("Other", node("Wait", duration="1"))
    out = derive_bundle(source, tmp_path / "derived", scenario, keep=lambda rel: True,
                        trees={tree: document}, write=lambda stage: (stage / "events.jsonl").write_text(""))
    assert (out / tree).read_text(encoding="utf-8") == write_tree(document)
    assert (source / tree).read_bytes() == before
    assert not (out / "trajectories.csv").exists()  # a run belongs to the bundle it ran in
    assert (out / "events.jsonl").exists() and is_bundle(out)


def test_a_derived_bundle_keeps_the_writers_guards(source, tmp_path):
    """Atomic (a failing write leaves nothing), and never over a folder GROVE did not write."""
    scenario = load_scenario(source)
    foreign = tmp_path / "notes"
    foreign.mkdir()
    (foreign / "mine.txt").write_text("keep me", encoding="utf-8")
    with pytest.raises(GroveError):
        derive_bundle(source, foreign, scenario, keep=lambda rel: True)
    assert (foreign / "mine.txt").read_text(encoding="utf-8") == "keep me"

    def fail(stage: Path) -> None:
        raise RuntimeError("disk gone")

    with pytest.raises(RuntimeError):
        derive_bundle(source, tmp_path / "half", scenario, keep=lambda rel: True, write=fail)
    assert not (tmp_path / "half").exists()
    assert sorted(p.name for p in tmp_path.iterdir() if p.name.startswith(".")) == []


def test_a_derived_bundle_skips_links_in_its_source(source, tmp_path):
    (tmp_path / "secret.txt").write_text("not the bundle's", encoding="utf-8")
    (source / "trees" / "leak.xml").symlink_to(tmp_path / "secret.txt")
    out = derive_bundle(source, tmp_path / "derived", load_scenario(source), keep=lambda rel: True)
    assert not (out / "trees" / "leak.xml").exists()
