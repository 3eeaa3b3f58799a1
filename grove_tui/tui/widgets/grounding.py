"""The grounding report on the inspect screen: for each group, what the sentence asked beside what the
scenario does, each marked ✓ or ✗ with the reason.

It reads the `grounding` entry of the bundle's generation.json as plain data. The report is written
by the language layer (its GroundingReport's `to_dict()`), and bundles made before it existed have no
such entry, so the reader here accepts the shapes a report of groups and checks can take (a list of
checks per group, or `asked`/`done` mappings) and says plainly when there is no report.
"""

from __future__ import annotations

import io
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from rich.console import Console, Group
from rich.table import Table
from rich.text import Text
from textual.containers import VerticalScroll
from textual.widgets import Static

# Alternative key names, most likely first: the report is data from another layer, read defensively.
FIELD_KEYS = ("field", "name", "what", "aspect", "key")
ASKED_KEYS = ("asked", "expected", "wanted", "requested", "prompt")
DONE_KEYS = ("does", "done", "actual", "got", "scenario", "result")
OK_KEYS = ("ok", "honoured", "honored", "passed", "match", "matches", "satisfied")
REASON_KEYS = ("reason", "why", "note", "detail", "message")
WHO_KEYS = ("who", "phrase", "text")
LABEL_KEYS = ("label", "group", "name")
CHECK_LIST_KEYS = ("checks", "items", "fields", "rows")
NOTE_KEYS = ("unhonoured", "not_honoured", "notes", "warnings")
OK_MARK, FAIL_MARK = "✓", "✗"


@dataclass(frozen=True)
class GroundingCheck:
    field: str
    asked: Any
    done: Any
    ok: bool
    reason: str = ""


@dataclass(frozen=True)
class GroundingGroup:
    label: str  # the group as the sentence says it, and its label in the scenario when that differs
    checks: tuple[GroundingCheck, ...]
    reason: str = ""
    agents: int | None = None  # how many agents the scenario gives it

    @property
    def ok(self) -> bool:
        return all(check.ok for check in self.checks)


def _first(data: Mapping[str, Any], keys: Sequence[str], default: Any = None) -> Any:
    for key in keys:
        if key in data and data[key] is not None:
            return data[key]
    return default


def _check(field: str, data: Any, ok_hint: Any = None, reason_hint: Any = None) -> GroundingCheck:
    if not isinstance(data, Mapping):  # {"count": true}
        return GroundingCheck(field, None, None, bool(data), str(reason_hint or ""))
    asked, done = _first(data, ASKED_KEYS), _first(data, DONE_KEYS)
    ok = _first(data, OK_KEYS, ok_hint)
    if ok is None:
        ok = asked == done  # no verdict given: agreement is the verdict
    return GroundingCheck(str(_first(data, FIELD_KEYS, field)), asked, done, bool(ok),
                          str(_first(data, REASON_KEYS, reason_hint) or ""))


def _group(index: int, data: Any) -> GroundingGroup:
    if not isinstance(data, Mapping):
        return GroundingGroup(f"group {index + 1}", ())
    who, label = _first(data, WHO_KEYS), _first(data, LABEL_KEYS)
    if who and label and str(label).lower() not in str(who).lower():
        label = f"{who} → {label}"  # "someone → visitor": the sentence's words, then the scenario's label
    elif who:
        label = who  # "ten patients" already says "patient"
    label = str(label or f"group {index + 1}")
    members = data.get("members")
    agents = len(members) if isinstance(members, Sequence) and not isinstance(members, str) else None
    checks: list[GroundingCheck] = []
    listed = _first(data, CHECK_LIST_KEYS)
    if isinstance(listed, Sequence) and not isinstance(listed, str):
        checks = [_check(f"check {i + 1}", item) for i, item in enumerate(listed)]
    elif isinstance(listed, Mapping):
        checks = [_check(str(name), item) for name, item in listed.items()]
    else:
        asked, done = data.get("asked"), data.get("done")
        if isinstance(asked, Mapping):
            done = done if isinstance(done, Mapping) else {}
            oks = data.get("ok") if isinstance(data.get("ok"), Mapping) else {}
            reasons = data.get("reasons") if isinstance(data.get("reasons"), Mapping) else {}
            for name, value in asked.items():
                checks.append(_check(str(name), {"asked": value, "done": done.get(name)}, oks.get(name),
                                     reasons.get(name)))
    return GroundingGroup(label, tuple(checks), str(_first(data, REASON_KEYS, "") or ""), agents)


