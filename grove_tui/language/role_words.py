"""Words for one person that no list of person nouns can hold in full: a role said by its
abbreviation ("the GP", "our SENCO", "a PCSO", "the TA": an all-capital short word after a
determiner, with the person's verb after it), a short colloquial role ("the vet", "the doc"), and a
substantivised superlative or age word standing for a member of a family ("our youngest", "the
eldest", "the little one", "their middle one"). Each is a person only where a noun would stand:
after a determiner or possessive and before its verb, so "the GP surgery" or "the eldest child"
keep their own heads."""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol

from grove_tui.language import lexicon as lx
from grove_tui.language.counts import number_at
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

class _People(Protocol):
    def is_person_noun(self, i: int) -> bool: ...

    def person_head(self, j: int, *, counted: bool) -> int | None: ...


_DETERMINERS = frozenset({"the", "a", "an", "our", "their", "his", "her", "my", "your", "another", "one", "this", "that",
                          "'s", "’s"})  # "the bride's youngest"
# Short roles typed in lower case as often as not (an abbreviation's capitals are no help there).
SHORT_ROLES = frozenset("gp vet doc ref hca pcso senco ta ceo cfo cto mp dj mc medic paramedic sen lsa reverend rev "
                        "padre".split())
# Abbreviations in capitals that name no person: units, times, things, places.
_NOT_PEOPLE = frozenset("AM PM OK TV PC IT AI UK US EU ID DNA ATM CCTV ICU ENT AE GPS USB VIP WC PE RE PIN SOS "
                        "HQ CT MRI ECG ER OR ED CPR".split())
# Words of age or birth order that stand for a child or sibling of a family after a possessive or "the".
_FAMILY_ORDER = frozenset("youngest eldest oldest middle".split())
_LITTLE_ONES = frozenset("little young wee youngest eldest oldest middle baby older younger elder big".split())
_MAX_SIBLINGS = 6  # "the older two", "the youngest three": children of one family, not a crowd
_MAX_LETTERS = 5
# What an unknown capital word does when it is a vehicle or a machine ("the AGV drives", "the PA announces").
_MACHINE_VERBS = frozenset("drive reverse park beep honk stall announce crackle break idle load unload tow "
                           "dock charge".split())
# Plurals of adjectives said as one person ("a regular", adjective_people.py) that are nouns by themselves.
_ADJECTIVE_PLURALS = frozenset("regulars locals natives".split())


def _verb_follows(s: Sentence, i: int) -> bool:
    """Whether the word after i is a verb of the phrase's person (tagged or known by its form)."""
    if i + 1 >= s.n:
        return False
    nxt = s.w[i + 1]
    return nxt.pos in ("VERB", "AUX") or nxt.tag in ("VBZ", "VBP", "VBD", "MD") or \
        (s.low[i + 1].endswith("s") and (verb_lemma(s.low[i + 1]) in lx.INTENT_VERBS or verb_lemma(s.low[i + 1]) in lx.HUMAN_SUBJECT_VERBS)) or \
        s.low[i + 1] in ("and", ",", "who") or (s.low[i + 1].endswith("s") and nxt.dep == "ROOT") or \
        (verb_lemma(s.low[i + 1]) in lx.INTENT_VERBS and nxt.dep == "ROOT")  # "her PA walk": the small model's noun


# Words that count the people of an "of" after them ("a pair of RGNs", "a team of PCSOs").
_COUNTING_OF = frozenset("pair couple trio quartet handful group team bunch dozen few".split())


def abbreviated_role(s: Sentence, i: int) -> bool:
    """Whether word i is a role said short ("the GP waits", "a PCSO walks", "the vet heads out"); round 45:
    also in the plural after a word that counts people ("a pair of RGNs at the trolley"), verb or none."""
    if i >= 2 and s.low[i - 1] == "of" and s.low[i - 2] in _COUNTING_OF and abbreviation_label(s, i) is not None:
        return True
    first = i
    while first > 1 and s.w[first - 1].head == i and s.w[first - 1].dep in ("compound", "amod") and \
            s.w[first - 1].pos in ("NOUN", "ADJ"):
        first -= 1  # "a locum GP loiters", "the duty PCSO walks"
    opened = first > 0 and s.low[first - 1] in _DETERMINERS
    if not opened and not (s.low[i] in SHORT_ROLES and first == i and (i == 0 or s.low[i - 1] in (",", ";"))):
        return False  # a short role typed bare only at the start of chat ("hca hangs on 5 mins @ ...")
    text = s.w[i].text
    capitals = text.isalpha() and text.isupper() and 2 <= len(text) <= _MAX_LETTERS and text not in _NOT_PEOPLE
    if not (capitals or s.low[i] in SHORT_ROLES):
        return False
    if s.index.knows(s.low[i]) and not capitals:
        return False  # a world naming a place "the vet" keeps it a place
    verbs = {verb_lemma(s.low[i + 1]), s.lemma(i + 1), s.low[i + 1].removesuffix("s")} if i + 1 < s.n else set()
    if s.low[i] not in SHORT_ROLES and any(v in _MACHINE_VERBS or v in lx.SOUND_LIGHT_VERBS or v in lx.THING_VERBS
                                           for v in verbs):
        return False  # "the AGV drives to the bay", "an HGV reverses", "the PA announces a delay": a machine
    return _verb_follows(s, i)


