"""One person named by a word the reader does not know as a person, said with a describing participle or a
verb the tagger takes for a plural noun ("the visiting hairdresser makes her way to the salon", "a
sixth-former ducks out of the toy shop", "the smiling clown walks to the kitchen"): a single article and
a singular head before a finite verb say one person, not a vague crowd left to the model."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.model import Count
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma, verb_lemma

_ONE = frozenset({"a", "an", "the"})
_FINITE = frozenset({"VBZ", "VBD"})
_AFTER_A_VERB = frozenset({"IN", "RP", "TO", "DT", "PRP$", "RB"})  # "ducks out of", "nips into", "grabs a"

_PERSON_ENDINGS = ("er", "or", "ist", "ian", "ee", "ant", "ent", "man", "woman", "ess", "ie", "ster")
_PERSON_PRONOUNS = frozenset({"her", "his", "she", "he", "herself", "himself"})
# Words of a subject that is no person ("the flashing light", "the waiting room", "the visiting hours").
_NOT_PEOPLE = frozenset("""afternoon morning evening night day hour hours minute moment time week weekend session
shift lift elevator door alarm light queue line sign screen floor room area hall place bell phone noise smell smoke
fire water rain sun announcement delivery train bus flight plane van car trolley event meeting show film tour class
lesson talk match game sale gate barrier turnstile window machine printer tap kettle""".split())
# Verbs a thing does as well as a person: after one, the subject must show it is a person.
_THING_POSTURES = frozenset({"sit", "stand", "lie", "hang", "rest", "lean", "stay", "remain", "lay"})


def _is_modifier(s: Sentence, i: int) -> bool:
    """A word describing the head before it: an adjective, a participle, a noun, a hyphened part."""
    if s.low[i] == "-" or s.w[i].tag == "HYPH" or (i > 0 and s.low[i - 1] == "-") or (i + 1 < s.n and s.low[i + 1] == "-"):
        return True
    return s.w[i].tag == "VBG" or s.w[i].pos in ("ADJ", "NOUN", "PROPN")


def _person_cue(s: Sentence, first: int, head: int, verb: int) -> bool:
    """Whether the subject shows it is a person: an agent ending, a hyphened compound, a "her"/"his" in
    its clause, or a verb only people do."""
    if s.low[head].endswith(_PERSON_ENDINGS) or "-" in s.low[first:head + 1]:
        return True
    if verb_lemma(s.low[verb]) in lx.PEOPLE_GOING_VERBS | lx.HUMAN_SUBJECT_VERBS:
        return True
    stop = next((i for i in range(verb, s.n) if s.low[i] in (";", ".")), s.n)
    return any(s.low[i] in _PERSON_PRONOUNS for i in range(verb, stop))


def _said_of_a_person(s: Sentence, verb: int) -> bool:
    """A verb only people do, or "her"/"his" right after it ("makes her way", "grabs his coat")."""
    return verb_lemma(s.low[verb]) in lx.PEOPLE_GOING_VERBS or (verb + 1 < s.n and s.low[verb + 1] in _PERSON_PRONOUNS)


def lone_subject_count(s: Sentence, robot_tokens: set[int]) -> Count | None:
    """Exactly one, when the sentence opens "a/an/the" + describing words + one singular person word +
    its finite verb, a verb the tagger took for a plural noun counted as the verb."""
    if s.n < 4 or s.low[0] not in _ONE or 0 in robot_tokens:
        return None
    k = 1
    while k < s.n and k < 7 and (s.low[k] == "-" or not s.is_punct(k)) and _is_modifier(s, k) and k not in robot_tokens:
        k += 1
    if k < 2 or k >= s.n:
        return None
    head, verb = k - 1, k
    if s.w[verb].tag not in _FINITE:
        # "a sixth-former ducks out": the singular article's head cannot be a plural noun; it is the verb
        if s.low[0] == "the" or head < 2 or s.w[head].tag != "NNS" or s.w[verb].tag not in _AFTER_A_VERB:
            return None
        head, verb = head - 1, head
    if s.w[head].tag == "VBG" or s.low[head] == "-" or lemma(s.low[head]) != s.low[head] and s.w[head].tag == "NNS":
        return None
    word = s.low[head]
    if word in lx.ROBOT_WORDS or lemma(word) in _NOT_PEOPLE or lemma(word) in lx.NON_PEOPLE:
        return None
    found = s.index.match([lemma(w) for w in s.low[1:head + 1] if w != "-"])
    if found is not None and found.exact and not (word.endswith(_PERSON_ENDINGS) and _said_of_a_person(s, verb)):
        return None  # "the revolving door turns": a place's name
    if verb_lemma(s.low[verb]) in lx.THING_VERBS | lx.EVENT_VERBS:
        return None
    if verb_lemma(s.low[verb]) in _THING_POSTURES and not _person_cue(s, 1, head, verb):
        return None
    if not _person_cue(s, 1, head, verb):
        return None
    return Count("exact", 1, 1, 1)
