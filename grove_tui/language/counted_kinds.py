"""People said by a count and a plural noun no list names, whatever words say their kind between
("Thirty top-year juniors troop into the hall", "thirty-odd Brownies troop ...", "roughly two hundred
thrill-seekers are lined up at ...", "a pair of mall cops saunter through ..."): the parser's subject
of a verb, counted by a number or a "pair"/"trio"/"couple" of, and no place, thing or time word."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.dozen_kinds import counted_by_a_dozen, subject_of_an_untagged_going
from grove_tui.language.group_of_subjects import subject_through_a_group_of
from grove_tui.language.place_modifiers import names_a_place
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_GROUP_OF = frozenset("pair trio couple quartet handful dozen score".split())
_KIND_POS = ("ADJ", "NOUN", "PROPN", "PUNCT", "VERB")  # "top-year", "mall", "thrill-": the kind said between


def counted_plural_subject(s: Sentence, i: int) -> bool:
    """Whether the plural noun at i is a counted subject: "<count> <kind words> <noun> <verb>"."""
    word = s.w[i]
    if word.tag not in ("NNS", "NNPS") or not s.low[i].isalpha() or len(s.low[i]) < 4:
        return False
    lem = s.lemma(i)
    if lem in lx.NON_PLACES or lem in lx.NON_PEOPLE or lem in lx.DURATION_UNITS or lem in lx.ROBOT_WORDS \
            or lem in lx.HAZARD_NOUNS or lem in lx.BUILDING_WORDS or lem in lx.IMPLIED_RANGES \
            or names_a_place(s.index, lem) or s.index.knows(lem):
        return False
    if not _subject_of_a_verb(s, i):
        return False
    k = i - 1
    while k >= 0 and i - k <= 4 and s.w[k].pos in _KIND_POS and s.low[k] not in (",", ".", ";", ":") \
            and s.w[k].tag not in ("NNS", "NNPS") and not s.w[k].tag.startswith("VB") or (
            k >= 0 and s.w[k].tag == "VBN" and s.w[k].dep == "amod"):
        k -= 1
    if k < 0:
        return False
    if counted_by_a_dozen(s, k + 1, i):
        return True  # "a dozen ice hockey juniors clatter ...": "dozen" is a noun to the parser
    if s.low[k] == "odd" or (s.low[k] == "-" and k > 0 and s.w[k - 1].pos == "NUM"):
        k -= 1
        while k >= 0 and s.low[k] in ("-", "odd"):
            k -= 1
    if k >= 0 and s.w[k].pos == "NUM" and s.low[k] not in ("one", "1"):
        return True
    return k >= 1 and s.low[k] == "of" and s.lemma(k - 1) in _GROUP_OF


def _subject_of_a_verb(s: Sentence, i: int) -> bool:
    """The parser's subject of a verb that is not only a thing's, or a word before a plural verb the
    parser took for an adverb or noun ("mall cops saunter")."""
    word = s.w[i]
    if subject_through_a_group_of(s, i):
        return True  # "a couple of first-year sketchers put away ...": the couple is the parser's subject
    if word.dep in ("nsubj", "nsubjpass") and word.head != i and s.w[word.head].pos in ("VERB", "AUX"):
        head = word.head
        lined_up = head + 1 < s.n and s.low[head + 1] == "up"  # "are lined up at ...": a queue, no things
        return s.verb(head) not in lx.THING_VERBS or lined_up
    if subject_of_an_untagged_going(s, i):
        return True  # "a dozen ice hockey juniors clatter from ...": the verb read as a name
    if i + 1 < s.n:
        nxt = verb_lemma(s.low[i + 1])
        return nxt in lx.INTENT_VERBS or nxt in lx.HUMAN_SUBJECT_VERBS or nxt in lx.PEOPLE_GOING_VERBS
    return False
