"""Verbs the small parser takes for plural nouns after one person (round 19): "a new hire heads over
from the lobby", "a care assistant ambles over to the lounge", "counsel for the claimant heads to
court 2", "Sam, our toddler, waddles after the robot". Read as nouns, "hire heads" is a crowd of
heads and the person is lost; read by its place, an "-s" word right after a singular noun phrase
(opened by "a", "an", "one", "the", a possessive or a name, with no verb before it in its sentence)
and followed by a preposition, an adverb, a determiner, a name, a number or the end is the phrase's
verb, and the phrase is its one subject."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from grove_tui.language.and_verbs import as_second_verbs
from grove_tui.language.counted_verbs import as_counted_verbs
from grove_tui.language.listed_verbs import as_listed_verbs
from grove_tui.language.object_verbs import as_object_verbs
from grove_tui.language.order_fronts import without_order_words
from grove_tui.language.counted_modifiers import as_counted_modifiers, as_plural_verbs_before_a_clause
from grove_tui.language.gathering_verbs import as_gathering_verbs
from grove_tui.language.plural_gathering_verbs import as_plural_gathering_verbs
from grove_tui.language.gerund_verbs import as_verbs_before_gerunds
from grove_tui.language.leading_verb_tags import as_leading_verbs
from grove_tui.language.modal_names import as_modal_names
from grove_tui.language.counted_takers import as_counted_takers
from grove_tui.language.later_verbs import as_later_verbs
from grove_tui.language.parser import Word
from grove_tui.language.person_shapes import with_listed_subjects, with_shaped_subjects
from grove_tui.language.origin_names import origins_not_subjects
from grove_tui.language.plural_verbs import as_plural_verbs
from grove_tui.language.collective_verbs import as_collective_verbs
from grove_tui.language.seated_subjects import subject_of
from grove_tui.language.subject_phrases import (
    prepositions_as_such, subjects_of_subjectless_verbs, verbs_after_names, with_the_subject)
from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma, verb_lemma

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

_SINGULAR = frozenset({"NN", "NNP", "JJ"})
_AFTER = frozenset({"ADP", "ADV", "DET", "PROPN", "PRON", "NUM", "PART", "PUNCT", "SCONJ", "CCONJ"})
_SUBJECT_WORDS = frozenset({"DET", "ADJ", "NOUN", "PROPN", "NUM", "ADP", "PUNCT", "PRON"})


def _verb_form(w: Word) -> bool:
    low = w.lower
    if w.pos != "NOUN" or w.tag != "NNS" or not low.isalpha() or len(low) < 4 or not low.endswith("s") or \
            low.endswith(("ss", "us", "is")):
        return False
    return verb_lemma(low) != low or w.dep == "ROOT"  # a verb the lexicon knows, or the parse's own root


def _named_before(words: list[Word], k: int) -> bool:
    """Whether one person's role then name between commas come right before k ("Our toddler, Sam, waddles")."""
    return k >= 4 and words[k - 1].lower == "," and words[k - 3].lower == "," and words[k - 2].text[:1].isupper() \
        and words[k - 2].pos in ("PROPN", "NOUN") and words[k - 4].tag in _SINGULAR


def _described_people(words: list[Word], k: int) -> bool:
    """Whether word k is a plural person noun after describing words only, opening its sentence, with
    a comma after it ("Curious toddlers, a small gaggle of them, waddle ...", "Bored teenagers, a gang of
    them, loiter ..."): the people the aside counts, not a verb the parser made the root of."""
    low = words[k].lower
    if lemma(low) == low or lemma(low) not in lx.PERSON_NOUNS or verb_lemma(low) != low:
        return False
    if k + 1 >= len(words) or words[k + 1].lower != ",":
        return False
    before = [x for x in words[:k] if x.sentence == words[k].sentence]
    return bool(before) and all(x.pos in ("ADJ", "ADV") for x in before)


# Words opening a clause fronted before the main one ("When the robot comes round the corner, ..."),
# and the nouns of time that open one after "the" ("The instant the robot rolls out of the lift, ...").
_FRONTING = frozenset("when whenever as once after before while whilst if until till since".split())
_TIME_NOUNS = frozenset("moment minute second instant time".split())


def _fronted_comma(words: list[Word], k: int) -> int | None:
    """The comma before k that closes a clause fronted before the main one in k's sentence ("When the
    robot comes round the corner, ...", "The instant the robot rolls out of the lift, ..."), else None."""
    start = next(j for j in range(k + 1) if words[j].sentence == words[k].sentence)
    first = words[start].lower
    timed = start + 1 < k and first in ("the", "every", "each", "any") and words[start + 1].lower in _TIME_NOUNS
    if not (first in _FRONTING or timed):
        return None
    comma = max((j for j in range(start + 2, k) if words[j].lower == ","), default=None)
    if comma is None or not any(x.pos in ("VERB", "AUX") for x in words[start:comma]):
        return None
    return comma


def _after_a_fronted_clause(words: list[Word], k: int) -> list[Word]:
    """The words of k's sentence before k, from after a fronted clause's comma if there is one: that
    clause's verb is not one said before the person, whose own verb the parser took for a plural noun."""
    comma = _fronted_comma(words, k)
    if comma is not None:
        return words[comma + 1:k]
    return [x for x in words[:k] if x.sentence == words[k].sentence]


