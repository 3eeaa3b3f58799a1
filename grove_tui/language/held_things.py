"""A load of things is no person (round 27): "a zookeeper lugs a heavy sack of pellets from the
penguin pool to the aquariums", "a porter wheels a stack of suitcases to the lifts", "a cleaner
pushes a trolley of towels". A singular noun no list keeps for people, followed by "of" and a
plural or mass noun that is no person either, is a quantity of things, however the parser takes
the verb before it ("lugs" read a plural noun leaves "sack" the sentence's subject)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# Words before "of" that name people ("the head of security", "a member of staff", "the friend of a
# patient"): a person, whatever follows.
_PEOPLE_OF = frozenset("head chief member friend director manager captain officer leader mother father son "
                       "daughter wife husband one rest most some many none few all each".split())


def _person_word(s: Sentence, k: int) -> bool:
    return s.lemma(k) in lx.PERSON_NOUNS or s.low[k] in lx.PERSON_NOUNS


def a_load_of_things(s: Sentence, i: int) -> bool:
    """Whether word i is a singular noun that holds things: "a sack of pellets", "a crate of fish"."""
    w = s.w[i]
    if w.tag != "NN" or i + 2 >= s.n or s.low[i + 1] != "of" or not s.low[i].isalpha() or \
            _person_word(s, i) or s.lemma(i) in _PEOPLE_OF or s.low[i].endswith(lx.STRONG_AGENT_SUFFIXES) or \
            s.lemma(i) in lx.TOGETHER_COLLECTIVES | lx.QUEUE_COLLECTIVES | lx.QUANTIFYING_COLLECTIVES:
        return False
    if i == 0 or s.low[i - 1] not in ("a", "an") and s.w[i - 1].pos != "ADJ":
        return False  # "a sack of", "a heavy sack of"
    things = [k for k in range(i + 2, min(i + 5, s.n)) if s.w[k].head == i + 1 and s.w[k].dep == "pobj"]
    if not things:
        return False
    k = things[0]
    return s.w[k].tag in ("NNS", "NN") and s.low[k].isalpha() and not _person_word(s, k) and \
        not any(_person_word(s, j) for j in range(i + 2, k))
