"""The tests' own layout: one definition per fixture name, test folders that mirror the packages, and test
files that docs and code name where they are."""

from __future__ import annotations

import ast
import re
from collections import defaultdict
from pathlib import Path

from helpers.paths import REPO

TESTS = REPO / "tests"
# Folders under tests/ that hold no tests of a package: shared helpers, input files, snapshot baselines.
NOT_PACKAGES = {"helpers", "data", "__snapshots__", "__pycache__"}


def _is_fixture(decorator: ast.expr) -> bool:
    target = decorator.func if isinstance(decorator, ast.Call) else decorator
    return (isinstance(target, ast.Attribute) and target.attr == "fixture") or (
        isinstance(target, ast.Name) and target.id == "fixture")


def _fixture_name(node: ast.FunctionDef | ast.AsyncFunctionDef) -> str:
    """The name tests ask for: the function's, or the decorator's `name=` when it gives one."""
    for decorator in node.decorator_list:
        if isinstance(decorator, ast.Call) and _is_fixture(decorator):
            for keyword in decorator.keywords:
                if keyword.arg == "name" and isinstance(keyword.value, ast.Constant):
                    return str(keyword.value.value)
    return node.name


def fixture_definitions(root: Path = TESTS) -> dict[str, list[str]]:
    """Every fixture defined under root (conftest files, test modules, helpers): name -> ["path:line", ...]."""
    found: dict[str, list[str]] = defaultdict(list)
    for path in sorted(root.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
        for node in ast.walk(tree):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and any(
                    _is_fixture(d) for d in node.decorator_list):
                where = path.relative_to(REPO if path.is_relative_to(REPO) else root)
                found[_fixture_name(node)].append(f"{where}:{node.lineno}")
    return dict(found)


def test_the_fixture_scan_finds_fixtures_and_their_duplicates(tmp_path):
    (tmp_path / "a").mkdir()
    (tmp_path / "conftest.py").write_text("import pytest\n\n@pytest.fixture(scope='module')\ndef world():\n    ...\n")
    (tmp_path / "a" / "test_a.py").write_text(
        "import pytest\nfrom pytest import fixture\n\n@fixture\ndef world():\n    ...\n\n"
        "@pytest.fixture(name='grid')\ndef _grid():\n    ...\n\ndef test_x(world, grid):\n    ...\n")
    found = fixture_definitions(tmp_path)
    assert set(found) == {"world", "grid"}
    assert len(found["world"]) == 2 and len(found["grid"]) == 1


def test_no_fixture_is_defined_twice():
    """A fixture used by several modules lives in the conftest.py of the level they share (tests/conftest.py,
    tests/<package>/conftest.py); two fixtures that do different things have different names."""
    twice = {name: where for name, where in fixture_definitions().items() if len(where) > 1}
    assert not twice, "defined more than once:\n" + "\n".join(
        f"  {name}: {', '.join(where)}" for name, where in sorted(twice.items()))


def test_test_folders_mirror_the_packages():
    """tests/<package>/[<subpackage>/] holds the tests of grove_tui/<package>/[<subpackage>/] (tests/bt/format
    for grove_tui/bt/format); tests of top-level modules sit in tests/."""
    packages = {path.parent.relative_to(REPO / "grove_tui").as_posix()
                for path in (REPO / "grove_tui").rglob("__init__.py") if path.parent != REPO / "grove_tui"}
    folders = {path.relative_to(TESTS).as_posix() for path in TESTS.rglob("*")
               if path.is_dir() and not NOT_PACKAGES.intersection(path.relative_to(TESTS).parts)}
    assert "bt/format" in packages and "bt" in folders  # the scan sees nested packages and folders
    assert folders <= packages, f"test folders with no package of that name: {sorted(folders - packages)}"


def test_every_test_file_named_in_docs_and_code_exists():
    """Docs and docstrings point readers at tests by path; after a move, the path must follow."""
    files = [*REPO.glob("grove_tui/**/*.py"), *REPO.glob("bench/**/*.py"), *REPO.glob("docs/*.md"),
             REPO / "README.md", *TESTS.rglob("*.py")]
    stale = set()
    for path in files:
        for match in re.finditer(r"\btests/[A-Za-z0-9_/]+\.py\b", path.read_text(encoding="utf-8")):
            if not (REPO / match.group(0)).exists():
                stale.add(f"{path.relative_to(REPO)}: {match.group(0)}")
    assert not stale, "\n".join(sorted(stale))
