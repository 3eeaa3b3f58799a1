"""Whoever shuts a place so that others are moved off it (round 33): "Police shut platform two over an
unattended holdall and the hundred-odd travellers on it are moved off", "staff close the café and the
twenty people in it are cleared out". The ones who close the place only set the scene: the people
moved (in the passive) are the group, and the closers are none."""

from __future__ import annotations

import re
from collections.abc import Sequence

from grove_tui.language.mention import Mention
from grove_tui.language.sentence import Sentence

# Verbs of shutting a place, in the forms a closer uses ("police shut", "staff have closed", "seal off").
_CLOSING = frozenset(f"{v}{end}" for v in ("close", "cordon", "seal", "lock", "clos") for end in ("", "s", "d", "ed"))\
    | frozenset("shut shuts shutting closing sealing cordoning".split())
_BEFORE_VERB = frozenset("have has had quickly swiftly promptly then immediately hurriedly just soon also".split())
# The people after it moved in the passive ("are moved off", "get cleared out", "are evacuated from it").
_MOVED = re.compile(r"\b(?:is|are|was|were|get|gets|got|being|be)\s+(?:\w+\s+)?"
                    r"(?:moved|cleared|evacuated|ushered|hustled|shepherded|herded|shooed|led|taken|sent|asked|told|"
                    r"escorted|directed|turfed|kicked|marched|guided|walked)\b", re.I)

# How the people moved off are said: as those already there ("the sixty passengers on it", "everyone").
_KNOWN = frozenset("the all everyone everybody those any".split())
_AT_THE_SAME_TIME = frozenset("while whilst as meanwhile when".split())


def _closes(s: Sentence, m: Mention) -> bool:
    v = s.skip(m.last + 1, _BEFORE_VERB)
    return v + 1 < s.n and s.low[v] in _CLOSING and s.w[v].sentence == s.w[m.first].sentence


def without_closers(s: Sentence, mentions: Sequence[Mention]) -> list[Mention]:
    """The mentions but one that only shuts the place the people said after it are moved off."""
    if len(mentions) < 2 or any(m.relation is not None for m in mentions):
        return list(mentions)
    first, after = mentions[0], mentions[1]
    if not _closes(s, first) or s.w[after.first].sentence != s.w[first.first].sentence or \
            s.low[after.first] not in _KNOWN or any(s.low[k] in _AT_THE_SAME_TIME for k in range(first.last, after.first)):
        return list(mentions)  # "a guard locks the pharmacy while two nurses are sent ...": both are there
    rest = s.prompt[s.w[after.last].end:]
    cut = re.search(r"[.;!?]|\bwhile\b|\bmeanwhile\b", rest)
    return list(mentions[1:]) if _MOVED.search(rest[:cut.start()] if cut else rest) else list(mentions)
