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

# generation.json's "grounding" entry and its parts as JSON holds them: to_dict writes them, from_dict reads them.
JsonDict = dict[str, Any]
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

    def to_dict(self) -> JsonDict:
        return {"field": self.field, "asked": self.asked, "does": self.does, "ok": self.ok, "reason": self.reason}

    @classmethod
    def from_dict(cls, data: JsonDict) -> GroundingCheck:
        return cls(str(data["field"]), str(data["asked"]), str(data["does"]), bool(data["ok"]),
                   str(data.get("reason", "")))


@dataclass(frozen=True)
class GroupGrounding:
    who: str  # the phrase of the sentence ("two families of three")
    label: str  # the group's label in the scenario
    checks: tuple[GroundingCheck, ...]
    members: tuple[int, ...] = ()  # agent ids of the group in the scenario

    @property
    def ok(self) -> bool:
        return all(c.ok for c in self.checks)

    def to_dict(self) -> JsonDict:
        return {"who": self.who, "label": self.label, "ok": self.ok, "members": list(self.members),
                "checks": [c.to_dict() for c in self.checks]}

    @classmethod
    def from_dict(cls, data: JsonDict) -> GroupGrounding:
        return cls(str(data["who"]), str(data["label"]), tuple(GroundingCheck.from_dict(c) for c in data["checks"]),
                   tuple(int(m) for m in data.get("members", ())))


@dataclass(frozen=True)
class GroundingReport:
    prompt: str
    groups: tuple[GroupGrounding, ...]
    unhonoured: tuple[str, ...] = ()  # parts of the sentence the scenario could not honour, said plainly
    repairs: tuple[str, ...] = field(default=())  # where the model's draft was repaired to match the sentence
    # Misspelt place words the reading put right ("read 'kitchn' as 'kitchen'"): honoured, but said,
    # so a user sees which place a typo was taken for. They do not make the report fail.
    corrections: tuple[str, ...] = field(default=())

    @property
    def ok(self) -> bool:
        return all(g.ok for g in self.groups) and not self.unhonoured

    def to_dict(self) -> JsonDict:
        return {"prompt": self.prompt, "ok": self.ok, "groups": [g.to_dict() for g in self.groups],
                "unhonoured": list(self.unhonoured), "repairs": list(self.repairs),
                "corrections": list(self.corrections)}

    @classmethod
    def from_dict(cls, data: JsonDict) -> GroundingReport:
        return cls(str(data.get("prompt", "")), tuple(GroupGrounding.from_dict(g) for g in data.get("groups", ())),
                   tuple(str(u) for u in data.get("unhonoured", ())), tuple(str(r) for r in data.get("repairs", ())),
                   tuple(str(c) for c in data.get("corrections", ())))

    def lines(self) -> list[str]:
        """Plain-text rendering, one line per group and one per check (for the CLI and logs)."""
        out: list[str] = []
        for g in self.groups:
            out.append(f"{OK_MARK if g.ok else FAIL_MARK} {g.who} -> {g.label} ({len(g.members)} agents)")
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
