"""The count of the people a sentence names by a word the reader does not know as a person ("the
clinical lead comes over", "a first-time donor lies on the couch", "roughly 30 jumpers wait", "three or
four anxious in-laws in ICU"): when no group is found and the model is left to fill the people in, the
subject's own number, article or pair word still says how many there are; a vague crowd is only a guess."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.counts import count_of, quantifier
from grove_tui.language.lone_subjects import lone_subject_count
from grove_tui.language.model import Count, FieldConfidence, GroupReading
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma, verb_lemma

_SINGLE = frozenset({"a", "an", "the", "one", "this", "that"})
_FINITE = frozenset({"VBZ", "VBP", "VBD", "MD"})
# Verbs of people a tagger may take for plural nouns after a singular subject ("waits", "wanders").
_MISTAGGED_VERBS = lx.PEOPLE_GOING_VERBS | lx.HUMAN_SUBJECT_VERBS | lx.ROBOT_WAIT_VERBS
# Round 48: a second clause's subject ("..., and the twenty or so jumpers in the cage pour out"), and the
# article before a count ("the twenty or so", "all thirty", "those forty").
_JOINERS = frozenset({"and", "but"})
_OPENERS = frozenset({"the", "all", "those", "these"})
_RELATIVES = frozenset({"who", "whom", "that", "whose"})
# Words of a subject that is no person: a time, a thing, a place, an event ("a busy afternoon", "the lift").
_NOT_PEOPLE = frozenset("""afternoon morning evening night day hour minute moment time week weekend session shift
lift elevator door doors alarm light lights queue line sign screen floor room area hall place bell phone
noise smell smoke fire water rain sun announcement delivery train bus flight plane van car trolley
event meeting show film tour class lesson talk match game sale gate barrier turnstile window""".split()) | lx.PASSAGE_WORDS


# Verbs of posture or rest that things do as well as people ("a new mudguard sits by the entrance"): after
# one of them the subject must show it is a person some other way (_person_cue).
_THING_POSTURES = frozenset({"sit", "stand", "lie", "hang", "rest", "lean", "stay", "remain", "lay"})
_PERSON_ENDINGS = ("er", "or", "ist", "ian", "ee", "ant", "ent", "man", "woman", "ess", "ie", "ster")
_PERSON_PRONOUNS = frozenset({"her", "his", "their", "she", "he", "they", "them", "him", "herself", "himself"})


def _person_cue(s: Sentence, first: int, end: int, verb: int | None) -> bool:
    """Whether the subject shows it is a person: an agent ending ("donor", "jumper"), a hyphened compound
    ("first-time", "in-laws"), a "who" clause, a personal pronoun in its clause, or the robot it reacts to."""
    head = lemma(s.low[end - 1])
    if head.endswith(_PERSON_ENDINGS) or "-" in s.low[first:end] or (end < s.n and s.low[end] in ("who", "whom", "whose")):
        return True
    stop = next((i for i in range(verb or end, s.n) if s.low[i] in (";", ".")), s.n)
    return any(s.low[i] in _PERSON_PRONOUNS or s.low[i] in lx.ROBOT_WORDS for i in range(end, stop))


def _starts(s: Sentence) -> list[int]:
    """Where the main clause's subject may begin: the sentence's start, and after each comma of a
    fronted clause or word ("As soon as the session starts, ...", "Wide-eyed, ...")."""
    return [0] + [i + 1 for i in range(s.n - 1) if s.low[i] == ","]


def _phrase_end(s: Sentence, j: int) -> int:
    """The index after the noun phrase's modifiers and head starting at j."""
    k = j
    while k < s.n:
        hyphened = (s.low[k] == "-" and k > j) or (k > j and s.low[k - 1] == "-") or \
            (k + 1 < s.n and s.low[k + 1] == "-")  # "first-time", "in-laws", "eight-year-olds"
        if not hyphened and (s.is_punct(k) or s.w[k].pos not in ("ADJ", "NOUN", "PROPN")):
            break
        k += 1
    return k


