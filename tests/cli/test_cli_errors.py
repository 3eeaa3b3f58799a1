"""Every subcommand, given a missing or a broken input, prints one line `error: ...` and exits with the
code the README's table documents; never a traceback."""

from __future__ import annotations

import pytest
from click.testing import CliRunner

from grove_tui.cli import SUBCOMMANDS, main
from grove_tui.errors import EXIT_BAD_INPUT

BROKEN_YAML = "zones: [ {name: lobby\n"


@pytest.fixture()
def inputs(tmp_path, monkeypatch):
    """Missing and broken inputs of every kind a subcommand reads."""
    monkeypatch.delenv("GROVE_CONFIG_FILE", raising=False)
    broken_bundle = tmp_path / "broken_bundle"
    broken_bundle.mkdir()
    (broken_bundle / "scenario.yaml").write_text(BROKEN_YAML, encoding="utf-8")
    no_scenario = tmp_path / "no_scenario"
    no_scenario.mkdir()
    (no_scenario / "trajectories.csv").write_text("frame,t,id,x,y,vx,vy,yaw,group\n", encoding="utf-8")
    broken_world = tmp_path / "broken_world.yaml"
    broken_world.write_text(BROKEN_YAML, encoding="utf-8")
    broken_jobs = tmp_path / "jobs.jsonl"
    broken_jobs.write_bytes(b'{"world": "hospital", "preset": "normal", "prompt": "caf\xe9"}\n')
    broken_suite = tmp_path / "suite.yaml"
    broken_suite.write_text("cases:\n  - id: one\n    world: hospital\n", encoding="utf-8")
    broken_config = tmp_path / "config.yaml"
    broken_config.write_text("ui: !!python/object/apply:os.system ['true']\n", encoding="utf-8")
    broken_cases = tmp_path / "cases.yaml"
    broken_cases.write_text(BROKEN_YAML, encoding="utf-8")
    return {"MISSING": str(tmp_path / "missing"), "BUNDLE": str(broken_bundle), "NOSCENARIO": str(no_scenario),
            "WORLD": str(broken_world), "JOBS": str(broken_jobs), "SUITE": str(broken_suite),
            "CONFIG": str(broken_config), "CASES": str(broken_cases), "OUT": str(tmp_path / "out"),
            "MISSINGFILE": str(tmp_path / "missing.xml")}


GENERATE = ["generate", "--no-ui", "--preset", "normal", "--prompt", "two people walk", "--out", "OUT", "--world"]

# (subcommand, arguments, exit code); every subcommand has a missing and a broken case.
CASES = [
    ("worlds", ["worlds", "show", "MISSING"], 2),
    ("worlds", ["worlds", "show", "WORLD"], 2),
    ("worlds", ["worlds", "check", "MISSING"], 2),
    ("bt", ["bt", "validate", "MISSINGFILE"], 2),
    ("bt", ["bt", "validate", "BUNDLE"], 2),  # a folder, not a tree file
    ("rag", ["rag", "eval", "--cases", "MISSING"], 2),
    ("rag", ["rag", "eval", "--cases", "CASES"], 2),
    ("models", ["models", "pull", "no-such-model"], 2),
    ("models", ["models", "list"], 2),  # with the broken config file (see below)
    ("generate", GENERATE + ["MISSING"], 2),
    ("generate", GENERATE + ["WORLD"], 2),
    ("batch", ["batch", "MISSING", "--out", "OUT"], 2),
    ("batch", ["batch", "JOBS", "--out", "OUT"], 2),
    ("simulate", ["simulate", "MISSING"], 2),
    ("simulate", ["simulate", "BUNDLE"], 2),
    ("export", ["export", "hunav", "MISSING", "--out", "OUT"], 2),
    ("export", ["export", "hunav", "BUNDLE", "--out", "OUT"], 2),
    ("export", ["export", "trajectories", "NOSCENARIO", "--out", "OUT"], 2),
    ("export", ["export", "rosbag", "BUNDLE", "--out", "OUT"], 2),
    ("export", ["export", "foxglove", "NOSCENARIO", "--out", "OUT"], 2),
    ("metrics", ["metrics", "MISSING"], 2),
    ("metrics", ["metrics", "NOSCENARIO"], 2),
    ("picture", ["picture", "MISSING"], 2),
    ("picture", ["picture", "BUNDLE"], 2),
    ("eval", ["eval", "MISSING", "--out", "OUT"], 2),
    ("eval", ["eval", "SUITE", "--out", "OUT"], 2),
    ("open", ["open", "MISSING"], 2),
    ("open", ["open", "BUNDLE"], 2),
    ("refine", ["refine", "MISSING", "--prompt", "add a cleaner", "--out", "OUT"], 2),
    ("refine", ["refine", "BUNDLE", "--prompt", "add a cleaner", "--out", "OUT"], 2),
    ("understanding", ["understanding", "MISSING", "--out", "OUT"], 2),
    ("understanding", ["understanding", "CASES", "--out", "OUT"], 2),
    ("import", ["import", "hunav", "MISSING", "--out", "OUT"], 2),
    ("import", ["import", "hunav", "CASES", "--out", "OUT"], 2),
    ("dataset", ["dataset", "summary", "MISSING"], 2),
    ("dataset", ["dataset", "summary", "BUNDLE"], 2),  # a folder that is no batch output
    ("validate", ["validate", "no-such-test-set"], 2),  # reads no file: a missing and a bad choice
    ("validate", ["validate", "rimea", "--model", "no-such-model"], 2),
]


def test_every_subcommand_is_covered():
    assert {name for name, _, _ in CASES} == set(SUBCOMMANDS)


@pytest.mark.parametrize(("name", "args", "code"), CASES, ids=[" ".join(args[:3]) for _, args, _ in CASES])
def test_a_missing_or_broken_input_is_one_error_line_and_its_exit_code(inputs, monkeypatch, name, args, code):
    if args == ["models", "list"]:
        monkeypatch.setenv("GROVE_CONFIG_FILE", inputs["CONFIG"])
    result = CliRunner().invoke(main, [inputs.get(arg, arg) for arg in args])
    assert result.exception is None or isinstance(result.exception, SystemExit), result.exc_info
    assert result.exit_code == code, (result.stdout, result.stderr)
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), result.stderr
    assert "Traceback" not in result.stderr + result.stdout


def test_a_usage_error_is_one_line_too():
    result = CliRunner().invoke(main, ["generate", "--no-ui"])
    assert result.exit_code == EXIT_BAD_INPUT
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: Missing option") and "generate --help" in lines[0]


def test_a_checker_lists_the_problems_of_a_broken_file_and_exits_1(inputs, tmp_path):
    # `worlds check` and `bt validate` exist to list problems: that is their output, not an error.
    broken_tree = tmp_path / "tree.xml"
    broken_tree.write_text("<root BTCPP_format='4'><BehaviorTree ID='x'><NoSuchNode/></BehaviorTree></root>")
    for args in (["worlds", "check", inputs["WORLD"]], ["bt", "validate", str(broken_tree)]):
        result = CliRunner().invoke(main, args)
        assert result.exit_code == 1, (args, result.output)
        assert result.exception is None or isinstance(result.exception, SystemExit)
