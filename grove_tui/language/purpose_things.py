"""The things a purpose gets, as a list: "to buy plasters and paracetamol", "to buy paracetamol, plasters
and a tube of cream". A purpose's phrase ends at its first comma or "and" (language/sentence.py), which
would leave the rest of the list to be read as another clause; the list runs on through items that are
each a thing (a noun the world does not call a place, and no person), up to an item after "and" or "or"
that closes it (the sentence's end, a comma or a place preposition). Read for Sentence.phrase_end."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# Words that join the items of a list.
_LINKS = frozenset({",", "and", "or"})
# Words an item is made of besides its nouns: "a tube of cream", "some fresh bread".
_INSIDE = frozenset({"of"})
# At most this many words to an item ("a small tube of antiseptic cream").
_ITEM_WORDS = 6


def things_end(s: Sentence, j: int) -> int:
    """Where the list of things that starts at word j (a link after the purpose's first thing) ends: past
    its last item, when one after "and"/"or" closes it; j when no list of things starts there."""
    k = j
    while k < s.n and s.low[k] in _LINKS:
        last = any(s.low[x] in ("and", "or") for x in range(k, s.skip(k, _LINKS)))
        k = s.skip(k, _LINKS)
        item = _item_end(s, k)
        if item == k:
            return j
        if last:
            return item if item >= s.n or (s.is_punct(item) and not s.joins(item)) or \
                s.low[item] in lx.PLACE_PREPOSITIONS else j
        k = item
    return j


def _item_end(s: Sentence, k: int) -> int:
    """The end of one thing of a list starting at word k; k when the words there are no thing (a person,
    a place of the world, a clause of its own: "and three nurses walk")."""
    x = k
    while x < s.n and x < k + _ITEM_WORDS and not s.is_punct(x) and s.low[x] not in _LINKS and \
            s.low[x] not in lx.CLAUSE_STARTERS and (s.low[x] in _INSIDE or s.low[x] not in lx.PLACE_PREPOSITIONS):
        if s.w[x].pos in ("VERB", "AUX", "PRON", "ADV") and s.w[x].tag not in ("NN", "NNS"):
            return k
        x += 1
    head = x - 1
    if head < k or s.w[head].pos not in ("NOUN", "PROPN") or s.lemma(head) in lx.PERSON_NOUNS or \
            s.low[head] in lx.PERSON_NOUNS or s.index.knows(s.lemma(head)):
        return k
    return x
