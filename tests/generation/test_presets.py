"""Presets are data: shipped files load, user files override, malformed files are named precisely."""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml

from grove_tui.generation.presets import PresetError, list_presets, load_preset, preset_from_dict
from grove_tui.paths import presets_dir

SHIPPED = ("emergency", "queuing", "normal", "vanilla")


@pytest.mark.parametrize("name", SHIPPED)
def test_shipped_presets_load(name):
    preset = load_preset(name)
    assert preset.name == name
    assert preset.description and "\n" not in preset.description
    assert preset.template
    assert preset.control_nodes


def test_shipped_preset_policies_follow_the_paper():
    emergency, queuing, normal, vanilla = (load_preset(n) for n in SHIPPED)
    assert emergency.velocity == "field" and emergency.required_nodes == ("FollowVelocityField",)
    assert not {"Converse", "Wander", "FollowAgent"} & set(emergency.allowed_nodes)
    assert "exits" in emergency.required_rois
    assert queuing.goal_sampling == "sequential" and "Queue" in queuing.allowed_nodes and queuing.planner.enabled
    assert normal.velocity == "waypoints" and normal.planner.enabled and "FollowVelocityField" in normal.forbidden_nodes
    assert vanilla.context == "world" and not vanilla.guided and vanilla.retrieval_filter is None


def test_list_presets_has_the_shipped_ones_first(monkeypatch, tmp_path):
    monkeypatch.setenv("GROVE_CONFIG_DIR", str(tmp_path))
    assert list_presets()[:4] == sorted(SHIPPED)


def test_user_preset_in_config_dir_is_found_and_overrides(monkeypatch, tmp_path):
    monkeypatch.setenv("GROVE_CONFIG_DIR", str(tmp_path))
    data = yaml.safe_load((presets_dir() / "normal.yaml").read_text())
    data["name"] = "calm"
    data["description"] = "Quiet afternoon"
    (tmp_path / "presets").mkdir()
    (tmp_path / "presets" / "calm.yaml").write_text(yaml.safe_dump(data))
    assert "calm" in list_presets()
    assert load_preset("calm").description == "Quiet afternoon"
    data["name"] = "normal"
    data["description"] = "my normal"
    (tmp_path / "presets" / "normal.yaml").write_text(yaml.safe_dump(data))
    assert load_preset("normal").description == "my normal"


def test_preset_by_path(tmp_path):
    data = yaml.safe_load((presets_dir() / "queuing.yaml").read_text())
    path = tmp_path / "mine.yaml"
    path.write_text(yaml.safe_dump(data))
    assert load_preset(str(path)).name == "queuing"


def test_unknown_preset_lists_known_ones():
    with pytest.raises(PresetError, match="unknown preset 'panic'.*emergency"):
        load_preset("panic")


def test_empty_preset_name():
    with pytest.raises(PresetError, match="no preset given"):
        load_preset("  ")


def test_missing_path():
    with pytest.raises(PresetError, match="no such preset file"):
        load_preset("/nonexistent/thing.yaml")


def _base() -> dict:
    return yaml.safe_load((presets_dir() / "normal.yaml").read_text())


@pytest.mark.parametrize(
    "change, message",
    [
        (lambda d: d.pop("template"), "missing key 'template'"),
        (lambda d: d.update(velocity="teleport"), "velocity must be one of waypoints, field"),
        (lambda d: d.update(goal_sampling=3), "goal_sampling must be text"),
        (lambda d: d["limits"].update(max_count=0), "limits.max_count must be a positive number"),
        (lambda d: d["limits"].update(max_count=501), "limits.max_count: 501 is over the limit of 500 people per group"),
        (lambda d: d["limits"].update(max_groups=2.5), "limits.max_groups must be a whole number"),
        (lambda d: d["planner"].update(enabled="yes"), "planner.enabled must be true or false"),
        (lambda d: d["nodes"].update(control=[]), "nodes.control must name at least one"),
        (lambda d: d["nodes"].update(allowed="GoTo"), "nodes.allowed must be a list"),
        (lambda d: d.update(required_rois=["toilets"]), "required_rois may hold exits"),
        (lambda d: d["retrieval"].update(k=-1), "retrieval.k must be a whole number"),
    ],
)
def test_malformed_presets_name_the_key(change, message):
    data = _base()
    change(data)
    with pytest.raises(PresetError, match=message):
        preset_from_dict(data, source=Path("bad.yaml"))


def test_not_a_mapping(tmp_path):
    path = tmp_path / "list.yaml"
    path.write_text("- a\n- b\n")
    with pytest.raises(PresetError, match="list.yaml: expected a mapping"):
        load_preset(str(path))


def test_grid_inflation_follows_the_agents_radius_unless_the_preset_sets_it():
    data = _base()
    data["agent"]["radius"] = 0.3
    assert preset_from_dict(data, source=Path("p.yaml")).planner.inflation == 0.3
    data["planner"]["inflation"] = 0.4
    preset = preset_from_dict(data, source=Path("p.yaml"))
    assert (preset.agent_radius, preset.planner.inflation) == (0.3, 0.4)


def test_exit_choice_and_radius_are_checked():
    data = _base()
    data["exit_choice"] = "busiest"
    with pytest.raises(PresetError, match="exit_choice must be one of nearest, least_congested"):
        preset_from_dict(data, source=Path("bad.yaml"))
    data = _base()
    data["agent"]["radius"] = 5.0
    with pytest.raises(PresetError, match=r"agent.radius must be 0.05..2.0 m"):
        preset_from_dict(data, source=Path("bad.yaml"))
