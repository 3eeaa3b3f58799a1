"""The node database agrees with the node manifest: every node documented, nothing stale, templates valid."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
import yaml

from grove_tui.bt.format.manifest import NODES
from grove_tui.generation.node_docs import (
    check_node_documents,
    load_node_database,
    load_templates,
    render_node_document,
    split_camel,
    sync_node_documents,
    template_problems,
)
from grove_tui.paths import node_db_dir


@pytest.fixture
def node_db_copy(tmp_path: Path) -> Path:
    target = tmp_path / "node_db"
    shutil.copytree(node_db_dir(), target)
    return target


def test_shipped_node_database_matches_the_manifest():
    assert check_node_documents(node_db_dir()) == []


def test_every_manifest_node_has_a_document():
    documented = {path.stem for path in (node_db_dir() / "nodes").glob("*.md")}
    assert documented == set(NODES)


def test_a_missing_document_is_reported(node_db_copy: Path):
    (node_db_copy / "nodes" / "Queue.md").unlink()
    problems = check_node_documents(node_db_copy)
    assert any("Queue.md: missing" in p for p in problems), problems


def test_a_stale_document_is_reported(node_db_copy: Path):
    path = node_db_copy / "nodes" / "GoTo.md"
    path.write_text(path.read_text(encoding="utf-8").replace("tolerance", "tolerence"), encoding="utf-8")
    problems = check_node_documents(node_db_copy)
    assert any("GoTo.md: stale" in p for p in problems), problems


def test_a_document_for_a_node_that_does_not_exist_is_reported(node_db_copy: Path):
    (node_db_copy / "nodes" / "Teleport.md").write_text("---\nname: Teleport\n---\n# Teleport\n", encoding="utf-8")
    problems = check_node_documents(node_db_copy)
    assert any("no node Teleport" in p for p in problems), problems


def _write_template(root: Path, tree: dict, nodes: list[str], presets=("normal", "vanilla")) -> None:
    data = {"name": "broken", "description": "a template under test", "presets": list(presets), "tree": tree, "nodes": nodes}
    (root / "templates" / "broken.yaml").write_text(yaml.safe_dump(data), encoding="utf-8")


def test_a_template_naming_an_unknown_node_is_reported(node_db_copy: Path):
    _write_template(node_db_copy, {"node": "Sequence", "children": [{"node": "Teleport", "target": "x"}]}, ["Teleport"])
    problems = check_node_documents(node_db_copy)
    assert any("unknown node 'Teleport'" in p for p in problems), problems


def test_a_template_naming_an_unknown_port_is_reported(node_db_copy: Path):
    _write_template(node_db_copy, {"node": "GoTo", "destination": "lobby"}, ["GoTo"])
    problems = check_node_documents(node_db_copy)
    assert any("GoTo has no port 'destination'" in p for p in problems), problems


def test_a_template_writing_an_automatic_port_is_reported(node_db_copy: Path):
    _write_template(node_db_copy, {"node": "GoTo", "target": "lobby", "waypoints": "1,2;3,4"}, ["GoTo"])
    problems = check_node_documents(node_db_copy)
    assert any("GoTo.waypoints is automatic" in p for p in problems), problems


def test_a_template_whose_node_list_disagrees_with_its_tree_is_reported(node_db_copy: Path):
    tree = {"node": "Sequence", "children": [{"node": "GoTo", "target": "a"}, {"node": "Wait"}]}
    _write_template(node_db_copy, tree, ["Sequence", "GoTo"])
    problems = check_node_documents(node_db_copy)
    assert any("nodes omits ['Wait']" in p for p in problems), problems


def test_a_template_offered_to_a_preset_its_nodes_forbid_is_reported(node_db_copy: Path):
    _write_template(node_db_copy, {"node": "Wander", "zone": "lobby"}, ["Wander"], presets=("emergency",))
    problems = check_node_documents(node_db_copy)
    assert any("may not retrieve Wander" in p for p in problems), problems


def test_shipped_templates_cover_the_required_situations():
    names = {t.name for t in load_templates(node_db_dir())}
    required = {"queue_at_counter", "group_walk_to_goal", "conversation_circle", "evacuation_group", "wander_in_zone",
                "follow_someone", "robot_curious_bystander", "scared_of_robot", "wait_then_leave",
                "visit_places_in_order", "patrol_between_points"}
    assert required <= names
    for template in load_templates(node_db_dir()):
        assert template_problems(template, NODES) == []


def test_sync_writes_missing_documents_and_removes_orphans(node_db_copy: Path):
    (node_db_copy / "nodes" / "Wait.md").unlink()
    (node_db_copy / "nodes" / "Teleport.md").write_text("---\nname: Teleport\n---\n", encoding="utf-8")
    written, removed = sync_node_documents(node_db_copy)
    assert written == ["Wait"]
    assert removed == ["Teleport"]
    assert check_node_documents(node_db_copy) == []
    assert sync_node_documents(node_db_copy) == ([], [])


def test_node_document_shows_writable_ports_with_ranges_and_marks_automatic_ones():
    text = render_node_document(NODES["Queue"])
    ports_section = text.split("Ports:")[1].split("\n\n")[0]
    assert "- spacing: float; 0.3..3.0, default 0.6." in ports_section
    assert "- service_point: target" in ports_section and "required" in ports_section
    assert "agent_id" not in ports_section and "- x:" not in ports_section
    assert "Automatic (filled by post-processing, never write): x, y, agent_id" in text
    assert 'Example: {"node": "Queue", "service_point": "<service_point>"}' in text


def test_notes_for_an_unknown_node_are_rejected(node_db_copy: Path):
    with (node_db_copy / "notes.yaml").open("a", encoding="utf-8") as handle:
        handle.write("Teleport:\n  constraints: [never]\n")
    problems = check_node_documents(node_db_copy)
    assert any("Teleport" in p and "notes.yaml" in p for p in problems), problems


def test_database_indexes_only_model_writable_leaf_nodes_and_templates():
    database = load_node_database(node_db_dir())
    indexed = {d.name for d in database.documents if d.indexed}
    assert "Queue" in indexed and "queue_at_counter" in indexed
    assert "Sequence" not in indexed  # control nodes come from the preset
    assert "SetGoal" not in indexed  # llm=False: post-processing only
    for name, spec in NODES.items():
        if spec.llm and spec.category != "control":
            assert name in indexed, name


def test_split_camel_reads_node_names_as_words():
    assert split_camel("FollowVelocityField") == "follow velocity field"
    assert split_camel("IsRobotVisible") == "is robot visible"
    assert split_camel("GoTo") == "go to"


def test_a_presets_file_that_is_not_a_mapping_is_named(node_db_copy: Path) -> None:
    """presets.yaml must map each preset to what it prioritises; a list is refused with the file's name."""
    from grove_tui.errors import NodeDbError

    (node_db_copy / "presets.yaml").write_text("- emergency\n- queuing\n", encoding="utf-8")
    with pytest.raises(NodeDbError, match=r"presets\.yaml: expected a mapping"):
        load_node_database(node_db_copy)
