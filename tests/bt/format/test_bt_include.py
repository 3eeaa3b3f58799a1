"""Reading trees written the way HuNavSim writes them: <include> (relative to the including file, depth
limited, never outside the allowed folders), SubTree with a remapped blackboard, HuNavSim's unbounded
ports, and an unset blackboard entry that stops one agent, not the run.

The trees here are written for these tests in HuNavSim's style (HuNavSim's own files are not copied
into this repository); `GROVE_HUNAV_TREES=DIR` additionally validates every .xml under DIR."""

from __future__ import annotations

import math
import os
from pathlib import Path

import pytest

from grove_tui.bt.format.include import MAX_INCLUDE_DEPTH, resolve_includes
from grove_tui.errors import BTError
from grove_tui.bt.format.xml import check_tree_file, load_tree_file
from helpers.hall import agent, simulate

REGULAR = '''<?xml version='1.0' encoding='UTF-8'?>
<root main_tree_to_execute="RegularNavTree" BTCPP_format="4">
  <TreeNodesModel><Action ID="RegularNav"/></TreeNodesModel>
  <BehaviorTree ID="RegularNavTree">
    <Fallback>
      <Sequence><Inverter><IsGoalReached agent_id="{id}"/></Inverter><RegularNav agent_id="{id}" time_step="{dt}"/></Sequence>
      <UpdateGoal agent_id="{id}"/>
    </Fallback>
  </BehaviorTree>
</root>
'''

THREATENING = '''<root main_tree_to_execute="ThreatTree" BTCPP_format="4">
  <include path="{path}"/>
  <BehaviorTree ID="ThreatTree">
    <Fallback>
      <Sequence>
        <IsRobotVisible agent_id="{{id}}" distance="4.0"/>
        <ThreateningNav agent_id="{{id}}" time_step="{{dt}}" goal_dist="20" beh_duration="40" only_once="True"/>
      </Sequence>
      <Sequence>
        <SetBlackboard output_key="agentid" value="{{id}}"/>
        <SetBlackboard output_key="timestep" value="{{dt}}"/>
        <SubTree ID="RegularNavTree" id="{{agentid}}" dt="{{timestep}}"/>
      </Sequence>
    </Fallback>
  </BehaviorTree>
</root>
'''


def _write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def test_include_resolves_relative_to_the_including_file(tmp_path):
    _write(tmp_path / "lib", "BTRegularNav.xml", REGULAR)
    main = _write(tmp_path, "agent.xml", THREATENING.format(path="lib/BTRegularNav.xml"))
    assert check_tree_file(main) == []  # goal_dist 20: HuNavSim has no maximum, neither do we
    document = load_tree_file(main)
    assert set(document.trees) == {"ThreatTree", "RegularNavTree"}


def test_nested_include_is_relative_to_each_file_and_shared_files_load_once(tmp_path):
    _write(tmp_path / "lib", "BTRegularNav.xml", REGULAR)
    _write(tmp_path / "lib", "middle.xml", '<root BTCPP_format="4"><include path="BTRegularNav.xml"/></root>')
    main = _write(tmp_path, "agent.xml", THREATENING.format(path="lib/middle.xml").replace(
        '<include path="lib/middle.xml"/>', '<include path="lib/middle.xml"/><include path="lib/BTRegularNav.xml"/>'))
    assert check_tree_file(main) == []


@pytest.mark.parametrize("target, message", [
    ("../outside/BTRegularNav.xml", "leaves the allowed folders"),
    ("/etc/passwd", "leaves the allowed folders"),
    ("missing.xml", "no such behavior-tree file"),
])
def test_include_outside_or_missing_is_refused(tmp_path, target, message):
    _write(tmp_path / "outside", "BTRegularNav.xml", REGULAR)
    main = _write(tmp_path / "trees", "agent.xml", THREATENING.format(path=target))
    problems = check_tree_file(main)
    assert len(problems) == 1 and message in problems[0].message


def test_symlink_out_of_the_folder_is_refused(tmp_path):
    _write(tmp_path / "outside", "BTRegularNav.xml", REGULAR)
    (tmp_path / "trees").mkdir()
    (tmp_path / "trees" / "link.xml").symlink_to(tmp_path / "outside" / "BTRegularNav.xml")
    main = _write(tmp_path / "trees", "agent.xml", THREATENING.format(path="link.xml"))
    with pytest.raises(BTError, match="leaves the allowed folders"):
        load_tree_file(main)


def test_include_cycle_and_depth_limit(tmp_path):
    _write(tmp_path, "a.xml", '<root BTCPP_format="4"><include path="b.xml"/></root>')
    _write(tmp_path, "b.xml", '<root BTCPP_format="4"><include path="a.xml"/></root>')
    with pytest.raises(BTError, match="include cycle: a.xml -> b.xml -> a.xml"):
        resolve_includes(tmp_path / "a.xml")
    for i in range(MAX_INCLUDE_DEPTH + 2):
        _write(tmp_path, f"d{i}.xml", f'<root BTCPP_format="4"><include path="d{i + 1}.xml"/></root>')
    with pytest.raises(BTError, match=f"deeper than {MAX_INCLUDE_DEPTH}"):
        resolve_includes(tmp_path / "d0.xml")
    # an explicit allowed folder above the file admits what is inside it
    _write(tmp_path / "lib", "BTRegularNav.xml", REGULAR)
    main = _write(tmp_path / "trees", "agent.xml", THREATENING.format(path="../lib/BTRegularNav.xml"))
    assert b"RegularNavTree" in resolve_includes(main, allowed_roots=[tmp_path])


