"""People placed by a participle of staying, then moved in the passive (round 65): "the forty
travellers waiting there are sent up the emergency stairs", "the diners sitting in the café are
ushered out through the side door". The parser takes the participle ("waiting") for the people's verb
and the passive for a place of waiting, so the group waits at the stairs. The participle only says
where they were: it is left out ("the forty travellers there are sent up ..."), and the passive reads
as the move it is (an evacuation when an alarm or hazard sends them, as for "the travellers there")."""

from __future__ import annotations

import re

_STAYING = r"(?:waiting|sitting|standing|queuing|queueing|lingering|loitering|milling\s+(?:about|around))"
_WHERE = r"(?:there|here|(?:on|in|at|by|inside|outside|near)\s+the\s+[\w'’-]+(?:\s+[\w'’-]+){0,3}?)"
_MOVED = (r"(?:are|is|get|gets|were|was|have\s+been|has\s+been)\s+(?:all\s+|quickly\s+|swiftly\s+|promptly\s+|"
          r"calmly\s+|then\s+|hastily\s+)?(?:sent|ushered|hurried|herded|shepherded|evacuated|bundled|marched|"
          r"rushed|shooed|hustled|steered|directed|guided|moved\s+on|led)\b")
_PLACED_THEN_SENT = re.compile(rf"\b{_STAYING}\s+({_WHERE})\s+(?={_MOVED})", re.I)


def without_staying_before_passive_moves(text: str) -> str:
    """The text with a staying participle before a passive move left out (module doc)."""
    return _PLACED_THEN_SENT.sub(lambda m: m.group(1) + " ", text)
