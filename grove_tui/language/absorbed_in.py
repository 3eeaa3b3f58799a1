"""What someone is absorbed in is no place to refuse (round 69): "three stroke survivors are glued to
the racing", "two porters engrossed in the snooker", "a lad absorbed in his comic", "a pair hooked on the
darts". After a word of rapt attention and its preposition, the phrase is what holds them (a programme,
a game, a book), not a place the world lacks; a place the world has ("glued to the wallboard") is still
read as usual by the caller."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# A word of rapt attention and the prepositions it takes ("glued to", "engrossed in", "hooked on").
_ABSORBED = {"glued": ("to",), "riveted": ("to",), "transfixed": ("by",), "engrossed": ("in", "by"),
             "absorbed": ("in", "by"), "immersed": ("in",), "wrapped": ("in",), "hooked": ("on",),
             "gripped": ("by",), "enthralled": ("by",), "captivated": ("by",), "mesmerised": ("by",),
             "mesmerized": ("by",)}
_BETWEEN = frozenset("completely totally utterly fully quite so still firmly well and truly up".split())


def absorbed_in(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether the preposition at `at` follows a word of rapt attention (module doc)."""
    if at < 1 or k >= s.n:
        return False
    x = at - 1
    while x > 0 and s.low[x] in _BETWEEN and s.low[x] not in _ABSORBED:
        x -= 1
    said = s.low[x]
    return said in _ABSORBED and s.low[at] in _ABSORBED[said]
