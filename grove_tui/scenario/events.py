"""The simulation's event log (`events.jsonl` in a bundle): queue joins and services, evacuations, goals."""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from grove_tui.errors import EventLogError
from grove_tui.files import write_text_atomic
from grove_tui.limits import InputLimitError, read_text_bounded

EVENTS_FILE = "events.jsonl"
# A long crowded run logs a few events per person: 64 MB is hundreds of thousands of them.
MAX_EVENTS_BYTES = 64 * 1024 * 1024


@dataclass(frozen=True)
class SimEvent:
    """Something the simulation observed: queue joins/services, evacuations, goals reached."""

    t: float
    agent_id: int
    # "queue_join", "queue_advance", "queue_served", "evacuated", "left_building" (pushed outside, not
    # evacuating), "kept_in" (pushed over an exit's door line, not leaving: held back in, once per person), "goal_reached", "conversation_start" (detail: the ids in the circle, "3,4,5"),
    # "conversation_end", "robot_reaction" (detail: the reaction node), "tree_error"
    kind: str
    detail: str = ""  # queue name for queue events, exit for evacuations


def write_events(path: str | Path, events: Sequence[SimEvent]) -> Path:
    """The simulation's event log as JSON lines (t, agent_id, kind, detail), written atomically."""
    lines = [json.dumps({"t": round(e.t, 4), "agent_id": e.agent_id, "kind": e.kind, "detail": e.detail})
             for e in events]
    return write_text_atomic(path, "\n".join(lines) + ("\n" if lines else ""))


def read_events(path: str | Path) -> list[SimEvent]:
    path = Path(path)
    events = []
    try:
        # A regular file of bounded size: events.jsonl linked to /dev/zero or made a pipe once read forever.
        text = read_text_bounded(path, MAX_EVENTS_BYTES, "event log")
    except InputLimitError as exc:
        raise EventLogError(str(exc)) from None
    for number, line in enumerate(text.splitlines(), start=1):
        if not line.strip():
            continue
        try:
            data = json.loads(line)
            events.append(SimEvent(float(data["t"]), int(data["agent_id"]), str(data["kind"]),
                                   str(data.get("detail", ""))))
        except (ValueError, KeyError, TypeError) as exc:
            raise EventLogError(f"{path}:{number}: not an event record: {exc}") from None
    return events