def _verb_after(s: Sentence, k: int) -> int | None:
    """The finite verb the subject ending before k goes with, past a short place phrase or a "who"
    clause ("a pair of cub scouts beside the rescue pump gape", "a donor who felt woozy lies")."""
    relative = k < s.n and s.low[k] in _RELATIVES
    seen = 0
    for i in range(k + (1 if relative else 0), min(s.n, k + 10)):
        if s.low[i] in (",", ";", ".", "and", "but", "while"):
            return None
        if s.w[i].tag in _FINITE or (s.w[i].pos in ("VERB", "AUX") and s.w[i].tag not in ("VBG", "VBN")) or \
                (s.w[i].tag == "NNS" and verb_lemma(s.low[i]) in _MISTAGGED_VERBS) or \
                _going_taken_for_a_noun(s, k, i):  # "a temp ... waits", "the fifty ... on the pier pour into"
            if relative and seen == 0:
                seen = 1
                continue
            return i
        if i == k and not relative and s.w[i].pos != "ADP":
            return None
    return None


def _going_taken_for_a_noun(s: Sentence, k: int, i: int) -> bool:
    """Whether the word at i, past the subject's place phrase, is a verb of going the parser took for
    the place's last noun ("the fifty or so crabbers on the pier pour into the arcade": "pier pour")."""
    return i > k + 1 and s.w[i].tag in ("NN", "NNS") and i + 1 < s.n and s.w[i + 1].pos == "ADP" and \
        lx.INTENT_VERBS.get(verb_lemma(s.low[i])) in ("walk", "evacuate") and s.w[i - 1].pos in ("NOUN", "PROPN")


def _names_a_place(s: Sentence, first: int, end: int) -> bool:
    """Whether the phrase is a place's whole name ("the fountain sparkles"); a word a place only shares
    ("a donor" in a donor centre) is no place."""
    found = s.index.match([lemma(w) for w in s.low[first:end] if w != "-"])
    return found is not None and found.exact


def subject_count(s: Sentence, robot_tokens: set[int]) -> Count | None:
    """The count the sentence's first subject phrase says, if it has one and names nobody known."""
    joined = [i + 1 for i in range(s.n - 1) if s.low[i] in _JOINERS and s.w[i].pos == "CCONJ"]
    one: Count | None = None  # a lone "the power fails" gives way to a later clause's counted subject
    for start in _starts(s)[:3] + joined:  # "The alarm trips and the twenty or so jumpers ... pour out"
        if one is not None and start not in joined:
            continue
        if start in robot_tokens or start >= s.n:
            continue
        q = quantifier(s, start)
        opened = q is None and s.low[start] in _OPENERS and start + 1 < s.n
        if opened:
            q = quantifier(s, start + 1)  # "the twenty or so jumpers": the count after its article
        single = q is None and s.low[start] in _SINGLE
        if q is None and not single:
            continue
        head_start = q.end if q is not None else start + 1
        end = _phrase_end(s, head_start)
        taken = end == head_start and opened and q is not None and head_start + 1 < s.n and s.low[head_start].isalpha() \
                and s.low[head_start].endswith("s") and s.w[head_start + 1].pos == "ADP"
        if taken:
            end += 1  # "the thirty or so floats in the pool": whatever word is counted, tagged a verb or not
        if end == head_start or any(i in robot_tokens for i in range(start, end)):
            continue
        head = s.low[end - 1]
        if head in lx.ROBOT_WORDS or lemma(head) in _NOT_PEOPLE or lemma(head) in lx.NON_PEOPLE or \
                (s.w[end - 1].pos not in ("NOUN", "PROPN") and not taken) or _names_a_place(s, head_start, end):
            continue
        plural = lemma(head) != head
        if single and (plural or s.low[start] == "the" and s.w[end - 1].pos == "PROPN"):
            continue
        verb = _verb_after(s, end)
        verbless = not any(w.tag in _FINITE for i, w in enumerate(s.w) if not start <= i < end)
        if verb is None and not (verbless and q is not None and q.value):
            continue
        if verb is not None and lemma(s.low[verb]) in lx.THING_VERBS | lx.EVENT_VERBS:
            continue
        if verb is not None and verb_lemma(s.low[verb]) in _THING_POSTURES and not _person_cue(s, start, end, verb):
            continue
        if single:
            if verb is not None and s.w[verb].tag == "VBP":
                continue
            one = one or Count("exact", 1, 1, 1)
            continue
        assert q is not None
        return count_of(s, q, "unnamed")
    return one


def counted_unnamed(s: Sentence, group: GroupReading, robot_tokens: set[int]) -> GroupReading:
    """The unnamed group with the count its subject says, when it says one."""
    count = subject_count(s, robot_tokens) or lone_subject_count(s, robot_tokens)  # "the visiting hairdresser makes"
    if count is None:
        return group
    return replace(group, count=count, confidence=tuple(c for c in group.confidence if c.field != "count") + (
        FieldConfidence("count", 0.7, f"the subject's own number: {count.value}"),))