def read_grounding(report: Mapping[str, Any] | None) -> tuple[list[GroundingGroup], list[str]] | None:
    """(groups, notes) from a generation report, or None when it holds no grounding report."""
    if not isinstance(report, Mapping):
        return None
    grounding = report.get("grounding")
    if grounding is None:
        return None
    if isinstance(grounding, Sequence) and not isinstance(grounding, str):
        groups_data, notes = grounding, []
    elif isinstance(grounding, Mapping):
        groups_data = grounding.get("groups") or []
        notes = _first(grounding, NOTE_KEYS, [])
    else:
        return None
    notes = [str(n) for n in notes] if isinstance(notes, Sequence) and not isinstance(notes, str) else [str(notes)]
    corrections = grounding.get("corrections") if isinstance(grounding, Mapping) else None
    if isinstance(corrections, Sequence) and not isinstance(corrections, str):
        notes += [f"correction: {c}" for c in corrections]  # a misspelt place the reading put right
    return [_group(i, g) for i, g in enumerate(groups_data)], notes


def _value(value: Any) -> str:
    if value is None or value in ("", "-") or value == []:
        return "—"
    if isinstance(value, float) and value.is_integer():
        return str(int(value))
    if isinstance(value, (list, tuple)):
        return ", ".join(_value(v) for v in value)
    if isinstance(value, Mapping):  # a count record: show what a person would say
        if "value" in value:
            return _value(value["value"])
        return ", ".join(f"{k} {_value(v)}" for k, v in value.items())
    return str(value)


def render_grounding(parsed: tuple[list[GroundingGroup], list[str]] | None) -> Group:
    """One block per group: its verdict and label, then a grid of checks (mark, field, value), the
    value wrapping inside its own column so a narrow panel (80x24) stays readable. A value the
    sentence did not state shows dim (the scenario chose it); one that differs shows asked → done."""
    if parsed is None:
        return Group(Text("No grounding report in this bundle: it was generated before the sentence was read "
                          "into groups. Regenerate (g) to get one.", style="dim"))
    groups, notes = parsed
    parts: list[Any] = []
    if not groups:
        parts.append(Text("The sentence was read as no group of people.", style="dim"))
    for group in groups:
        header = Text()
        header.append(f"{OK_MARK if group.ok else FAIL_MARK} ", style="bold green" if group.ok else "bold red")
        header.append(group.label, style="bold")
        if group.agents is not None:
            header.append(f" ×{group.agents}", style="dim")
        if group.reason and not group.ok:
            header.append(f"  {group.reason}", style="dim")
        parts.append(header)
        grid = Table.grid(padding=(0, 1, 0, 0))
        grid.add_column(no_wrap=True)
        grid.add_column(no_wrap=True)
        grid.add_column(overflow="fold", ratio=1)
        for check in group.checks:
            mark = Text(f" {OK_MARK if check.ok else FAIL_MARK}", style="green" if check.ok else "red")
            asked, done = _value(check.asked), _value(check.done)
            if asked == "—":
                value = Text(done, style="dim")
            elif asked == done:
                value = Text(done)
            else:
                value = Text(f"{asked} → {done}")
            if check.reason and not check.ok:
                value.append(f"\n{check.reason}", style="italic")
            grid.add_row(mark, Text(check.field, style="" if check.ok else "bold"), value)
        parts.append(grid)
    for note in notes:
        parts.append(Text(f"! {note}", style="yellow"))
    return Group(*parts)


def grounding_text(parsed: tuple[list[GroundingGroup], list[str]] | None, width: int = 60) -> str:
    """The report as plain text at a given width (what the panel shows, without colours)."""
    console = Console(width=width, record=True, color_system=None, file=io.StringIO())
    console.print(render_grounding(parsed))
    return console.export_text()


def summary(parsed: tuple[list[GroundingGroup], list[str]] | None) -> str:
    """'3/4 groups ✓' for a title, or '' without a report."""
    if parsed is None or not parsed[0]:
        return ""
    groups = parsed[0]
    return f"{sum(g.ok for g in groups)}/{len(groups)} groups {OK_MARK}"


class GroundingPanel(VerticalScroll, can_focus=True):
    """The report, scrollable with the arrow keys (groups can outnumber the rows at 80x24)."""

    HELP = """\
## Grounding

For each group of people the sentence describes: what it asked (count, start, destination,
behavior, robot reaction) beside what the scenario does, ✓ when they agree and ✗ with the
reason when they do not. Lines marked `!` are parts of the sentence that could not be honoured.
"""

    def __init__(self, report: Mapping[str, Any] | None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._parsed = read_grounding(report)

    def compose(self):
        yield Static(render_grounding(self._parsed), id="grounding-text")

    def show(self, report: Mapping[str, Any] | None) -> None:
        self._parsed = read_grounding(report)
        self.query_one("#grounding-text", Static).update(render_grounding(self._parsed))
        self.border_title = self.title()

    def title(self) -> str:
        counted = summary(self._parsed)
        return f"Grounding · {counted}" if counted else "Grounding"

    def on_mount(self) -> None:
        self.border_title = self.title()
