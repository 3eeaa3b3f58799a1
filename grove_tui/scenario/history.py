"""A scenario's history of follow-ups: each edit a step (sentence, reading, diff), kept in generation.json.

    history = History.from_report(json.loads(Path("generation.json").read_text()))
    for step in history.steps:
        print(step.number, step.sentence)
        for line in step.diff.lines():
            print("  ", line)

A `RefineDiff` says what a follow-up does to the scenario's groups before it is applied: groups
added, changed (which fields, old -> new) and removed, with counts, places and behaviors, and what
happens to the robot. It is plain data: generation/refine.py builds it, the app and the CLI show it,
the bundle keeps it.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TypedDict

from grove_tui.jsontypes import JSONMapping, JSONObject, Parsed

ADDED, CHANGED, REMOVED = "added", "changed", "removed"
MARKS = {ADDED: "+", CHANGED: "~", REMOVED: "-"}


@dataclass(frozen=True)
class GroupSummary:
    """A group as a diff shows it: who, how many, what they do and where."""

    label: str
    count: int
    behavior: str  # "queue at pharmacy_counter", "walk to cafeteria", "wander in main_corridor"
    start: str = ""  # where they start ("" when the sentence leaves it to the scenario)
    pace: str = "normal"
    reaction: str = ""  # HuNavSim reaction to the robot, "" for none

    def text(self) -> str:
        out = f"{self.label} ×{self.count}: {self.behavior}"
        if self.start:
            out += f", from {self.start}"
        if self.pace != "normal":
            out += f", {self.pace}"
        if self.reaction:
            out += f", {self.reaction} with the robot"
        return out

    def to_dict(self) -> JSONObject:
        return {"label": self.label, "count": self.count, "behavior": self.behavior, "start": self.start,
                "pace": self.pace, "reaction": self.reaction}

    @classmethod
    def from_dict(cls, data: Parsed) -> GroupSummary:
        return cls(str(data["label"]), int(data["count"]), str(data.get("behavior", "")), str(data.get("start", "")),
                   str(data.get("pace", "normal")), str(data.get("reaction", "")))


@dataclass(frozen=True)
class GroupChange:
    kind: str  # ADDED, CHANGED or REMOVED
    before: GroupSummary | None
    after: GroupSummary | None
    fields: tuple[str, ...] = ()  # what a change changes: "count", "behavior", "start", "pace", "reaction"
    regenerated: bool = False  # the model writes the group's tree again (else its tree is kept)

    @property
    def label(self) -> str:
        shown = self.after or self.before
        return shown.label if shown is not None else ""

    def line(self) -> str:
        if self.kind == ADDED and self.after is not None:
            return f"+ {self.after.text()}"
        if self.kind == REMOVED and self.before is not None:
            return f"- {self.before.text()}"
        assert self.before is not None and self.after is not None
        parts = []
        b, a = self.before, self.after
        if b.count != a.count:
            parts.append(f"×{b.count} → ×{a.count}")
        if b.behavior != a.behavior:
            parts.append(f"{b.behavior} → {a.behavior}")
        if b.start != a.start:
            parts.append(f"from {b.start or '-'} → from {a.start or '-'}")
        if b.pace != a.pace:
            parts.append(f"{b.pace} → {a.pace} pace")
        if b.reaction != a.reaction:
            parts.append(f"robot: {b.reaction or 'no reaction'} → {a.reaction or 'no reaction'}")
        return f"~ {a.label}: " + ("; ".join(parts) if parts else "unchanged")

    def to_dict(self) -> JSONObject:
        return {"kind": self.kind, "before": self.before.to_dict() if self.before else None,
                "after": self.after.to_dict() if self.after else None, "fields": list(self.fields),
                "regenerated": self.regenerated}

    @classmethod
    def from_dict(cls, data: Parsed) -> GroupChange:
        return cls(str(data["kind"]), GroupSummary.from_dict(data["before"]) if data.get("before") else None,
                   GroupSummary.from_dict(data["after"]) if data.get("after") else None,
                   tuple(str(f) for f in data.get("fields", ())), bool(data.get("regenerated", False)))


@dataclass(frozen=True)
class RobotChange:
    kind: str  # ADDED, CHANGED or REMOVED
    before: str  # "crosses entrance_lobby -> pharmacy", "none"
    after: str

    def line(self) -> str:
        return f"{MARKS.get(self.kind, '~')} robot: {self.before} → {self.after}"

    def to_dict(self) -> JSONObject:
        return {"kind": self.kind, "before": self.before, "after": self.after}

    @classmethod
    def from_dict(cls, data: Parsed) -> RobotChange:
        return cls(str(data["kind"]), str(data.get("before", "")), str(data.get("after", "")))


@dataclass(frozen=True)
class RefineDiff:
    sentence: str
    groups: tuple[GroupChange, ...] = ()
    robot: RobotChange | None = None
    kept: int = 0  # groups left exactly as they were
    notes: tuple[str, ...] = ()

    @property
    def empty(self) -> bool:
        return not self.groups and self.robot is None

    def lines(self) -> list[str]:
        out = [change.line() for change in self.groups]
        if self.robot is not None:
            out.append(self.robot.line())
        out.append(f"= {self.kept} group(s) kept as they are" if self.kept else "= no group kept as it was")
        out += [f"! {note}" for note in self.notes]
        return out

    def to_dict(self) -> JSONObject:
        return {"sentence": self.sentence, "groups": [g.to_dict() for g in self.groups],
                "robot": self.robot.to_dict() if self.robot is not None else None, "kept": self.kept,
                "notes": list(self.notes)}

    @classmethod
    def from_dict(cls, data: Parsed) -> RefineDiff:
        return cls(str(data.get("sentence", "")), tuple(GroupChange.from_dict(g) for g in data.get("groups", ())),
                   RobotChange.from_dict(data["robot"]) if data.get("robot") else None, int(data.get("kept", 0)),
                   tuple(str(n) for n in data.get("notes", ())))


class StageTiming(TypedDict):
    """One stage's entry in generation.json's "stages" (and a history step's): its time and tokens."""

    seconds: float
    prompt_tokens: int
    completion_tokens: int


@dataclass(frozen=True)
class HistoryStep:
    """One follow-up applied: its number (the first sentence is 0), words, reading and diff."""

    number: int
    sentence: str
    reading: JSONMapping  # the EditReading's to_dict() (language/edits.py)
    diff: RefineDiff
    seed: int = 0
    seconds: float = 0.0
    stages: Mapping[str, StageTiming] = field(default_factory=dict)

    def to_dict(self) -> dict[str, object]:  # JSON; object, because JSONValue cannot name StageTiming
        return {"number": self.number, "sentence": self.sentence, "reading": self.reading,
                "diff": self.diff.to_dict(), "seed": self.seed, "seconds": self.seconds, "stages": self.stages}

    @classmethod
    def from_dict(cls, data: Parsed) -> HistoryStep:
        return cls(int(data["number"]), str(data["sentence"]), dict(data.get("reading") or {}),
                   RefineDiff.from_dict(data.get("diff") or {}), int(data.get("seed", 0)),
                   float(data.get("seconds", 0.0)), dict(data.get("stages") or {}))


@dataclass(frozen=True)
class History:
    prompt: str  # sentence 0
    steps: tuple[HistoryStep, ...] = ()

    @property
    def sentences(self) -> list[str]:
        return [self.prompt] + [step.sentence for step in self.steps]

    @classmethod
    def from_report(cls, report: Parsed) -> History:
        return cls(str(report.get("prompt", "")), tuple(HistoryStep.from_dict(s) for s in report.get("history", ())))