def plural_adjective_people(s: Sentence, i: int) -> bool:
    """Whether word i is the plural of an adjective said as a person ("regulars", "locals"): a
    plural noun is a person with or without a determiner ("spin class regulars")."""
    return s.low[i] in _ADJECTIVE_PLURALS and s.w[i].pos in ("NOUN", "PROPN")


def family_member(s: Sentence, i: int) -> bool:
    """Whether word i stands for one member of a family: "our youngest", "the eldest", "the little
    one", "their middle one" (the person's verb after it)."""
    if i == 0:
        return False
    word = s.low[i]
    if word in _FAMILY_ORDER:
        return s.low[i - 1] in _DETERMINERS and _verb_follows(s, i)
    if (word == "one" or family_size(s, i) > 1) and s.low[i - 1] in _LITTLE_ONES and i >= 2 and \
            s.low[i - 2] in _DETERMINERS:
        return _verb_follows(s, i)  # "the little one", "the eldest two", "the older three"
    return False


def family_size(s: Sentence, i: int) -> int:
    """How many the family word at i says: 2 for "the eldest two", else 1."""
    said = number_at(s, i)
    n = said[0] if said is not None and said[1] == i + 1 else None
    return n if n is not None and 1 < n <= _MAX_SIBLINGS and i > 0 and s.low[i - 1] in _LITTLE_ONES else 1


def world_person_name(s: Sentence, title: int, j: int) -> bool:
    """Whether words title..j say a person the world names a place after ("Mrs Okafor" of "Mrs
    Okafor's room"): a name, though its word is a place's word too."""
    said = tuple(s.low[title:j + 1])
    # The index keeps its phrases' lemmas, and a surname ending in "s" has a plural's ("Dr Hughes's
    # room" is kept as "dr hughe room"): the name is compared as said and as lemmas.
    lemmas = tuple(s.lemma(k) for k in range(title, j + 1))
    n = len(said)
    return any(phrase[x:x + n] in (said, lemmas) for e in s.index.entries for phrase in e.phrases
               for x in range(len(phrase) - n + 1))


def _kind_word(s: Sentence, j: int) -> bool:
    """Whether the word at j only says what kind the noun after it is: a compound noun or a number
    ("art class", "Year 9 group"), or a piece of a hyphened word ("A-level")."""
    w = s.w[j]
    return w.tag == "HYPH" or (j + 1 < s.n and s.w[j + 1].tag == "HYPH") or (
        w.dep in ("compound", "nummod", "amod") and w.head > j and w.pos in ("NOUN", "PROPN", "NUM", "DET", "ADJ"))


def possessor_of_a_person(s: Sentence, is_person: Callable[[int], bool], head: int) -> bool:
    """Whether the name ending at `head` only owns the person said next ("Mrs Okafor's daughter",
    "Dr Patel's registrar"): the daughter is the group, her mother no one said to be there."""
    if head + 2 >= s.n or s.low[head + 1] not in ("'s", "’s", "'"):
        return False
    j = head + 2
    while j < s.n and j < head + 6 and not is_person(j) and (s.w[j].pos == "ADJ" or _kind_word(s, j)):
        j += 1  # "Mr Reid's elderly sister", "Mrs Lee's A-level group", "Mr Shah's art class"
    return j < s.n and is_person(j)


def abbreviation_label(s: Sentence, i: int) -> str | None:
    """The label of a role said short and in the plural ("TAs", "PCSOs": ta, pcso), else None."""
    text = s.w[i].text
    if len(text) >= 3 and text[-1] == "s" and text[:-1].isalpha() and text[:-1].isupper() and \
            len(text) - 1 <= _MAX_LETTERS and text[:-1] not in _NOT_PEOPLE:
        return text[:-1].lower()
    return None


def person_of_a_person(s: Sentence, people: _People, at: int) -> bool:
    """Whether the phrase at `at`, after a person's "'s", is another person who is the subject ("the
    nurse's elderly mother waits", "Mr Reid's sister walks"): a group, its owner none."""
    if at < 2 or not people.is_person_noun(at - 2):
        return False
    head = people.person_head(at, counted=False)
    return head is not None and head < at + 3 and (s.w[head].dep in ("nsubj", "nsubjpass") or _verb_follows(s, head))
