"""`grove import hunav` under hostile input (issue 35): every case is one `error:` line, exit 2, no bundle
written; and what it does write, `grove simulate` reads.

Each case was a traceback, a hang, or an exit 0 with a bundle `simulate` then refused.
"""

from __future__ import annotations

import os
import threading

import pytest
from click.testing import CliRunner
from helpers.hunav_files import BASE, document, params, write_scenario

from grove_tui.cli import main
from grove_tui.limits import MAX_GROUP_COUNT, MAX_SCENARIO_AGENTS

EXIT_BAD_INPUT = 2
ALIAS_BOMB = ("hunav_loader:\n  ros__parameters:\n    yaml_base_name: agents_lab\n    map: lab\n"
              "    a0: &a0 [agent1, agent1, agent1, agent1, agent1, agent1, agent1, agent1, agent1]\n"
              + "".join(f"    a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 9) + "]\n" for i in range(1, 9))
              + "    agents: *a8\n")


def refuse(path, out, contains: str) -> str:
    run = CliRunner().invoke(main, ["import", "hunav", str(path), "--out", str(out)], catch_exceptions=False)
    assert run.exit_code == EXIT_BAD_INPUT, run.output
    lines = run.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and len(lines[0]) < 600, run.stderr[:600]
    assert contains in lines[0], lines[0]
    assert not os.path.lexists(out) and not any(p.name.startswith(".") for p in out.parent.iterdir())
    return lines[0]


def with_agent(key, value, agent="agent1"):
    values = params()
    values[agent][key] = value
    return values


@pytest.mark.parametrize("values, contains", [
    (with_agent("init_pose", [0.5, 4.0]), "agent1.init_pose is [0.5, 4.0]; expected a mapping with x and y"),
    (with_agent("behavior", "Scared"), "agent1.behavior is 'Scared'; HuNavSim's loader reads a mapping"),
    (with_agent("init_pose", {"x": float("inf"), "y": 4.0}), "agent1.init_pose.x is inf"),
    (with_agent("init_pose", {"x": float("nan"), "y": 4.0}), "agent1.init_pose.x is nan"),
    (with_agent("max_vel", float("inf")), "agent1.max_vel is inf; it must be a finite number within 0..10"),
    (with_agent("max_vel", -3.0), "agent1.max_vel is -3.0"),
    (with_agent("radius", 9.0), "agent1.radius is 9.0"),
    (with_agent("behavior", {"type": "Berserk"}), "agent1.behavior.type is 'Berserk'; HuNavSim's behaviors are"),
    (with_agent("group_id", 10**30), "agent1.group_id is 1000000000000000000000000000000"),
    (with_agent("init_pose", {"x": 99_999.0, "y": 4.0}), "agent1.init_pose.x is 99999.0; it must be a finite number "
                                                          "within -10000..10000"),
], ids=["init_pose list", "behavior string", "inf pose", "nan pose", "max_vel inf", "max_vel -3", "radius 9",
        "Berserk", "group 1e30", "99 km pose"])
def test_values_simulate_would_refuse_are_refused_at_import(tmp_path, values, contains):
    refuse(write_scenario(tmp_path / "s", values), tmp_path / "out", contains)


@pytest.mark.parametrize("change, contains", [
    (lambda v: v.__setitem__("agents", ["agent1", {"N": 1}]), "`agents` lists {'N': 1}, which is not an agent's name"),
    (lambda v: v.__setitem__("agents", [-70157]), "`agents` lists -70157, which is not an agent's name"),
    (lambda v: v["agent1"].__setitem__("goals", 2.5), "agent1.goals is 2.5"),
], ids=["a mapping as a name", "a number as a name", "goals a number"])
def test_shapes_the_fuzzer_found_are_refused(tmp_path, change, contains):
    """bench/fuzz.py found these (TypeError in the loader check) after the hand-off's layouts were merged."""
    values = params()
    change(values)
    refuse(write_scenario(tmp_path / "s", values), tmp_path / "out", contains)


def test_non_finite_goals_are_refused(tmp_path):
    values = params()
    values["global_goals"][2] = {"x": float("nan"), "y": 1.5}
    refuse(write_scenario(tmp_path / "s", values), tmp_path / "out", "global_goals.2.x is nan")