def _subjects_after_fronted_clauses(words: list[Word]) -> list[Word]:
    """The parse with the noun phrase right after a fronted clause's comma the subject of the verb that
    follows it ("The moment the robot trundles up to gate B2, a nervous flyer gasps": the flyer gasps),
    where the parser hung it on the clause before as an apposition."""
    out = list(words)
    for k in range(2, len(out)):
        verb, noun = out[k], out[k - 1]
        if verb.pos != "VERB" or verb.tag not in ("VBZ", "VBD", "VBP") or noun.pos != "NOUN" or noun.dep == "nsubj":
            continue
        comma = _fronted_comma(out, k)
        phrase = out[comma + 1:k] if comma is not None else []
        if len(phrase) >= 2 and phrase[0].pos == "DET" and all(x.pos in ("DET", "ADJ", "NOUN", "ADV") for x in phrase):
            out[k - 1] = replace(noun, dep="nsubj", head=k)
    return out


def _taken_for_noun(words: list[Word], k: int) -> bool:
    w = words[k]
    if k == 0 or not (_verb_form(w) or (_named_before(words, k) and w.tag == "NNS" and w.lower.endswith("s"))):
        return False
    if _described_people(words, k):
        return False
    before = without_order_words(_after_a_fronted_clause(words, k))  # "First a man shops in X"
    if not before or any(x.pos not in _SUBJECT_WORDS and x.tag != "POS" for x in before):  # "the porter's pal"
        return False  # a verb before it: "they wait by the taxi ranks"
    if any(x.tag in ("NNS", "NNPS") or (x.pos == "NUM" and x.lower != "one") for x in before):
        return False  # more than one said before: "nine members queue at reception for their day passes"
    prev = words[k - 1]
    subject = any(x.dep == "nsubj" and x.head == k for x in before)
    if not subject and not _named_before(words, k) and (prev.pos not in ("NOUN", "PROPN", "ADJ") or prev.tag not in _SINGULAR):
        return False
    nxt = words[k + 1] if k + 1 < len(words) and words[k + 1].sentence == w.sentence else None
    return nxt is None or nxt.pos in _AFTER


def as_singular_verbs(words: list[Word]) -> list[Word]:
    """The parse with the verb of one person, taken for a plural noun, tagged a verb (module doc)."""
    # "4 duck into": a verb; "A pair of orderlies wheel Mr Ahmed", "A porter wheels frail Mrs Patel": the verb
    words = with_listed_subjects(as_verbs_before_gerunds(words))  # "the junior captain practises chipping": a verb; "A steward hovers near ...": "steward" read an adverb
    words = as_leading_verbs(as_listed_verbs(as_counted_verbs(as_counted_takers(as_object_verbs(as_modal_names(words))))))  # "my mum irons shirts"
    out = prepositions_as_such(as_plural_verbs_before_a_clause(as_counted_modifiers(words)))  # "a timid lad beside gate B1": "beside" tagged a noun
    for k, w in enumerate(words):
        after_phrase = subject_of(out, k) if not _taken_for_noun(out, k) else None
        if after_phrase is not None:  # "a timid lad beside cashpoint 1 cowers", "Jenny from accounts nips over"
            out = with_the_subject(out, k, after_phrase)
            continue
        if not _taken_for_noun(out, k):
            continue
        base = verb_lemma(w.lower)
        if base == w.lower:
            base = w.lemma if w.lemma != w.lower else w.lower[:-1]
        subject = any(x.dep == "nsubj" and x.head == k for x in out[:k])
        root = next((j for j, x in enumerate(out) if x.sentence == w.sentence and x.dep == "ROOT"), k)
        out[k] = replace(w, pos="VERB", tag="VBZ", lemma=base, dep="ROOT", head=k)
        if subject:
            continue  # "Sam, our toddler, waddles": the parser found the subject
        prev = out[k - 1]
        if root == k or (root > k and (words[root].pos not in ("VERB", "AUX")
                                       or any(x.pos == "SCONJ" or x.lower in (";", "then") for x in out[k + 1:root]))):
            # "a care assistant ambles", "... nips over because her pass needs ...": the noun before
            for j in range(k - 1):
                if out[j].head == k and out[j].sentence == w.sentence:
                    out[j] = replace(out[j], head=k - 1)
            out[k - 1] = replace(prev, dep="nsubj", head=k)
        else:  # "counsel for the claimant heads": the phrase's root is the subject
            for j in range(k - 1):
                if out[j].head == k and out[j].sentence == w.sentence:
                    out[j] = replace(out[j], head=k - 1)
            out[k - 1] = replace(prev, dep=w.dep, head=w.head)
            out[root] = replace(out[root], dep="nsubj", head=k)
    # "some 30 well-wishers drift out of ...": the plural's verb, too; "Dave scoots across": its subject;
    # "is frightened of the robot and cowers whenever ...": one person's second verb
    out = with_shaped_subjects(_subjects_after_fronted_clauses(out))  # "The croupier bolts from ...": a person, taken for an adjective
    out = as_later_verbs(as_second_verbs(origins_not_subjects(subjects_of_subjectless_verbs(verbs_after_names(as_plural_verbs(as_collective_verbs(out)))))))
    return as_plural_gathering_verbs(as_gathering_verbs(out))  # "a class of twenty crowds about the robot"


def subject_of_a_later_verb(s: Sentence, k: int) -> bool:
    """Whether person word k is the parser's subject of a verb said after an aside or a phrase
    about them ("Sam, our toddler, waddles ...", "counsel for the claimant heads ..."): one person
    named, though no verb follows the word itself."""
    w = s.w[k]
    v = w.head
    if w.dep != "nsubj" or v <= k + 1 or v - k > 8 or s.w[v].pos not in ("VERB", "AUX") or k + 1 >= s.n:
        return False
    if s.low[k + 1] != "," and s.w[k + 1].pos != "ADP":
        return False
    return all(s.w[j].pos not in ("VERB", "AUX") and s.low[j] not in ("and", "or", "while", "as")
               for j in range(k + 1, v))
