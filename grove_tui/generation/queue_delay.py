"""A wait before a queue: "wait by the kiosk for a minute, then join the queue at the ticket office",
"sit in the waiting room for five minutes before queuing at reception".

The reader marks such a group (`waits_first`): its intent is the queue, its seconds are the wait where
it starts. The tree waits those seconds there, then queues; the report claims the wait at the start and
counts only joins made after it. "Queue at the pharmacy for ten minutes" keeps queuing at once (a
queue's own length is set by its service).
"""

from __future__ import annotations

from grove_tui.language.reading import GroupReading


def wait_before_queuing(group: GroupReading, service: str) -> float | None:
    """The seconds the group waits where it starts before it queues at `service`, or None."""
    if not group.waits_first or not group.wait_seconds or group.start == service:
        return None
    return float(group.wait_seconds)
