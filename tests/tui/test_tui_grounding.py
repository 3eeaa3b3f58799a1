"""The inspect screen's grounding report: reading generation.json's `grounding` entry and drawing it."""

from __future__ import annotations

from grove_tui.tui.widgets.grounding import grounding_text, read_grounding, summary

# The shape the language layer's GroundingReport.to_dict() writes.
REPORT = {"grounding": {
    "prompt": "ten patients queue at the pharmacy while a family walks to the exit",
    "ok": False,
    "groups": [
        {"who": "ten patients", "label": "patient", "ok": True, "members": list(range(1, 11)), "checks": [
            {"field": "count", "asked": "10", "does": "10", "ok": True, "reason": ""},
            {"field": "destination", "asked": "pharmacy_counter", "does": "pharmacy_counter", "ok": True,
             "reason": ""},
            {"field": "behavior", "asked": "queue", "does": "queue", "ok": True, "reason": ""}]},
        {"who": "a family", "label": "family", "ok": False, "members": [11, 12, 13], "checks": [
            {"field": "count", "asked": "2-6", "does": "3", "ok": True, "reason": ""},
            {"field": "destination", "asked": "main_entrance", "does": "cafeteria", "ok": False,
             "reason": "no path to main_entrance from the spawn"}]},
    ],
    "unhonoured": ["'by the window': the world has no window"],
    "repairs": [],
}}


def test_reads_the_language_layers_report():
    groups, notes = read_grounding(REPORT)
    assert [g.label for g in groups] == ["ten patients", "a family"]
    assert [g.ok for g in groups] == [True, False]
    assert groups[0].agents == 10
    failed = [c for c in groups[1].checks if not c.ok]
    assert [(c.field, c.asked, c.done, c.reason) for c in failed] == [
        ("destination", "main_entrance", "cafeteria", "no path to main_entrance from the spawn")]
    assert notes == ["'by the window': the world has no window"]
    assert summary((groups, notes)) == "1/2 groups ✓"


def test_renders_asked_beside_done_with_marks_and_reasons():
    text = grounding_text(read_grounding(REPORT), width=60)
    assert "✓ ten patients ×10" in text
    assert " ✓ count       10" in text  # agreement shows the value once
    assert " ✗ destination main_entrance → cafeteria" in text
    assert "no path to main_entrance from the spawn" in text
    assert " ✓ count       2-6 → 3" in text
    assert "! 'by the window': the world has no window" in text


def test_values_wrap_inside_their_column_at_80x24_widths():
    lines = grounding_text(read_grounding(REPORT), width=30).splitlines()
    reason = [i for i, line in enumerate(lines) if "no path" in line][0]
    # the reason starts under the value column, not under the mark
    assert lines[reason].index("no path") == lines[reason - 1].index("cafeteria") > 10
    assert max(len(line.rstrip()) for line in lines) <= 30


def test_other_shapes_and_missing_reports():
    # asked/done mappings with per-field verdicts, and checks without a verdict (agreement decides)
    parsed = read_grounding({"grounding": [
        {"label": "visitors", "asked": {"count": 4, "start": "lobby"}, "done": {"count": 4, "start": "corridor"},
         "reasons": {"start": "lobby is full"}},
        {"name": "nurse", "checks": [{"name": "behavior", "expected": "wait", "actual": "wait"}]},
    ]})
    groups, notes = parsed
    assert [(c.field, c.ok, c.reason) for c in groups[0].checks] == [("count", True, ""),
                                                                     ("start", False, "lobby is full")]
    assert groups[1].label == "nurse" and groups[1].ok and notes == []
    assert read_grounding({"grounding": {"groups": [{"who": "someone", "label": "visitor", "checks": []}]}}
                          )[0][0].label == "someone → visitor"
    assert read_grounding({"stages": {}}) is None and read_grounding(None) is None
    assert "No grounding report" in grounding_text(None)
    assert summary(None) == ""
