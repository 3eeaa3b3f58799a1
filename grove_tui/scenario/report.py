"""The grounding report: for every group, what the sentence asked beside what the scenario does.

Written into generation.json under "grounding", printed by `grove generate` and shown on the app's
inspect screen. It is plain data (no English is read here): generation/reconcile.py builds it from
the prompt's reading and the post-processed groups.

    report = GroundingReport.from_dict(json.loads(Path("generation.json").read_text())["grounding"])
    for line in report.lines():
        print(line)
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

OK_MARK = "✓"
FAIL_MARK = "✗"
CHECKED_FIELDS = ("count", "start", "destination", "behavior", "robot reaction")


@dataclass(frozen=True)
class GroundingCheck:
    """One field of one group: what was asked, what the scenario does, whether they agree and why."""

    field: str  # one of CHECKED_FIELDS
    asked: str  # as the sentence states it ("10", "pharmacy", "queue", "Curious"); "-" when it states nothing
    does: str  # what the scenario does
    ok: bool
    reason: str = ""

    def to_dict(self) -> dict[str, Any]:
        return {"field": self.field, "asked": self.asked, "does": self.does, "ok": self.ok, "reason": self.reason}

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> GroundingCheck:
        return cls(str(data["field"]), str(data["asked"]), str(data["does"]), bool(data["ok"]),
                   str(data.get("reason", "")))


@dataclass(frozen=True)
class GroupGrounding:
    who: str  # the phrase of the sentence ("two families of three")
    label: str  # the group's label in the scenario
    checks: tuple[GroundingCheck, ...]
    members: tuple[int, ...] = ()  # agent ids of the group in the scenario
    asked_by: int = 0  # the sentence that asked for the group: 0 the first, k the k-th follow-up
    changed_by: tuple[int, ...] = ()  # the follow-ups that changed it

    @property
    def ok(self) -> bool:
        return all(c.ok for c in self.checks)

    def to_dict(self) -> dict[str, Any]:
        data = {"who": self.who, "label": self.label, "ok": self.ok, "members": list(self.members),
                "checks": [c.to_dict() for c in self.checks], "asked_by": self.asked_by}
        if self.changed_by:
            data["changed_by"] = list(self.changed_by)
        return data

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> GroupGrounding:
        return cls(str(data["who"]), str(data["label"]), tuple(GroundingCheck.from_dict(c) for c in data["checks"]),
                   tuple(int(m) for m in data.get("members", ())), int(data.get("asked_by", 0)),
                   tuple(int(c) for c in data.get("changed_by", ())))

    def asked(self) -> str:
        """Which sentence asked for the group, and which changed it: "sentence 1, changed by 3"."""
        text = f"sentence {self.asked_by + 1}"
        if self.changed_by:
            text += ", changed by " + ", ".join(str(c + 1) for c in self.changed_by)
        return text


@dataclass(frozen=True)
class GroundingReport:
    prompt: str
    groups: tuple[GroupGrounding, ...]
    unhonoured: tuple[str, ...] = ()  # parts of the sentence the scenario could not honour, said plainly
    repairs: tuple[str, ...] = field(default=())  # where the model's draft was repaired to match the sentence
    # Misspelt place words the reading put right ("read 'kitchn' as 'kitchen'"): honoured, but said,
    # so a user sees which place a typo was taken for. They do not make the report fail.
    corrections: tuple[str, ...] = field(default=())
    # Every sentence the scenario was made from: the prompt, then each follow-up that refined it
    # (generation/refine.py); empty for a scenario of one sentence.
    sentences: tuple[str, ...] = field(default=())

    @property
    def ok(self) -> bool:
        return all(g.ok for g in self.groups) and not self.unhonoured

    def to_dict(self) -> dict[str, Any]:
        data = {"prompt": self.prompt, "ok": self.ok, "groups": [g.to_dict() for g in self.groups],
                "unhonoured": list(self.unhonoured), "repairs": list(self.repairs),
                "corrections": list(self.corrections)}
        if self.sentences:
            data["sentences"] = list(self.sentences)
        return data

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> GroundingReport:
        return cls(str(data.get("prompt", "")), tuple(GroupGrounding.from_dict(g) for g in data.get("groups", ())),
                   tuple(str(u) for u in data.get("unhonoured", ())), tuple(str(r) for r in data.get("repairs", ())),
                   tuple(str(c) for c in data.get("corrections", ())),
                   tuple(str(s) for s in data.get("sentences", ())))

    def lines(self) -> list[str]:
        """Plain-text rendering, one line per group and one per check (for the CLI and logs)."""
        out: list[str] = []
        for number, sentence in enumerate(self.sentences, start=1):
            out.append(f"sentence {number}: {sentence}")
        for g in self.groups:
            asked = f", {g.asked()}" if self.sentences else ""
            out.append(f"{OK_MARK if g.ok else FAIL_MARK} {g.who} -> {g.label} ({len(g.members)} agents{asked})")
            for c in g.checks:
                line = f"    {OK_MARK if c.ok else FAIL_MARK} {c.field}: asked {c.asked}, does {c.does}"
                if c.reason:
                    line += f" ({c.reason})"
                out.append(line)
        for correction in self.corrections:
            out.append(f"~ correction: {correction}")
        for u in self.unhonoured:
            out.append(f"{FAIL_MARK} not honoured: {u}")
        return out