def test_ros_package_include_is_explained(tmp_path):
    main = _write(tmp_path, "agent.xml", '<root BTCPP_format="4"><include ros_pkg="hunav_agent_manager" '
                                         'path="behavior_trees/BTRegularNav.xml"/></root>')
    with pytest.raises(BTError, match="ros_pkg"):
        resolve_includes(main)


def test_hunavsim_style_tree_ticks_in_grove(hall, tmp_path):
    """SetBlackboard + SubTree remapping, RegularNav's goal loop: the agent walks its goals."""
    _write(tmp_path / "lib", "BTRegularNav.xml", REGULAR)
    main = _write(tmp_path, "agent.xml", THREATENING.format(path="lib/BTRegularNav.xml"))
    from grove_tui.simulation.simulation import Simulation

    world, grid, planner = hall
    document = load_tree_file(main)
    agents = [agent(1, (5.0, 6.0), goals=((10.0, 6.0), (5.0, 6.0)))]
    sim = Simulation.build(agents, [document], world=world, grid=grid, planner=planner, walls=world.walls(), seed=7)
    sim.run(8.0)
    assert sim.crowd.pos[0][0] > 6.0  # walked toward its first goal
    assert sim.tree_errors == {}


def test_unset_blackboard_entry_stops_that_agent_only(hall):
    # HuNavSim 2.0's BTSurprisedNav.xml reads {dist}/{duration}/{once}, which its agent manager never sets
    bodies = ['<Sequence><StopAndWaitTimerAction wait_duration="{duration}"/><Wait duration="1"/></Sequence>',
              '<GoTo target="counter"/>']
    sim = simulate(hall, [agent(1, (8, 6)), agent(2, (5, 6))], bodies)
    sim.run(6.0)
    assert list(sim.tree_errors) == [1] and "{duration}" in sim.tree_errors[1] and "not set" in sim.tree_errors[1]
    assert "tree error" in sim.agent_status(1)
    assert any(kind == "tree_error" for _, _, kind, _ in sim.context.events)
    assert math.dist(sim.crowd.pos[1], (5, 6)) > 1.0  # the other agent carried on to the counter


@pytest.mark.skipif(not os.environ.get("GROVE_HUNAV_TREES"), reason="set GROVE_HUNAV_TREES to HuNavSim's tree folder")
def test_every_tree_in_a_hunavsim_folder_validates():
    folder = Path(os.environ["GROVE_HUNAV_TREES"])
    files = sorted(p for p in folder.rglob("*.xml") if "<BehaviorTree" in p.read_text(errors="replace"))
    assert files
    bad = {p.name: [str(q) for q in check_tree_file(p)] for p in files}
    assert {k: v for k, v in bad.items() if v} == {}


@pytest.mark.skipif(not os.environ.get("GROVE_HUNAV_TREES"), reason="set GROVE_HUNAV_TREES to HuNavSim's tree folder")
def test_every_tree_in_a_hunavsim_folder_ticks_for_a_minute(hall):
    """Each tree drives agent 1 among three RegularNav agents for 60 s: it runs, or stops that agent
    alone on a blackboard entry HuNavSim's agent manager never sets ({dist}, {duration}...)."""
    from grove_tui.scenario.model import RobotSpec
    from grove_tui.simulation.simulation import Simulation

    folder = Path(os.environ["GROVE_HUNAV_TREES"])
    world, grid, planner = hall
    goals = {i: (4.0 + 1.5 * i, 3.0 + (i % 3) * 2.5) for i in range(1, 9)}

    class _Scenario:
        global_goals = goals

    regular = next(p for p in folder.rglob("BTRegularNav.xml"))
    for path in sorted(p for p in folder.rglob("*.xml") if "<BehaviorTree" in p.read_text(errors="replace")):
        documents = [load_tree_file(path)] + [load_tree_file(regular)] * 3
        agents = [agent(i, (3.0 + 2 * i, 5.0), goals=(goals[i], goals[i + 4])) for i in range(1, 5)]
        sim = Simulation.build(agents, documents, world=world, grid=grid, planner=planner, walls=world.walls(),
                               robot=RobotSpec(start=(15.0, 8.0), goal=(5.0, 8.0), max_vel=0.5), seed=1,
                               scenario=_Scenario())
        sim.run(60.0)
        assert set(sim.tree_errors) <= {1}, path.name
        assert all("which is not set" in message for message in sim.tree_errors.values()), path.name


def test_older_hunavsim_point_ports_validate_and_run(hall):
    # Earlier HuNavSim 2.0 trees name points by target_x/target_y (GoTo, SetGoal, LookAtPoint) and
    # center_x/center_y (ConversationFormation) instead of global goal ids.
    body = ('<Sequence><GoTo agent_id="{id}" target_x="10" target_y="6" time_step="{dt}" temporary="false" '
            'stop_duration="5.0"/><LookAtPoint agent_id="{id}" target_x="12" target_y="6"/></Sequence>')
    xml = ('<root BTCPP_format="4" main_tree_to_execute="T"><BehaviorTree ID="T">' + body + '</BehaviorTree></root>')
    from grove_tui.bt.format.xml import check_tree_text

    assert check_tree_text(xml) == []
    sim = simulate(hall, [agent(1, (5.0, 6.0))], [body])
    sim.run(10.0)
    assert math.dist(sim.crowd.pos[0], (10.0, 6.0)) < 0.6
    assert sim.tree_errors == {}
