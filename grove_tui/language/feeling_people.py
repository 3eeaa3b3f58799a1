"""One person told by how they feel about the robot (round 24): "a new agency loader on van bay A
is scared of the robot", "a nervous temp at the packing bench is frightened of it". A singular noun
after a determiner and its modifiers, with at most a place phrase before "is"/"was"/"seems" and a
feeling only people have of the robot, is a person whatever noun names them (a word no list has, or
one the world's rooms use: "loader" of "loading bay"). So too with the feeling said in an aside before
the verb (round 44: "a beginner on the slab, spooked by the robot, shrinks back against the wall")."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

_DETERMINERS = frozenset("a an the one our my their his her your this that".split())
_BE = frozenset("is was seems looks gets feels appears becomes remains stays".split())
_PLACE_WORDS = 7  # at most this many words of a place phrase between the person and "is"


def feels_about_the_robot(s: Sentence, i: int) -> bool:
    """Whether the noun at i is the one who feels something of the robot ("a temp ... is scared of it")."""
    lem = s.lemma(i)
    if s.w[i].pos not in ("NOUN", "PROPN") or lem != s.low[i] or lem in lx.ROBOT_WORDS or lem in lx.NON_PEOPLE:
        return False
    k = i - 1
    while k >= 0 and i - k <= 4 and s.low[k] not in _DETERMINERS and s.w[k].pos in ("ADJ", "NOUN", "PROPN"):
        k -= 1
    if k < 0 or s.low[k] not in _DETERMINERS:
        return False
    j = i + 1
    if j < s.n and s.low[j] in lx.PLACE_PREPOSITIONS:
        j = next((x for x in range(j + 1, min(s.n, j + _PLACE_WORDS + 1)) if s.low[x] in _BE or s.is_verb(x)
                  or s.is_punct(x)), s.n)
    if j + 1 < s.n and s.low[j] == "," and s.low[j + 1] in lx.ROBOT_FEELINGS:
        return _aside_then_verb(s, j + 1)  # "a beginner on the slab, spooked by the robot, shrinks back"
    if j >= s.n or s.low[j] not in _BE:
        return False
    j += 1
    while j < s.n and s.w[j].pos == "ADV":
        j += 1  # "is really scared", "seems a bit nervous" reads to its feeling
    return j < s.n and s.low[j] in lx.ROBOT_FEELINGS and any(
        s.low[x] in lx.ROBOT_WORDS or s.low[x] == "it" for x in range(j + 1, min(s.n, j + 5)))


def _aside_then_verb(s: Sentence, f: int) -> bool:
    """Whether the feeling at f is an aside about the robot between commas, a verb right after it
    ("..., spooked by the robot, shrinks back", "..., wary of it, edges away")."""
    end = next((x for x in range(f + 1, min(s.n, f + 6)) if s.low[x] == ","), None)
    if end is None or end + 1 >= s.n or not any(s.low[x] in lx.ROBOT_WORDS or s.low[x] == "it" for x in range(f + 1, end)):
        return False
    return s.is_verb(end + 1) or s.w[end + 1].tag in ("VBZ", "VBD", "VBP", "NNS")
