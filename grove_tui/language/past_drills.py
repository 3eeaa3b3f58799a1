"""A drill that is over (round 34): "two recruits hose down the old cars after a drill", "the pupils walk
back to class after last week's fire drill", "Following the evacuation drill, the staff return to their
desks". A drill is a cue of evacuation; one said as past is no evacuation of this scene, only when
it happens, so the phrase is left out before the sentence is read. A drill said as now ("during a
fire drill everyone leaves", "the fire drill starts and the pupils file out") keeps its words."""

from __future__ import annotations

import re

_DRILL = (r"(?:(?:fire|evacuation|emergency|safety|alarm|practice|lockdown)[\s-]+)?"
          r"(?:drill|drills|practice|rehearsal|test)")
_PAST_OWNER = (r"(?:last\s+week['’]s|last\s+month['’]s|yesterday['’]s|this\s+morning['’]s|today['’]s|"
               r"the\s+morning['’]s|last\s+night['’]s|an?\s+earlier|the\s+earlier|the\s+last|the\s+previous|"
               r"a\s+previous|last\s+term['’]s)")
_DET = r"(?:a|an|the|their|its|his|her|our|this|that)"
# "after a drill", "following the fire drill", "since the drill": always over.
_AFTER = re.compile(rf"(,?\s*)\b(?:after|following|since)\s+(?:{_PAST_OWNER}|{_DET})\s+{_DRILL}\b(\s*,)?", re.IGNORECASE)
# "at last week's fire drill", "during yesterday's drill": over by the owner word.
_AT_PAST = re.compile(rf"(,?\s*)\b(?:at|in|during|from|for)\s+{_PAST_OWNER}\s+{_DRILL}\b(\s*,)?", re.IGNORECASE)


def _drop(m: re.Match[str]) -> str:
    rest = m.string[m.end():]
    return "" if not rest or not rest[0].isalnum() and not rest[0].isspace() else " "


def without_past_drills(text: str) -> str:
    """The text without a drill said as over (module doc)."""
    out = _AT_PAST.sub(_drop, _AFTER.sub(_drop, text))
    if out == text:
        return text
    return re.sub(r"\s{2,}", " ", out).strip()  # "After the drill, twenty pupils ...": "twenty pupils ..."
