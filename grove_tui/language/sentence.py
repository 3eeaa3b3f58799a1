"""Pass 1 of the reader: the prompt as tokens and parse, with the word-level questions every later
pass asks ("is this punctuation", "the verb's base form", "the preposition here and its width").

spaCy (language/parser.py) gives words, tags, dependencies and sentence splits; the lexicon corrects
what the small model gets wrong, so a later pass never asks spaCy directly. A `Sentence` is built
once per prompt and read by the passes that follow: people and counts (`people.py`, `counts.py`,
`mentions.py`), clauses (`clauses.py`, `reactions.py`, `robot.py`), places (`place_phrases.py`) and
groups (`groups.py`).
"""

from __future__ import annotations

import random
import re
import zlib
from collections.abc import Sequence
from functools import cached_property

from grove_tui.language import lexicon as lx
from grove_tui.language.bare_place_names import bare_place_name
from grove_tui.language.handled_fixtures import handled_at
from grove_tui.language.hyphened_nouns import hyphened_particle_noun
from grove_tui.language.parser import Word
from grove_tui.language.particle_purposes import particle_verb
from grove_tui.language.particle_names import known_compound
from grove_tui.language.places import PlaceIndex
from grove_tui.language.purpose_things import things_end
from grove_tui.language.text import plain
from grove_tui.language.tokens import lemma, verb_lemma
from grove_tui.language.hyphened_verbs import hyphened_verb
from grove_tui.language.worked_things import is_work_particle

# A word that picks one place of a series: a number, a letter and a number ("c4", "a1"), or a single
# letter after the first word of a name ("ward b").
IDENTIFIER = re.compile(r"[a-z]?\d+[a-z]?|[a-z]")
_PUNCTUATION = frozenset({",", ";", ":", ".", "!", "?", "-", "--", "—", "(", ")"})


