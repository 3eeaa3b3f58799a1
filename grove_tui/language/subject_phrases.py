"""One person's verb after a phrase about them (round 23): "A timid lad beside cashpoint 1 cowers from
the robot", "Jenny from accounts nips over to the coffee corner", "Minutes before the ceremony, Cllr Begum
hurries from ...". The small parser reads the "-s" verb as a plural noun, and the words between the
person and it (a place with a number, a department in the plural, a fronted time) keep the rule of
`singular_verbs` from firing. Read by shape instead: within its clause (after the last comma), a singular
noun phrase opened by "a", "an", "the", a possessive or a name, then only prepositional phrases (or none), then
the "-s" word the lexicon knows as a verb, followed by a preposition, an adverb or the end: that word is
the phrase's verb and the phrase's last noun its one subject."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.fronted_words import fronted_only
from grove_tui.language.parser import Word, known_word
from grove_tui.language.tokens import verb_lemma

_OPENERS = frozenset({"a", "an", "the", "this", "that", "my", "our", "your", "his", "her", "their", "one"})
_PREPOSITIONS = lx.PLACE_PREPOSITIONS | frozenset({"of", "for", "with", "behind", "opposite"})
_HEAD_POS = frozenset({"DET", "ADJ", "NOUN", "PROPN"})
_PHRASE_POS = frozenset({"DET", "ADJ", "NOUN", "PROPN", "NUM", "ADP", "PART"})
_AFTER = frozenset({"ADP", "ADV", "PART", "PUNCT", "SCONJ", "CCONJ", "DET"})
_CLAUSE_BREAKS = frozenset({",", ";", ":", "—", "-"})


def _verb_s(w: Word) -> bool:
    low = w.lower
    return w.pos == "NOUN" and w.tag == "NNS" and low.isalpha() and len(low) > 3 and low.endswith("s") and \
        not low.endswith(("ss", "us", "is")) and verb_lemma(low) != low


def subject_before(words: list[Word], k: int) -> int | None:
    """The index of the one person whose verb is the "-s" word at k (module doc), or None."""
    w = words[k]
    nxt = words[k + 1] if k + 1 < len(words) and words[k + 1].sentence == w.sentence else None
    if not _verb_s(w) or (nxt is not None and nxt.pos not in _AFTER):
        return None
    first = k
    while first > 0 and words[first - 1].sentence == w.sentence and words[first - 1].lower not in _CLAUSE_BREAKS:
        first -= 1
    head_end = next((x for x in range(first, k) if words[x].lower in _PREPOSITIONS), k)
    head = words[first:head_end]
    if not head or any(x.pos not in _HEAD_POS and x.tag != "POS" for x in head):
        return None
    if head[0].pos == "DET" and head[0].lower not in _OPENERS:
        return None  # "every clerk", "some porter": not one person said outright
    if head[-1].tag not in ("NN", "NNP") or any(x.tag in ("NNS", "NNPS") for x in head):
        return None
    if any(x.pos not in _PHRASE_POS or x.lower in ("and", "or") for x in words[head_end:k]):
        return None  # a verb or a list between
    return head_end - 1


def with_the_subject(words: list[Word], k: int, subject: int) -> list[Word]:
    """The parse with the word at k the verb of the person at `subject`."""
    out = list(words)
    w = words[k]
    base = verb_lemma(w.lower)
    for j, x in enumerate(out):
        if j != k and x.sentence == w.sentence and x.dep == "ROOT":
            out[j] = replace(x, dep="dep", head=k)
        elif x.head == k and j < k and j != subject:
            out[j] = replace(x, head=subject)
    for j in range(subject + 1, k):
        if out[j].lower in _PREPOSITIONS and out[j].pos != "ADP":  # "beside" taken for a noun
            out[j] = replace(out[j], pos="ADP", tag="IN", dep="prep", head=subject)
    out[k] = replace(w, pos="VERB", tag="VBZ", lemma=base, dep="ROOT", head=k)
    out[subject] = replace(out[subject], dep="nsubj", head=k)
    return out


_NOT_SUBJECT_DEPS = frozenset({"compound", "npadvmod"})


def subjects_of_subjectless_verbs(words: list[Word]) -> list[Word]:
    """The parse with the name or noun before a verb that has no subject made its subject, when the
    parser hung it on the verb as a modifier no verb takes ("Dave scoots across", a compound; "Tom from
    sales pops over", a noun of measure): nouns are compounds of nouns, and a bare name opening a clause
    is not how long or how much."""
    out = list(words)
    for k, w in enumerate(words):
        if w.dep not in _NOT_SUBJECT_DEPS or w.tag not in ("NN", "NNP") or w.head <= k:
            continue
        verb = words[w.head]
        if verb.pos != "VERB" or not verb.tag.startswith("VB") or verb.sentence != w.sentence or \
                any(x.dep in ("nsubj", "nsubjpass") and x.head == w.head for x in words):
            continue
        between = words[k + 1:w.head]
        if any(x.pos in ("VERB", "AUX") or x.lower in (",", "and", "or") for x in between):
            continue
        if k > 0 and words[k - 1].sentence == w.sentence and words[k - 1].pos not in ("DET", "ADJ", "PUNCT", "PROPN") \
                and words[k - 1].lower not in ("and", "while", "as", "then"):
            continue  # "minutes before ...": words before it that are not its own
        out[k] = replace(w, dep="nsubj")
    return out


_NAME_VERB_AFTER = frozenset({"ADP", "ADV", "PART", "PUNCT", "SCONJ", "CCONJ"})
# Words after the verb the parser may call verbs themselves ("potters round the food court").
_PARTICLES = frozenset("round around about over up down off out in back along across".split())


def _a_name(words: list[Word], j: int) -> bool:
    """Whether word j reads as a person's name: capitalised, no plural, not opened by "the" or "a", and
    either inside the sentence (where only names are capitalised) or no English word ("Ines")."""
    w = words[j]
    if not (w.text[:1].isupper() and w.text[1:].islower() and w.text.isalpha()):
        return False
    starts = j == 0 or words[j - 1].sentence != w.sentence
    if w.tag in ("NNS", "NNPS") and not (starts and not known_word(w.lower)):
        return False  # a plural, but "Ines", "Agnes": a name the parser took for one
    if j > 0 and words[j - 1].sentence == w.sentence and words[j - 1].lower in ("the", "a", "an"):
        return False  # "the Costa seats", "a Boots bag": a shop's name
    return not starts or not known_word(w.lower)


def verbs_after_names(words: list[Word]) -> list[Word]:
    """The parse with an "-s" word right after a person's name, followed by a preposition, an adverb or
    the end, read as the name's verb ("Little Timmy bolts from the toy shop", "Grandma Rose potters
    round the food court", "Ines sketches by the skeleton", "our intern Bella dawdles by the printer"):
    the parser makes a plural noun of the name and the word ("Rose potters"), and a name does not
    head a plural."""
    out = list(words)
    for k, w in enumerate(words):
        nxt = words[k + 1] if k + 1 < len(words) and words[k + 1].sentence == w.sentence else None
        low = w.lower
        if k == 0 or w.tag != "NNS" or not low.isalpha() or not low.endswith("s") or low.endswith(("ss", "us", "is")) \
                or w.text[:1].isupper() or (nxt is not None and nxt.pos not in _NAME_VERB_AFTER and
                                            nxt.lower not in _PARTICLES) or \
                not _a_name(words, k - 1):
            continue
        if any(x.pos in ("VERB", "AUX") and x.sentence == w.sentence for x in out[:k]) and not fronted_only(out, k):
            continue  # a verb before it: "Tom meets Sue's parents at the door"
        base = verb_lemma(low)
        if base == low:
            base = low[:-2] if low.endswith(("ches", "shes", "sses", "xes")) else low[:-1]
        for j, x in enumerate(out):
            if j != k and x.sentence == w.sentence and x.dep == "ROOT":
                out[j] = replace(x, dep="dep", head=k)
        out[k] = replace(w, pos="VERB", tag="VBZ", lemma=base, dep="ROOT", head=k)
        out[k - 1] = replace(out[k - 1], pos="PROPN", tag="NNP", dep="nsubj", head=k)
        if nxt is not None and nxt.lower in _PARTICLES and nxt.pos == "VERB":
            out[k + 1] = replace(out[k + 1], pos="ADP", tag="IN", dep="prep", head=k)
    for k, w in enumerate(out):  # "Little Timmy bolts": a name the parser tagged an adjective
        if k > 0 and w.dep == "nsubj" and w.tag in ("JJ", "NN") and _a_name(out, k) and out[w.head].tag == "VBZ":
            out[k] = replace(w, pos="PROPN", tag="NNP")
    return out


# Words that are only ever prepositions, which the small parser sometimes tags nouns ("a lad beside gate B1").
_ONLY_PREPOSITIONS = frozenset("beside towards toward into onto via beneath alongside amid amongst among".split())


def prepositions_as_such(words: list[Word]) -> list[Word]:
    """The parse with a word that is only ever a preposition, tagged a noun, tagged a preposition; its
    phrase hangs on the word before it."""
    out = list(words)
    for k, w in enumerate(words):
        if k > 0 and w.lower in _ONLY_PREPOSITIONS and w.pos != "ADP" and words[k - 1].sentence == w.sentence:
            out[k] = replace(w, pos="ADP", tag="IN", dep="prep", head=k - 1)
    return out
