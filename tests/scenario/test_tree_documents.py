"""Trees flow between stages as TreeDocuments: XML text is written only where a file is, and read only where
one is read (the bundle reader, imports, `grove bt validate`), never re-parsed from text the codec already had."""

from __future__ import annotations

import ast
from pathlib import Path

from helpers.clinic import QUEUE, make_result
from helpers.paths import REPO

from grove_tui.bt.format.document import TreeDocument
from grove_tui.bt.format.xml import write_tree
from grove_tui.generation.draft import DraftGroup
from grove_tui.scenario.bundle import load_bundle, write_bundle

# The codec's entry points that turn BT XML text (or a file of it) into a document, or check such text.
TEXT_READERS = frozenset({"read_tree", "read_tree_file", "parse_tree_text", "check_tree_text", "check_tree_bytes",
                          "check_tree_file", "load_tree_file", "fromstring"})
# Where bytes are read, and so where they may be parsed, each for its reason.
READS_BYTES = {
    "grove_tui/scenario/bundle.py": "the bundle reader (load_trees)",
    "grove_tui/simulation/simulation.py": "Simulation.from_scenario reads a bundle's tree files to run them",
    "grove_tui/exports/hunav.py": "the HuNavSim export reads the bundle's tree files (and digests their bytes)",
    "grove_tui/exports/hunav_import.py": "the HuNavSim import reads HuNavSim's tree files",
    "grove_tui/services/session.py": "`grove bt validate FILE` checks a file the user names",
    "grove_tui/cli/bt.py": "`grove bt validate FILE` (through the session)",
    "grove_tui/bt/runtime/factory.py": "the runtime's factory builds a tree from text a caller hands it",
    "grove_tui/analysis/refine_chains.py": "the follow-up chain bench reads finished bundles' tree files",
}


def test_the_pipeline_hands_on_documents_and_the_bundle_writes_their_bytes(clinic, tmp_path):
    result = make_result(clinic, "queuing", "Six patients in the lobby queue at the pharmacy counter",
                         [DraftGroup("patients", 6, "lobby", QUEUE)])
    assert result.trees and all(isinstance(document, TreeDocument) for document in result.trees.values())
    out = write_bundle(result, tmp_path / "a")
    for rel, document in result.trees.items():
        assert (out / rel).read_bytes() == write_tree(document).encode("utf-8")
    # read back (parsed once, by the bundle reader) and written again: the same bytes, file for file
    scenario, trees, fields, grid = load_bundle(out)
    assert trees == result.trees
    again = write_bundle(type(result)(scenario, trees, fields, grid, dict(result.report)), tmp_path / "b")
    for rel in ["scenario.yaml", *result.trees]:
        assert (again / rel).read_bytes() == (out / rel).read_bytes(), rel


def _text_reader_calls(path: Path) -> list[str]:
    text = path.read_text(encoding="utf-8")
    if not any(name in text for name in TEXT_READERS):  # most modules: no need to parse them
        return []
    calls = []
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, ast.Call):
            func = node.func
            name = func.id if isinstance(func, ast.Name) else func.attr if isinstance(func, ast.Attribute) else ""
            if name in TEXT_READERS:
                calls.append(f"{name}() line {node.lineno}")
    return calls


def test_no_stage_re_reads_tree_text_the_codec_already_had():
    package = REPO / "grove_tui"
    found = {}
    for path in sorted(package.rglob("*.py")):
        rel = path.relative_to(REPO).as_posix()
        if rel.startswith("grove_tui/bt/format/") or rel in READS_BYTES:
            continue
        calls = _text_reader_calls(path)
        if calls:
            found[rel] = calls
    assert not found, f"these modules parse BT XML text; take the TreeDocument the stage before had: {found}"
    for rel in READS_BYTES:  # the allowance stays true: each still reads tree bytes
        assert _text_reader_calls(REPO / rel), f"{rel} no longer reads tree text; drop it from READS_BYTES"
