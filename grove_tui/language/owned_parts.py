"""A counted part of someone's own people: "the professor and three of her doctoral students walk
...", "the manager and two of her interns ...", "a consultant with two of his juniors". A possessive
before the people ("her students") says whose they are, not that the rest of them are in the scene:
the part is a group of its own, of as many as said, and no whole of the possessed people is added
(as "two of the crew" adds none, language/collective_parts.py). A whole with a count of its own
("two of her six students") is still a whole the part comes out of."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

_POSSESSIVES = frozenset({"his", "her", "their", "my", "our", "your"})


def owned_whole_unsaid(s: Sentence, of_at: int, counted_whole: bool) -> bool:
    """Whether the whole of a part "N of his/her/their X" is left out of the scene (see the module doc)."""
    return not counted_whole and of_at + 1 < s.n and s.low[of_at + 1] in _POSSESSIVES
