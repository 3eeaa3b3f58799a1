"""A place that says who people are gives way to where the clause says they set out (round 69): "forty
tourists off the coaches stream from the coach park to the arcade" start in the coach park, not at the
coach bays ("the coaches" an alias of the bays): "off the coaches" before the verb tells which tourists,
"from the coach park" after it is where they leave. Said alone ("tourists off the coaches walk to the
arcade") the place before the verb is still the start (roles.py)."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.place_phrases import Place


def start_said_after(current: Place | None, later: Place, verb_index: int | None) -> bool:
    """Whether `later`, a start said with "from"/"out of" after the verb, replaces `current`, a start said
    with "off" before it."""
    return current is not None and verb_index is not None and current.prep == "off" and \
        current.index < verb_index < later.index and later.prep == "from"
