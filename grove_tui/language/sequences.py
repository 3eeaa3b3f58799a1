"""Verbs that share the subject of the clause before them: a sequence of tasks for one doer ("the
robot waits on platform 1, then leads passengers to the exit", "the robot patrols the hall and later
escorts a visitor to the cafe"). The second verb has no subject of its own; it is the earlier clause's,
so people after it are the robot's when the robot is that subject."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

if TYPE_CHECKING:
    from grove_tui.language.people import People

# What joins a second verb to the first one's subject: "..., then leads", "and then guides", "and later takes"
_JOINERS = frozenset({",", "and", "then", "later", "afterwards", "next", "finally", "eventually", "also", "so"})
_PRONOUNS = frozenset({"they", "he", "she", "we", "i", "you"})


def shared_subject(s: Sentence, people: People, k: int) -> int | None:
    """The subject an earlier verb shares with the verb right after the words ending at `k`, when
    those words only join the two ("the robot waits on platform 1, then [leads]", "a guard waits
    by the gate and later [takes]"): the nearest word before them in the sentence that names someone
    (the robot, a person, a pronoun) and is followed by a verb; else None."""
    if k < 0 or s.low[k] not in _JOINERS:
        return None
    j = k
    while j >= 0 and s.low[j] in _JOINERS:
        j -= 1
    if j < 0 or s.w[j].sentence != s.w[k].sentence:
        return None
    for i in range(j, -1, -1):
        if s.w[i].sentence != s.w[k].sentence or s.low[i] in (";", ":"):
            return None
        word = s.low[i]
        if not (word in lx.ROBOT_WORDS or word in _PRONOUNS or word == "it" or people.is_person_noun(i)):
            continue
        after = i + 1
        while after < j and s.w[after].pos == "ADV":
            after += 1
        if after <= j and s.is_verb(after):
            return i
    return None


def shared_subject_is_robot(s: Sentence, people: People, k: int) -> bool:
    """Whether the verb after the joining words ending at `k` is the robot's ("the robot waits on
    platform 1, then leads passengers to the exit")."""
    i = shared_subject(s, people, k)
    return i is not None and (s.low[i] in lx.ROBOT_WORDS or (
        s.low[i] == "it" and any(w in lx.ROBOT_WORDS for w in s.low[:i])))


def shared_subject_is_person(s: Sentence, people: People, k: int) -> bool:
    """Whether the verb after the joining words ending at `k` is a person's ("a guard waits on
    platform 1, then leads four passengers to the café")."""
    i = shared_subject(s, people, k)
    return i is not None and s.low[i] not in lx.ROBOT_WORDS and s.low[i] != "it" and people.is_person_noun(i)


def acting_as_verb(s: Sentence, i: int) -> bool:
    """Whether a word that can name a person is the verb of a sequence instead ("..., then guides 5
    passengers", "and later escorts a visitor"): a verb of leading, tagged as a verb, after joining
    words and before its object."""
    if i < 1 or i + 1 >= s.n or s.w[i].pos != "VERB" or verb_lemma(s.low[i]) not in lx.LEADING_VERBS:
        return False
    return s.low[i - 1] in _JOINERS and (s.w[i + 1].pos in ("DET", "NUM", "PRON") or s.low[i + 1] in lx.DETERMINERS)


def robot_sequel(s: Sentence, verb: int, end: int) -> tuple[int, int] | None:
    """(first joining word, second verb) of a robot clause from `verb` to `end` that goes on to a
    second task with people: "waits on platform 1, then leads passengers to the exit", "patrols the
    hall and later follows a guard"; None when the clause has one verb, or its second one is no
    verb of leading or following."""
    for j in range(verb + 1, end):
        if s.low[j] not in _JOINERS - {"also", "so"} or (j > verb + 1 and s.low[j - 1] in _JOINERS):
            continue
        v = j
        while v < end and (s.low[v] in _JOINERS or s.w[v].pos == "ADV"):
            v += 1
        if v >= end or v == j or not (s.w[v].pos in ("VERB", "AUX") or s.w[v].tag.startswith("VB")):
            continue
        if verb_lemma(s.low[v]) in lx.LEADING_VERBS | lx.ROBOT_FOLLOW_VERBS and \
                any(s.low[j] == w for w in ("then", ",", "and")) and v + 1 < s.n and not s.is_punct(v + 1):
            return j, v
    return None


def each_leader(s: Sentence, people: People, k: int) -> int | None:
    """The person word of the people who each take someone along, when "each" at `k` stands between
    them and the verb or "with": "four nurses each escort a patient", "two porters, each pushing a
    patient", "three guides, each with a group of ten visitors"; else None."""
    if k < 1 or s.low[k] != "each":
        return None
    j = k - 1 if s.low[k - 1] != "," else k - 2
    return j if j >= 0 and people.is_person_noun(j) and s.lemma(j) != s.low[j] else None


# Words that open a sentence going on with the people said before: "Then they ...", "After that, they ..."
_SEQUENCE_OPENERS = frozenset({"then", "afterwards", "afterward", "later", "next", "finally", "eventually", "after",
                               "that", "this", "soon", "shortly", "and", ",", "a", "while", "minutes", "minute",
                               "few", "seconds", "hour", "an"})


def pronoun_sentences_end(s: Sentence, at: int, end: int, starts: set[int]) -> int:
    """Where the words of a group whose sentence ends at `at` end, when the sentences after it (before
    `end`, the next group's words) go on about them with "they", "he" or "she" and name nobody new:
    "Four developers chat in the kitchen. Then they go to the boardroom." The group owns them."""
    while at < end:
        sentence = s.w[at].sentence
        last = next((i for i in range(at, end) if s.w[i].sentence != sentence), end)
        if any(at <= x < last for x in starts):
            return at
        j = at
        while j < last and (s.low[j] in _SEQUENCE_OPENERS or s.w[j].pos == "NUM"):  # "Ten minutes later, they"
            j += 1
        if j >= last or s.low[j] not in ("they", "he", "she"):
            return at
        at = last
    return at
