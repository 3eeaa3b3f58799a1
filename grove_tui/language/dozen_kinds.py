"""A plural noun no list names, counted by "a dozen" or "a score" with no "of" and kind words between
("A dozen ice hockey juniors clatter to the gate", "a dozen cub scouts walk ...", "two dozen chess
juniors wait ..."): the count word is a noun to the parser, so the walk back over the kind words in
counted_kinds.py passes it and ends on the article. Here the words between are looked at again: a
"dozen"/"score" said after "a", "an", "half a" or a number, with only kind words after it."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

_COUNT_NOUNS = frozenset({"dozen", "score"})
_BEFORE = frozenset({"a", "an", "half"})


def counted_by_a_dozen(s: Sentence, first: int, i: int) -> bool:
    """Whether words first..i-1 (the kind words walked over before the plural at i) begin with a
    "dozen" or "score" counted by "a"/"an" or a number before it ("a dozen hockey juniors")."""
    for k in range(first, i - 1):
        if s.low[k] in _COUNT_NOUNS and k > 0 and (s.low[k - 1] in _BEFORE or s.w[k - 1].pos == "NUM"):
            return all(s.w[j].pos in ("NOUN", "PROPN", "ADJ") and s.w[j].tag not in ("NNS", "NNPS")
                       for j in range(k + 1, i))
    return False


# Prepositions of a way that follow a verb of going the parser took for a name ("juniors clatter from").
_WAY_WORDS = frozenset("from to into towards toward across through past along round around over onto out".split())


def subject_of_an_untagged_going(s: Sentence, i: int) -> bool:
    """Whether the plural at i is the subject of the word right after it that the parser made the
    a name or a noun ("juniors clatter from the café to the gate"), a way's preposition after it."""
    nxt = i + 1
    return nxt + 1 < s.n and s.w[nxt].pos in ("PROPN", "NOUN", "VERB") and s.low[nxt].isalpha() and \
        s.w[nxt].tag not in ("NNS", "NNPS") and not s.index.knows(s.lemma(nxt)) and s.low[nxt + 1] in _WAY_WORDS
