"""The manifest is the single source of truth: its invariants and its agreement with the runtime."""

from __future__ import annotations

import pytest

from grove_tui.bt.format.manifest import (
    CATEGORIES, NODES, PORT_TYPES, PRESETS, navigation_nodes, nodes_for_preset,
)
from grove_tui.crowd.leaves.registry import LEAF_CLASSES, unimplemented_nodes
from grove_tui.bt.format.ports import blackboard_pointer, convert_literal

# hunav_agent_manager/behavior_trees/TreeNodesModel.xml (d5b716b) plus the reference's TimeExpiredCondition,
# AvoidRobot and TimeDelay; GoTo is GROVE's (HuNavSim's ports kept, see below)
HUNAV_PORTS = {
    "IsGoalReached": {"agent_id"},
    "IsRobotVisible": {"agent_id", "distance"},
    "RandomChanceCondition": {"agent_id", "probability"},
    "IsRobotFacingAgent": {"agent_id"},
    "IsAgentVisible": {"observer_id", "agent_id", "distance", "field_of_view"},
    "IsRobotClose": {"agent_id", "threshold"},
    "IsAgentClose": {"observer_id", "target_agent_id", "threshold"},
    "UpdateGoal": {"agent_id"},
    "RegularNav": {"agent_id", "time_step"},
    "SurprisedNav": {"agent_id", "time_step", "beh_duration", "only_once"},
    "CuriousNav": {"agent_id", "time_step", "beh_duration", "only_once", "agent_vel", "stop_distance"},
    "ScaredNav": {"agent_id", "time_step", "beh_duration", "only_once", "runaway_vel", "scary_force_factor"},
    "ThreateningNav": {"agent_id", "time_step", "beh_duration", "only_once", "goal_dist"},
    "FindNearestAgent": {"agent_id", "target_agent_id"},
    "SaySomething": {"agent_id", "message"},
    "SetGroupId": {"agent_id", "group_id"},
    "SetGoal": {"agent_id", "goal_id"},
    "StopMovement": {"agent_id"},
    "ResumeMovement": {"agent_id"},
    "StopAndWaitTimerAction": {"agent_id", "wait_duration"},
    "ConversationFormation": {"main_agent_id", "conversation_duration", "goal_id", "time_step", "non_main_agent_ids"},
    "ApproachAgent": {"agent_id", "target_agent_id", "time_step", "closest_dist", "max_vel", "duration"},
    "ApproachRobot": {"agent_id", "time_step", "closest_dist", "max_vel", "duration"},
    "BlockRobot": {"agent_id", "time_step", "front_dist", "duration"},
    "BlockAgent": {"agent_id", "target_agent_id", "time_step", "front_dist", "duration"},
    "SetGroupWalk": {"main_agent_id", "time_step", "non_main_agent_ids", "duration"},
    "LookAtAgent": {"observer_id", "target_id"},
    "LookAtRobot": {"agent_id"},
    "LookAtPoint": {"agent_id", "goal_id"},
    "IsAnyoneSpeaking": {"agent_id", "time_step", "distance_threshold", "duration", "speaker_id"},
    "IsSpeaking": {"agent_id", "time_step", "target_id", "distance_threshold", "duration"},
    "IsAnyoneLookingAtMe": {"agent_id", "time_step", "distance_threshold", "angle_threshold", "duration", "observer_id"},
    "IsLookingAtMe": {"agent_id", "time_step", "target_id", "distance_threshold", "angle_threshold", "duration"},
    "TimeExpiredCondition": {"seconds", "ts", "only_once"},
    "AvoidRobot": {"agent_id", "time_step", "safe_distance", "runaway_vel", "duration"},
    "TimeDelay": {"delay"},
}


def test_every_hunavsim_node_keeps_its_port_names():
    for name, ports in HUNAV_PORTS.items():
        assert name in NODES, name
        assert NODES[name].origin == "hunavsim"
        have = set(NODES[name].port_names)
        assert ports <= have, f"{name} lacks {ports - have}"


def test_grove_goto_keeps_hunavsim_goto_ports():
    assert {"agent_id", "time_step", "goal_id", "tolerance"} <= set(NODES["GoTo"].port_names)
    for name in ("agent_id", "time_step", "goal_id"):
        assert NODES["GoTo"].port(name).auto


def test_every_manifest_node_has_an_implementation():
    assert unimplemented_nodes() == []
    assert set(LEAF_CLASSES) <= set(NODES)


@pytest.mark.parametrize("name", sorted(NODES))
def test_node_spec_is_well_formed(name):
    spec = NODES[name]
    assert spec.category in CATEGORIES
    assert spec.origin in ("btcpp", "hunavsim", "grove")
    assert spec.presets <= set(PRESETS)
    assert len(spec.description) > 40 and "\n" not in spec.description
    assert len({p.name for p in spec.ports}) == len(spec.ports)
    for port in spec.ports:
        assert port.type in PORT_TYPES
        assert port.direction in ("in", "out")
        assert port.description
        if port.default is not None and not (isinstance(port.default, str) and blackboard_pointer(port.default)):
            text = str(port.default).lower() if isinstance(port.default, bool) else str(port.default)
            convert_literal(port, text)  # defaults respect their own type and range
        if port.min is not None and port.max is not None:
            assert port.min <= port.max
    if spec.llm:
        assert spec.presets, f"{name} is offered to the model but in no preset"
    if spec.origin == "grove":
        assert spec.llm, "GROVE nodes exist for the model to write"


def test_navigation_nodes_carry_target_point_and_waypoint_ports():
    assert navigation_nodes() == {"GoTo", "Converse"}
    for name in navigation_nodes():
        spec = NODES[name]
        assert spec.port("target").type == "target" and not spec.port("target").auto
        for auto in ("x", "y", "waypoints"):
            assert spec.port(auto).auto
        assert spec.port("waypoints").type == "point_list"


def test_auto_ports_are_never_required_from_the_model():
    for spec in NODES.values():
        for port in spec.llm_ports:
            assert not port.auto
        for port in spec.ports:
            if port.auto:
                assert not port.required


def test_presets_follow_the_paper():
    emergency = {s.name for s in nodes_for_preset("emergency")}
    assert "FollowVelocityField" in emergency
    assert not emergency & {"GoTo", "Converse", "Wander", "FollowAgent", "Queue"}  # paper: no roaming, chatting
    queuing = {s.name for s in nodes_for_preset("queuing")}
    assert {"Queue", "GoTo", "Wait"} <= queuing and "FollowVelocityField" not in queuing
    normal = {s.name for s in nodes_for_preset("normal")}
    assert {"Converse", "Wander", "JoinGroup", "FollowAgent", "GoTo", "Queue"} <= normal
    assert {s.name for s in nodes_for_preset("my_custom_preset")} == {s.name for s in nodes_for_preset("vanilla")}
    for preset in PRESETS:
        names = {s.name for s in nodes_for_preset(preset)}
        assert {"Sequence", "Fallback"} <= names
        assert not names & {"SetGoal", "UpdateGoal", "RegularNav", "ConversationFormation"}  # id bookkeeping


def test_synonyms_help_lexical_retrieval():
    assert "line up" in NODES["Queue"].synonyms
    assert "evacuate" in NODES["FollowVelocityField"].synonyms
    for spec in NODES.values():
        if spec.llm and spec.origin == "grove":
            assert len(spec.synonyms) >= 5
