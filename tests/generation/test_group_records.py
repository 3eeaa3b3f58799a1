"""generation.json's group records carry what a later follow-up needs to report a group it does not touch."""

from __future__ import annotations

from grove_tui.generation.pipeline import group_records
from grove_tui.generation.postprocess import GroupPlan
from grove_tui.generation.scene import node_from_dict


def test_what_the_model_added_is_kept_for_the_follow_ups_report():
    # A follow-up rebuilds the report of untouched groups from these records: without "added" the
    # pause the model put after the walk was no longer listed as something nobody asked for.
    tree = node_from_dict({"node": "Sequence", "children": [{"node": "GoTo", "ports": {"target": "cafeteria"}},
                                                            {"node": "Wait", "ports": {"duration": 5.0}}]})
    plan = GroupPlan(0, "nurse", 1, "ward_a", tree, member_ids=[1], added=["a pause of 5 s"])
    plain = GroupPlan(1, "patient", 2, "ward_b", tree, member_ids=[2, 3])
    records = group_records([plan, plain], None)
    assert records[0]["added"] == ["a pause of 5 s"]
    assert "added" not in records[1]  # nothing added, nothing written: bundles without extras keep their bytes
