"""Words before a person noun that say what kind of person, not how many, and person nouns made of
two words: "two team leaders", "a temp worker" (a noun, then a word people's compounds end with),
"seven night-shift workers", "three part-time cleaners" (a hyphenated modifier), "four year 6
pupils", "two grade 9 students" (a school year: its number is no count), and "the head" (a head
teacher or head of department) when a person's verb or "of" a department follows."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.counts import cohort_number, number_at

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# What "the head of ..." is no person of ("the head of the queue", "at the head of the table").
_HEAD_OF_THINGS = frozenset("queue line table stairs staircase corridor bed river valley column procession "
                            "hall room pier platform steps list page".split())
# Prefixes of a person noun written with a hyphen ("co-pilot", "ex-wife", "step-dad", "vice-captain").
_HYPHEN_PREFIXES = frozenset("co ex step vice sub".split())
# Words before "head" that make it a person ("the deputy head", "the new head").
_HEAD_TITLES = frozenset("the a deputy assistant acting new former school department our their".split())


def modifier_end(s: Sentence, k: int) -> int | None:
    """The word after a modifier of a person noun starting at k that names a kind, not a count: a
    school year ("year 6", "grade 9") or a hyphenated modifier ("night-shift", "part-time"), else
    None."""
    number = number_at(s, k + 1) if k + 2 < s.n and cohort_number(s, k + 1) else None
    if number is not None:
        return number[1]  # "year 6 pupils"
    if s.low[k] in _HYPHEN_PREFIXES and k + 2 < s.n and s.low[k + 1] == "-":
        return k + 2  # "his co-pilot", "her ex-husband": the tokenizer splits one noun in three
    if k + 3 < s.n and s.low[k + 1] == "-" and s.low[k].isalpha() and s.low[k + 2].isalpha() and \
            s.w[k + 3].pos in ("NOUN", "PROPN", "ADJ") and s.low[k] not in lx.ROBOT_WORDS and \
            not (s.lemma(k + 2) in lx.IMPLIED_RANGES and s.w[k].pos not in ("NOUN", "ADP") and
                 s.w[k + 3].tag != "NNS"):  # not "a first-class patient", but "four early-shift regulars"
        return k + 3  # "night-shift workers", "part-time cleaners", "off-shift porters"
    return None


def kind_word(s: Sentence, k: int) -> bool:
    """Whether word k is inside a modifier naming the kind of a person noun after it: a noun of a
    compound ("temp worker"), a hyphen or a word of a hyphenated modifier ("night-shift workers"),
    or a school year ("year 6 pupils")."""
    word = s.w[k]
    return (word.dep in ("compound", "amod") and k < word.head <= k + 3 and word.pos in ("NOUN", "PROPN")) or \
        (s.low[k] == "-" and 0 < k < s.n - 1) or cohort_number(s, k) or modifier_end(s, k) is not None


def compound_head_person(s: Sentence, i: int) -> bool:
    """Whether word i ends a compound of two nouns naming a person by a word people's compounds end
    with ("team leader", "temp worker", "shop keeper"): a person."""
    lem = s.lemma(i)
    return (i > 0 and lem in lx.COMPOUND_PERSON_HEADS and s.w[i].pos in ("NOUN", "PROPN")
            and s.w[i - 1].pos in ("NOUN", "PROPN", "ADJ") and s.w[i - 1].head == i
            and s.w[i - 1].dep in ("compound", "amod") and s.low[i - 1] not in lx.ROBOT_WORDS)


def head_person(s: Sentence, i: int) -> bool:
    """Whether "head" at word i is a person ("the head goes back to her office", "the head of
    department walks", "the deputy head waits"): a noun after a determiner or title, then the
    subject of a person's verb, or "of" a department, not of a queue or table."""
    if s.low[i] not in ("head", "heads") or s.w[i].pos not in ("NOUN", "PROPN") or i == 0 or \
            s.low[i - 1] not in _HEAD_TITLES:
        return False
    if i + 1 < s.n and s.low[i + 1] == "of":
        j = s.skip(i + 2, lx.DETERMINERS)
        return j < s.n and s.lemma(j) not in _HEAD_OF_THINGS and s.lemma(j) not in lx.IMPLIED_RANGES and \
            s.low[j] not in lx.ROBOT_WORDS and s.w[j].pos in ("NOUN", "PROPN")
    word = s.w[i]
    if word.dep != "nsubj" or word.head == i:
        return False
    verb = s.verb(word.head)
    return verb in lx.INTENT_VERBS or verb in lx.HUMAN_SUBJECT_VERBS or verb in lx.PEOPLE_GOING_VERBS
