"""A member gone from the run who was not asked to leave: their claim is a ✗ that says so.

The simulation removes only those whose task is to leave (simulation/keep_inside.py); a bundle run
before that, or someone who still got out, has a `left_building` event. Whatever their claim (a wait,
a walk, a reaction), a longer run cannot bring them back, so a claim they had not yet made good is a
✗ with the reason, never "not checked". Claims about leaving (evacuate, leave) count the going out.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from grove_tui.scenario.events import SimEvent

LEAVING_CLAIMS = frozenset({"evacuate", "leave", "count", "start"})


def gone_reason(kind: str, member_ids: Sequence[int], events: Mapping[int, Sequence[SimEvent]]) -> str:
    """Why a claim of `kind` about these members cannot be made good any more ('' when none left the run)."""
    if kind in LEAVING_CLAIMS:
        return ""
    gone = [(e.t, i, e.detail) for i in member_ids for e in events.get(int(i), ()) if e.kind == "left_building"]
    if not gone:
        return ""
    t, i, door = min(gone)
    more = f" (and {len(gone) - 1} more)" if len(gone) > 1 else ""
    return (f"agent {i} was pushed out of the building{' through ' + door if door else ''} at t = {t:.1f} s{more}, "
            f"though not asked to leave: a longer run cannot bring them back")
