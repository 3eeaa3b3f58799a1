"""The robot said with its owner (round 43): "our robot", "my robot", "the hotel's robot", "the
store’s little robot" is the robot all the same, the subject of its clause ("... while our robot does
laps of the rink"), not a word in some other phrase."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

_OWNERS = frozenset("our my your their".split())
_POSSESSIVE = frozenset({"'s", "’s", "'", "’"})


def owner_word(s: Sentence, k: int) -> bool:
    """Whether word k says whose the robot after it is: "our", "my", or the "'s" of "the hotel's"
    (the noun before it is read by the phrase itself)."""
    return s.low[k] in _OWNERS or (s.low[k] in _POSSESSIVE and k > 0 and s.w[k - 1].pos in ("NOUN", "PROPN"))