@pytest.mark.parametrize("key", ["map", "yaml_base_name"])
def test_names_that_become_file_names_must_be_plain(tmp_path, key):
    for value in ("m" * 5000, "../../etc/x", ".hidden", ""):
        values = params()
        values[key] = value
        refuse(write_scenario(tmp_path / "s", values), tmp_path / "out", f"`{key}` is")


def test_a_group_larger_than_generation_allows_is_refused_before_any_tree_is_read(tmp_path):
    values = params()
    count = MAX_GROUP_COUNT + 1
    values["agents"] = [f"agent{i}" for i in range(1, count + 1)]
    for i in range(1, count + 1):
        values[f"agent{i}"] = dict(values["agent2"], id=i, group_id=7)
    # No tree files at all: the group is refused first.
    path = write_scenario(tmp_path / "s", values, tree_ids=[])
    refuse(path, tmp_path / "out", f"group_id 7 has {count} agents; a group holds at most {MAX_GROUP_COUNT}")


def test_more_agents_than_any_scenario_holds_is_one_short_line(tmp_path):
    # bench/hostile.py runs the 1,000,000 names; 20,000 exercise the same check in a fraction of the time.
    text = ("hunav_loader:\n  ros__parameters:\n    yaml_base_name: agents_lab\n    map: lab\n    agents: ["
            + ", ".join(["x"] * 20_000) + "]\n")
    line = refuse(write_scenario(tmp_path / "s", text=text), tmp_path / "out",
                  f"`agents` lists 20,000 agents; GROVE scenarios hold at most {MAX_SCENARIO_AGENTS:,}")
    assert len(line) < 300


def test_many_problems_are_counted_not_listed(tmp_path):
    values = params()
    values["agents"] = [f"ghost{i}" for i in range(5000)]
    line = refuse(write_scenario(tmp_path / "s", values), tmp_path / "out", "(and 4,997 more problems)")
    assert len(line) < 600


@pytest.mark.parametrize("text, contains", [
    ("hunav_loader: " + "[" * 20_000 + "]" * 20_000 + "\n", "nests more than"),
    (ALIAS_BOMB, "expands to more than"),
    (b"hunav_loader:\n  ros__parameters:\n    map: caf\xe9\n", "is not UTF-8 text"),
], ids=["20,000 brackets", "alias bomb in agents", "not UTF-8"])
@pytest.mark.slow
def test_hostile_yaml_is_refused_before_it_is_used(tmp_path, text, contains):
    refuse(write_scenario(tmp_path / "s", text=text), tmp_path / "out", contains)


def test_devices_and_pipes_are_refused_without_reading_them(tmp_path):
    folder = tmp_path / "s"
    write_scenario(folder)
    link = folder / "zero.yaml"
    link.symlink_to("/dev/zero")
    refuse(link, tmp_path / "out", "is a device, not a file")
    fifo = folder / "pipe.yaml"
    os.mkfifo(fifo)
    outcome: list[str] = []
    worker = threading.Thread(target=lambda: outcome.append(refuse(fifo, tmp_path / "out2", "is a pipe, not a file")))
    worker.start()
    worker.join(timeout=60)
    if worker.is_alive():  # unblock the reader so the suite does not hang, then fail
        with open(fifo, "w"):
            pass
        pytest.fail("import hunav blocked on a named pipe")
    assert outcome


def test_what_the_import_writes_simulates_from_any_folder(tmp_path, monkeypatch):
    from grove_tui.services.session import GroveSession

    bundle = tmp_path / "bundle"
    run = CliRunner().invoke(main, ["import", "hunav", str(write_scenario(tmp_path / "s")), "--out", str(bundle)])
    assert run.exit_code == 0, run.output
    monkeypatch.chdir(tmp_path / "s")  # a folder with a lab.yaml-less world/ would have been read before
    (tmp_path / "s" / "world").mkdir()
    (tmp_path / "s" / "world" / "lab.yaml").write_text("name: decoy\nzones: []\n")
    summary = GroveSession().simulate(bundle, 1.0)
    assert summary.sim_seconds == pytest.approx(1.0)


def test_the_valid_document_still_imports(tmp_path):
    assert "agents_lab" in document(params()) and BASE == "agents_lab"
    run = CliRunner().invoke(main, ["import", "hunav", str(write_scenario(tmp_path / "s")), "--out",
                                    str(tmp_path / "b")])
    assert run.exit_code == 0, run.output