class Sentence:
    """The parsed prompt, in one world (place words are told apart from other words by its index)."""

    def __init__(self, prompt: str, words: list[Word], index: PlaceIndex, seed: int) -> None:
        self.prompt = prompt
        self.w = words
        # "ward b." at the end of a sentence: the small model keeps the full stop on the word
        self.low = [plain(t.lower.rstrip(".") if len(t.lower) > 1 and t.lower[0].isalnum() else t.lower)
                    for t in words]
        self.index = index
        self.seed = seed
        self.n = len(words)

    # ---- words -------------------------------------------------------------------------------

    def choose(self, low: int, high: int, key: str) -> int:
        """A seeded choice in [low, high]: the same prompt and seed always give the same crowd."""
        if high <= low:
            return low
        rng = random.Random(zlib.crc32(f"{self.seed}|{key}".encode()))
        return rng.randint(low, high)

    def is_punct(self, i: int) -> bool:
        # "b." at a sentence end is tagged PUNCT by the small model, but it is a word with a full stop
        return (self.w[i].pos == "PUNCT" and not any(ch.isalnum() for ch in self.low[i])) or \
            self.low[i] in _PUNCTUATION

    def joins(self, i: int) -> bool:
        """Whether word i is a hyphen inside one word ("T-rex", "ice-cream"), no space either side."""
        w = self.w
        return self.low[i] in ("-", "‐") and 0 < i < self.n - 1 and w[i - 1].end == w[i].start and \
            w[i].end == w[i + 1].start

    def lemma(self, i: int) -> str:
        return lemma(self.low[i])

    def verb(self, i: int) -> str:
        """The verb's base form: the lexicon's first, then spaCy's for a verb the lexicon lacks."""
        v = verb_lemma(self.low[i])
        if v == self.low[i] and self.w[i].pos in ("VERB", "AUX"):
            return self.w[i].lemma
        return v

    def skip(self, j: int, words: set[str] | frozenset[str]) -> int:
        while j < self.n and self.low[j] in words and not (j + 1 < self.n and self.joins(j + 1)):
            j += 1  # "an A-list guest": the "A" of "A-list" is a word, not a second article
        return j

    def span(self, a: int, b: int) -> str:
        """The prompt's own text from word a to word b, inclusive."""
        return self.prompt[self.w[a].start:self.w[b].end]

    def sentence_of(self, i: int) -> int:
        return self.w[i].sentence

    def verbless(self, i: int) -> bool:
        """Whether the parser found no verb in word i's sentence: the small model tags some verbs as
        nouns when nothing else in the sentence is one ("a visitor sips coffee", "Mum and Dad nap")."""
        sentence = self.w[i].sentence
        # a person word the parser took for the verb is no verb ("Grandma and grandpa nap": "grandpa")
        return not any(w.pos in ("VERB", "AUX") and lemma(self.low[k]) not in lx.PERSON_NOUNS
                       for k, w in enumerate(self.w) if w.sentence == sentence)

    def is_verb(self, i: int) -> bool:
        """A verb by the parser's tag, or, in a sentence where the parser found none, a form of a
        verb the lexicon knows ("a fire alarm empties the pharmacy": the small model's noun)."""
        return self.w[i].pos in ("VERB", "AUX") or (verb_lemma(self.low[i]) != self.low[i] and self.verbless(i))

    def after_determiner(self, i: int) -> bool:
        return i > 0 and self.low[i - 1] in ("the", "a", "an", "their", "its", "his", "her", "our", "my", "this", "that")

    def hyphen_inside(self, j: int) -> bool:
        """A hyphen joining two words ("self-service", "forty-five"), not a dash between clauses."""
        return self.low[j] == "-" and 0 < j < self.n - 1 and self.low[j - 1][-1:].isalnum() and \
            self.low[j + 1][:1].isalnum() and self.w[j].start == self.w[j - 1].end

    def trigrams(self, own: Sequence[int]) -> set[tuple[str, ...]]:
        return {tuple(self.low[i:i + 3]) for i in own if i + 3 <= self.n}

    def phrase_words(self, i: int, n: int, ownset: set[int]) -> tuple[str, ...]:
        """The n words from i on in their base forms, skipping intensifiers after the first ("keep
        well clear"); words outside the clause end it."""
        out: list[str] = []
        j = i
        while j < self.n and len(out) < n:
            if j not in ownset:
                break
            word = self.low[j]
            if out and word in lx.ROBOT_PHRASE_FILLERS:
                j += 1
                continue
            base = verb_lemma(word)
            out.append(base if base != word else lemma(word))
            j += 1
        return tuple(out)

    @staticmethod
    def advance(own: Sequence[int], end: int) -> int:
        """The position in `own` of its first word at or after `end`."""
        return next((p for p, i in enumerate(own) if i >= end), len(own))

    # ---- phrases -----------------------------------------------------------------------------

    def preposition(self, i: int) -> tuple[str, int] | None:
        """(role preposition, width) for a place preposition at i, multi-word ones included; none
        before a verb ("the people inside leave": an adverb there)."""
        low = self.low
        w = low[i]
        if i >= 2 and self.hyphen_inside(i - 1):
            return None  # "check-in", "drop-off": the particle of a hyphenated name, no preposition
        if handled_at(low, i, self.index.knows):
            return "at", 1  # "tinker with the pinsetters", "check out the SUV": at the fixture handled
        if i + 1 < self.n and (self.w[i + 1].pos in ("VERB", "AUX") or verb_lemma(low[i + 1]) in lx.INTENT_VERBS) \
                and not self.index.knows(lemma(low[i + 1])) and low[i + 1] not in lx.DETERMINERS \
                and not known_compound(low, i + 1, self.index.knows) and not bare_place_name(low, i + 1):
            return None  # "in make-up", "to lost property": a place's name, though its first word is a verb
        two = tuple(low[i:i + 2])
        three = tuple(low[i:i + 3])
        if three in (("in", "front", "of"),):
            return "at", 3
        if two in (("out", "of"), ("away", "from")):
            return "from", 2
        if two in (("next", "to"), ("close", "to"), ("up", "to"), ("over", "to"), ("down", "to"), ("on", "to"),
                   ("in", "to")):
            return ("at" if two[0] in ("next", "close") else "to"), 2
        if is_work_particle(self.w, i):
            return None  # "hoses down the scrap cars": what is worked on, no way down
        if w == "down" and i + 1 < self.n and low[i + 1] in lx.DETERMINERS:
            return "down", 1
        if w == "round" and i + 1 < self.n and (low[i + 1] in lx.DETERMINERS or self.index.knows(lemma(low[i + 1]))):
            return "around", 1  # "gather round the whiteboard"
        if w == "over" and i + 2 < self.n and (low[i + 1] in lx.DETERMINERS and self.index.knows(lemma(low[i + 2])) or
                                               self.index.knows(lemma(low[i + 1])) and IDENTIFIER.fullmatch(low[i + 2])) \
                and not (i > 0 and lx.INTENT_VERBS.get(verb_lemma(low[i - 1])) in ("walk", "evacuate")):
            return "at", 1  # "hunched over the reception desk", "leaning over desk 9": at it, not across it
        if w == "out" and i + 1 < self.n and low[i + 1] in lx.DETERMINERS:
            return "out", 1  # "head out the back", "walk out the front door"
        if w == "between" and not any(low[x] == "and" for x in range(i + 2, min(i + 8, self.n))):
            return None  # "drift between shops": among them; "between X and Y" names two places
        if w == "up" and i + 1 < self.n and low[i + 1] in lx.DETERMINERS:
            return "down", 1  # "up the stairs", "up the corridor": along it, as "down"
        if w == "of" and i > 0 and low[i - 1] in _LAPS:
            return "around", 1  # "laps of the atrium", "a circuit of the garden": round it
        if w in lx.PLACE_PREPOSITIONS - {"down", "next"}:
            return w, 1
        if w == "where" and i > 0 and any((lx.INTENT_VERBS.get(verb_lemma(low[x])) or self.w[x].pos == "VERB") and
                                          self.w[x].lemma.lower() not in _KNOWING and verb_lemma(low[x]) not in _KNOWING
                                          for x in range(max(0, i - 2), i)):
            # "wait where the trains come in": the place of the clause (language/place_meaning.py); "go where ..." to it
            moving = any(lx.INTENT_VERBS.get(verb_lemma(low[x])) in ("walk", "evacuate")
                         for x in range(max(0, i - 2), i))
            return ("to" if moving else "at"), 0
        if w in ("upstairs", "downstairs") and i > 0 and \
                lx.INTENT_VERBS.get(verb_lemma(low[i - 1]), "wait") not in lx.STATIONARY_INTENTS:
            # "the kids run upstairs": up the stairs (language/place_around.py); on the way when a place follows
            return ("via" if i + 1 < self.n and low[i + 1] in lx.DESTINATION_PREPOSITIONS else "to"), 0
        return None

    def verb_follows(self, k: int) -> bool:
        """Whether the word at k is a verb (after "to": a purpose, not a place)."""
        if k >= self.n:
            return False
        if hyphened_verb(self, k):
            return True  # "keen to test-drive the estate car": a purpose, though the parser reads "test" a noun
        w = self.low[k]
        if w in lx.DETERMINERS or self.w[k].pos in ("DET", "NUM", "PROPN") or bare_place_name(self.low, k):
            return False  # "to lost property": a place's name
        if self.index.knows(lemma(w)) and self.w[k].tag != "VB":
            return False
        if hyphened_particle_noun(self, k):
            return False  # "walks to check-in": a place, not a purpose
        if k + 1 < self.n and IDENTIFIER.fullmatch(self.low[k + 1]) and self.index.knows(lemma(w)) and not (
                self.low[k + 1] == "a" and k + 2 < self.n and self.w[k + 2].pos in ("NOUN", "ADJ")):
            return False  # "to gate C4": a place word with its number, though the parser calls "gate" a verb
            # (but "to book a study room": a verb and its object)
        return self.w[k].tag == "VB" or self.w[k].pos == "VERB" or verb_lemma(w) != w or w in (
            "register", "check", "pick", "buy", "pay", "collect", "see", "get", "eat", "drink", "use") or \
            particle_verb(self.low, k, self.index.knows)  # "to hand in their coats"

    def around_follows(self, i: int) -> bool:
        return i + 1 < self.n and self.low[i + 1] in ("around", "about")

    def phrase_end(self, k: int, allow_objects: bool = False) -> int:
        """End (exclusive) of a short phrase: up to punctuation, a clause word or a place preposition."""
        j = k
        while j < self.n and j < k + 6:
            w = self.low[j]
            if (self.is_punct(j) and not self.joins(j)) or w in lx.CLAUSE_STARTERS or \
                    (w in lx.PLACE_PREPOSITIONS and j > k) or w == "for" or j > k and any(
                        tuple(self.low[j:j + len(p)]) == p for p in lx.NEGATED_PLACE_PHRASES):
                break  # "for bacon rolls rather than the staff lounge": the purpose ends before the place refused
            if not allow_objects and j > k and verb_lemma(w) in lx.INTENT_VERBS and self.w[j].pos == "VERB":
                break
            j += 1
        if allow_objects and j > k:
            return things_end(self, j)  # "to buy plasters and paracetamol": the things a purpose gets are all of it
        return j

    # ---- parse-level spans -------------------------------------------------------------------

    @cached_property
    def relative(self) -> frozenset[int]:
        """The words of relative clauses ("the visitors who are waiting in the lobby"): they say who
        the people are, not what they do, unless nothing else in their clause does."""
        children: dict[int, list[int]] = {}
        for w in self.w:
            if w.head != w.i:
                children.setdefault(w.head, []).append(w.i)
        out: set[int] = set()
        for w in self.w:
            if w.dep != "relcl":
                continue
            clause: set[int] = set()
            stack = [w.i]
            while stack:
                k = stack.pop()
                if k not in clause:
                    clause.add(k)
                    stack.extend(children.get(k, ()))
            # The small model may hang the main verb inside it ("who were sitting in the boardroom
            # walk to ..."): a finite verb of the lexicon after the relative's own verb ends it.
            end = next((k for k in sorted(clause) if k > w.i and self.w[k].tag not in ("VBG", "VBN")
                        and verb_lemma(self.low[k]) in lx.INTENT_VERBS and self.low[k - 1] != "to"
                        and self.w[k - 1].pos != "DET"), None)
            out |= {k for k in clause if end is None or k < end}
        return frozenset(out)

    @cached_property
    def together_phrases(self) -> frozenset[int]:
        """The words of "as a group", "side by side" ...: manner, never a mention of people."""
        out: set[int] = set()
        for i in range(self.n):
            for phrase in lx.TOGETHER_PHRASES:
                end = i + len(phrase)
                if tuple(self.low[i:end]) == phrase:
                    if end < self.n and (verb_lemma(self.low[end]) in lx.INTENT_VERBS | lx.ROBOT_VERBS.keys()
                                         or self.w[end].tag in ("VBZ", "VBD", "VBP", "MD")):
                        continue  # "as a family talks", "as a family buys tickets": who the clause is about
                    out.update(range(i, end))
        return frozenset(out)


# Verbs whose "where" asks or tells a place, not a place where people are ("know where the exit is").
_KNOWING = frozenset("know see wonder ask show tell remember forget decide find check say explain point "
                     "guess learn understand notice hear read look".split())
# Rounds of a place said with "of" ("laps of the atrium"): the place is gone round.
_LAPS = frozenset("laps lap circuits circuit loops loop lengths length".split())
