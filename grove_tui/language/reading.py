"""The reading of a prompt: which groups of people, how many, doing what, where (the shared contract).

    reading = read_prompt("Two families of three walk together to the cafeteria, while a few others "
                          "stroll around the lobby", world, seed=0)
    reading.groups[0].count   # Count(kind="structured", value=6, low=6, high=6, parties=2, party_size=3)
    reading.groups[1].intent  # "wander", location "entrance_lobby", relation "others_of:0"

Pure and deterministic: spaCy (language/parser.py) tokenizes the prompt, splits sentences and tags
words; the lexicon (language/lexicon.py) says what the words mean; the place matcher
(language/places.py) turns place phrases into the world's own names. No model is asked.

How a prompt is read:
1. Mentions. A group of people starts at a person phrase in subject position: at the start of a
   sentence or clause ("..., while", "and", "as", "then", "except"), after "there are" or an
   imperative scene verb ("Simulate ten nurses"). Its count is read from the phrase: a number,
   approximate ("about twenty"), vague ("a few", range in the lexicon, value chosen from the
   seed), implied by a collective ("a family" 3-4), structured ("two families of three" = 2
   parties of 3), whole-zone ("everyone in the cafeteria": the zone's area at a busy density) or
   exclusive ("nobody ... except one guard"). Relations: "one of them" is part of the group
   before (subset_of), "the others" / "a few others" are other people than that group
   (others_of; after a subset, the rest of its parent), "a few more" adds to it (more_of).
   A subset group's people are counted in its parent's `value` too: generation takes them out.
2. Clauses. Each group owns the words from its mention to the next mention; words before a
   sentence's first mention ("In the lobby, ...", "Evacuate the meeting area: ...") belong to the
   whole sentence. A group whose own words state no action shares the next group's ("ten
   patients and two nurses walk to the exit").
3. Places by role. A preposition gives a place its role (from: start; to/into/towards:
   destination; at/in/on/near/around: location for stationary intents, start for movers unless
   the verb is one of arrival; through/via/past/across: via, or the destination of a departure
   verb through an exit). "leave/evacuate the X" makes X the start, "enter/reach the X" the
   destination. Only a noun phrase in such a role can be an unknown place, and never one whose
   head is a word for people, time, manner or the building itself.
4. Intents from the verbs (phrasal verbs first: "line up" is a queue, "walk around" wandering),
   robot interactions from the verb that governs the robot (look, approach, follow, avoid,
   block -> HuNavSim Surprised, Curious, Curious, Scared, Threatening), purposes that are not
   places ("to register", "for coffee"), waits with durations, pace and togetherness.
5. Evacuations: a cue word ("evacuate", "alarm"), a hazard named on its own ("Fire!", "a bomb
   scare", not "the fire exit"), an emptying phrase ("empty out"; "get out" with urgency) or a
   zone that is cleared ("Platform 1 must be cleared", "clear the kitchen": its start).
6. Who is a person: a noun of the lexicon's list, a misspelling of one that is no word of the
   parser's vocabulary, the subject of a verb only people do ("a sommelier chats"), or a counted
   noun that does more than things do ("ten zombies shamble", not "two posters hang").
"""

from __future__ import annotations

import random
import re
import unicodedata
import zlib
from collections.abc import Sequence
from functools import lru_cache
from dataclasses import dataclass, field, replace
from typing import Any

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word, known_word, parse
from grove_tui.language.model import (COUNT_KINDS, INTENTS, ROBOT_INTERACTIONS, Count, FieldConfidence,  # noqa: F401
                                      GroupReading, PromptReading, RobotReading, effective_counts)
from grove_tui.language.places import PlaceIndex, PlaceMatch, place_index
from grove_tui.language.tokens import lemma, phrase_lemmas, verb_lemma

# A word that picks one place of a series: a number, a letter and a number ("c4", "a1"), or a single
# letter after the first word of a name ("ward b").
_IDENTIFIER = re.compile(r"[a-z]?\d+[a-z]?|[a-z]")
_MULTIWORD_LAST = frozenset(p[-1] for p in lx.MULTIWORD_PEOPLE)


# ---- reading --------------------------------------------------------------------------------

def _place_confidences(roles: dict[str, str | None], via: Sequence[str],
                       read_from: dict[str, _Place]) -> list[FieldConfidence]:
    """The confidence of each place field whose match was less than sure (see _match_confidence)."""
    out: list[FieldConfidence] = []
    for name, value in [*roles.items(), *(("via", v) for v in via)]:
        place = read_from.get(value) if value else None
        if place is not None and place.score < 1.0:
            out.append(FieldConfidence(name, place.score, place.reason, place.alternatives))
    return out


@lru_cache(maxsize=2048)
def _near_person_noun(word: str) -> str | None:
    """The person noun a word is one insertion, deletion, substitution or swap of two neighbours
    away from, in its singular or plural (Damerau-Levenshtein distance 1); None if none is."""
    forms = _person_forms()
    for n in (len(word) - 1, len(word), len(word) + 1):
        for form, noun in sorted(forms.get(n, {}).items()):
            if _one_edit(word, form):
                return noun
    return None


@lru_cache(maxsize=1)
def _person_forms() -> dict[int, dict[str, str]]:
    """Length -> {written form: person noun}, for the typo check."""
    by_length: dict[int, dict[str, str]] = {}
    irregular = {"children": "child", "people": "person", "women": "woman", "men": "man"}
    for noun in lx.PERSON_NOUNS:
        plural = noun[:-1] + "ies" if noun.endswith("y") else noun + "s"
        for form in (noun, plural, noun + "es"):
            if len(form) >= 5:
                by_length.setdefault(len(form), {}).setdefault(form, noun)
    for form, noun in irregular.items():
        by_length.setdefault(len(form), {})[form] = noun
    return by_length


def _one_edit(a: str, b: str) -> bool:
    if a == b:
        return False
    if len(a) == len(b):
        diff = [k for k in range(len(a)) if a[k] != b[k]]
        return len(diff) == 1 or (len(diff) == 2 and diff[1] == diff[0] + 1 and a[diff[0]] == b[diff[1]]
                                  and a[diff[1]] == b[diff[0]])
    if len(a) > len(b):
        a, b = b, a
    return any(b[:k] + b[k + 1:] == a for k in range(len(b)))


def _plain(word: str) -> str:
    """The word without accents ("café" -> "cafe"), as world names are written."""
    if word.isascii():
        return word
    return unicodedata.normalize("NFKD", word).encode("ascii", "ignore").decode() or word


def read_prompt(prompt: str, world: Any, *, seed: int = 0) -> PromptReading:
    """The groups of people a prompt describes, in the world's own place names (see module doc)."""
    text = " ".join((prompt or "").split())
    if not text:
        return PromptReading(prompt or "", ())
    index = place_index(world)
    words = parse(text)
    corrected, corrections = _place_spelling(text, words, index)
    if not corrections:
        return _Reader(text, words, index, int(seed)).read()
    # The corrected sentence is parsed again: a misspelt word is often mis-tagged too ("the kitchn").
    reading = _Reader(corrected, parse(corrected), index, int(seed)).read()
    return replace(reading, prompt=text, corrections=tuple(corrections))


def _place_spelling(text: str, words: Sequence[Word], index: PlaceIndex) -> tuple[str, list[str]]:
    """The prompt with misspelt place words put right, and what was put right ("read 'kitchn' as
    'kitchen'"). Conservative, so a real word is never turned into a place: a word is corrected only
    when the world has no place word like it, it is no word for people and no verb the lexicon knows,
    and exactly one word of the world's place names is one edit away (an insertion, deletion,
    substitution or swap of neighbours). Short words (3-4 letters) and real English words ("sever") are
    corrected only when the correction completes a name with the word next to them ("sever room" ->
    "server room"), never alone ("left" is not "lift"). Two words of a name run together are split
    ("livingroom" -> "living room")."""
    edits: list[tuple[int, int, str, str]] = []
    for k, w in enumerate(words):
        low = _plain(w.lower)
        if not low.isalpha() or len(low) < 3:
            continue
        base = lemma(low)
        if base in index.vocabulary or low in index.vocabulary or base in lx.PERSON_NOUNS or \
                low in lx.STOPWORDS or low in lx.NUMBER_WORDS or low in lx.ROBOT_WORDS or \
                verb_lemma(low) in lx.INTENT_VERBS or verb_lemma(low) in lx.ROBOT_VERBS:
            continue
        person = _near_person_noun(low)
        if person is not None and person not in index.vocabulary:
            continue  # "docters": a person, read by the people rule ("securty" is both: a place here)
        before, after = _content_neighbours(words, k)
        joined = index.joined_pairs.get(low)
        if joined is not None:
            if known_word(low):
                continue
            replacement = " ".join(joined)
        else:
            as_written = {v for v in index.name_words if abs(len(v) - len(low)) <= 1 and _one_edit(low, v)}
            as_plural = {v for v in index.name_words if base != low and abs(len(v) - len(base)) <= 1
                         and _one_edit(base, v)}
            found = sorted(as_written | as_plural)
            if len(found) != 1:
                continue  # nothing near, or two names equally near: no guess
            replacement = found[0]
            if replacement not in as_written:
                replacement += low[len(base):] if low.startswith(base) else "s"  # "machnes" -> "machines"
            completes = (before, found[0]) in index.name_pairs or (found[0], after) in index.name_pairs
            if (len(low) < 5 or known_word(low)) and not completes:
                continue  # "ticket hal" is the ticket hall; "hal" alone is nothing
        if w.text[:1].isupper():
            replacement = replacement[:1].upper() + replacement[1:]
        edits.append((w.start, w.end, replacement, w.text))
    if not edits:
        return text, []
    out = text
    for start, end, replacement, _ in reversed(edits):
        out = out[:start] + replacement + out[end:]
    return out, [f"read '{original}' as '{replacement}'" for _, _, replacement, original in edits]


def _content_neighbours(words: Sequence[Word], k: int) -> tuple[str, str]:
    """The lemmas of the nearest content words before and after word k ("chek-in hall": "hall")."""
    def near(indices: range) -> str:
        for j in indices:
            low = _plain(words[j].lower)
            if low.isalnum() and low not in lx.STOPWORDS:
                return lemma(low)
            if low.isalnum() and low not in ("in", "of", "-"):
                return ""
        return ""
    return near(range(k - 1, max(-1, k - 3), -1)), near(range(k + 1, min(len(words), k + 3)))


@dataclass
class _Mention:
    first: int  # token span of the person phrase
    last: int
    who: str
    label: str
    count: Count | None  # None for whole-zone and rest-of-parent counts, settled once places are known
    relation: str | None = None
    together: bool = False
    whole_zone: bool = False
    exclusive: bool = False
    rest_of_parent: bool = False
    collective: str | None = None  # the collective noun of "a queue of eight people", "a family"
    exception_of: int | None = None  # "everyone ... except two guards": the mention they are excepted from
    fraction: float = 1.0  # "half the office": the share of the zone's people
    zone_place: _Place | None = None  # the zone named inside the mention ("half the open office")


@dataclass
class _Place:
    prep: str  # the preposition or "obj:start" / "obj:dest" / "obj:via" for verb objects
    index: int  # token index of the preposition
    words: tuple[str, ...]
    match: PlaceMatch | None
    end: int = 0  # token index after the phrase
    score: float = 1.0  # how sure the match is (1.0: the phrase holds the place's whole name or an alias)
    reason: str = ""
    alternatives: tuple[str, ...] = ()  # other places the phrase fits as well


@dataclass
class _RobotClause:
    """A clause whose subject is the robot ("a robot crosses the hall to the lifts", "as it passes
    the lobby", "send the robot to ward A"): its words, and the index of its verb."""

    tokens: list[int]
    verb: int | None
    command: bool = False  # "send the robot to ...": the verb is the sender's


@dataclass
class _Clause:
    intent: str | None = None
    verb: str | None = None
    verb_index: int | None = None
    robot: str | None = None
    places: list[_Place] = field(default_factory=list)
    purpose: str | None = None
    wait_seconds: float | None = None
    together: bool = False
    pace: str = "normal"
    follows: str | None = None
    evacuate: bool = False
    has_action: bool = False
    moves: bool = False  # a verb of walking is among the clause's verbs


class _Reader:
    def __init__(self, prompt: str, words: list[Word], index: PlaceIndex, seed: int) -> None:
        self.prompt = prompt
        self.w = words
        # "ward b." at the end of a sentence: the small model keeps the full stop on the word
        self.low = [_plain(t.lower.rstrip(".") if len(t.lower) > 1 and t.lower[0].isalnum() else t.lower)
                    for t in words]
        self.index = index
        self.seed = seed
        self.n = len(words)
        self.unknown: list[str] = []
        self.notes: list[str] = []
        self.context_zones: list[str] = []  # zones of the places read so far, in reading order
        self.frame_zones: list[str] = []  # zones named as where people are ("on platform 2"), in reading order
        self.relative = self._relative_clause_tokens()
        self.quiet = False  # True while reading a clause whose places nobody goes to (see read)
        self.no_mention = self._together_phrase_tokens()

    # -- helpers ---------------------------------------------------------------------------

    def _choose(self, low: int, high: int, key: str) -> int:
        if high <= low:
            return low
        rng = random.Random(zlib.crc32(f"{self.seed}|{key}".encode()))
        return rng.randint(low, high)

    def _is_punct(self, i: int) -> bool:
        # "b." at a sentence end is tagged PUNCT by the small model, but it is a word with a full stop
        return (self.w[i].pos == "PUNCT" and not any(ch.isalnum() for ch in self.low[i])) or \
            self.low[i] in {",", ";", ":", ".", "!", "?", "-", "--", "—", "(", ")"}

    def _lemma(self, i: int) -> str:
        return lemma(self.low[i])

    def _verb(self, i: int) -> str:
        v = verb_lemma(self.low[i])
        if v == self.low[i] and self.w[i].pos in ("VERB", "AUX"):
            return self.w[i].lemma
        return v

    def _negated_clause_tokens(self) -> set[int]:
        """The words of a clause about nobody ("No one uses the main corridor; ...", "No passengers
        are waiting on platform 1, but ..."): its places are where nobody is, so they set no scene.
        Not when the clause names an exception ("nobody is in the kitchen except the cleaner")."""
        out: set[int] = set()
        for i in range(self.n):
            nobody = self.low[i] in lx.NOBODY_WORDS or (self.low[i] == "no" and i + 1 < self.n and (
                self.low[i + 1] in ("one", "body") or self._is_person_noun(i + 1)))
            if not nobody:
                continue
            end = i + 1
            while end < self.n and self.w[end].sentence == self.w[i].sentence and self.low[end] not in (";", ":") \
                    and not (self.low[end] in lx.CLAUSE_STARTERS | {"instead"} and end > i + 2):
                end += 1
            clause = range(i, end)
            if any(self.low[k] in lx.EXCEPT_WORDS or self.low[k] in ("apart", "only", "than") for k in clause) or \
                    (end < self.n and self.low[end] in lx.EXCEPT_WORDS - {"but"}):  # "..., but a cleaner"
                continue
            out.update(clause)
        return out

    def _relative_clause_tokens(self) -> set[int]:
        """The words of relative clauses ("the visitors who are waiting in the lobby"): they say who
        the people are, not what they do, unless nothing else in their clause does."""
        children: dict[int, list[int]] = {}
        for w in self.w:
            if w.head != w.i:
                children.setdefault(w.head, []).append(w.i)
        out: set[int] = set()
        for w in self.w:
            if w.dep == "relcl":
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
        return out

    def _together_phrase_tokens(self) -> set[int]:
        out: set[int] = set()
        for i in range(self.n):
            for phrase in lx.TOGETHER_PHRASES:
                end = i + len(phrase)
                if tuple(self.low[i:end]) == phrase:
                    if end < self.n and verb_lemma(self.low[end]) in lx.INTENT_VERBS | lx.ROBOT_VERBS.keys():
                        continue  # "as a family talks": the family is who the clause is about
                    out.update(range(i, end))
        return out

    def _number_at(self, i: int) -> tuple[int, int] | None:
        """(value, index after) of a number written at token i: digits, words, "a dozen", "twenty five"."""
        if i >= self.n:
            return None
        w = self.low[i].replace(",", "")
        if w.isdigit():
            value, j = int(w), i + 1
            if j < self.n and self.low[j] in lx.SCALES:  # "10 million people": read, so it can be refused
                value, j = value * lx.SCALES[self.low[j]], j + 1
        elif w in lx.UNITS or w in lx.TENS:
            total, current, j = 0, 0, i
            while j < self.n:
                x = self.low[j]
                if x in lx.UNITS:
                    current += lx.UNITS[x]
                elif x in lx.TENS:
                    current += lx.TENS[x]
                elif x == "-" and j + 1 < self.n and self.low[j + 1] in lx.UNITS and current % 10 == 0 and current:
                    pass  # "twenty-five"
                elif x in lx.SCALES and (current or total):
                    current = max(current, 1) * lx.SCALES[x]
                    if x in lx.BIG_SCALES:
                        total, current = total + current, 0
                elif x == "and" and j + 1 < self.n and self.low[j + 1] in lx.UNITS and current >= 100:
                    pass
                else:
                    break
                j += 1
            value = total + current
        elif w == "dozen":
            value, j = 12, i + 1
        elif w in ("a", "an") and i + 1 < self.n and (self.low[i + 1] == "dozen" or self.low[i + 1] in lx.SCALES):
            # "a thousand", "a billion people": read as numbers, so check_population refuses them.
            value, j = (12 if self.low[i + 1] == "dozen" else lx.SCALES[self.low[i + 1]]), i + 2
        elif w == "half" and tuple(self.low[i + 1:i + 3]) == ("a", "dozen"):
            value, j = 6, i + 3  # "half a dozen"
        else:
            return None
        if j < self.n and self.low[j] == "dozen" and w != "dozen":
            value, j = value * 12, j + 1
        return value, j

    def _is_person_noun(self, i: int) -> bool:
        lem = self._lemma(i)
        if lem in lx.NON_PEOPLE and lem not in lx.PERSON_NOUNS:
            return False
        if lem in lx.PERSON_NOUNS or self.low[i] in lx.PERSON_NOUNS or self._multiword_end(i):
            return True
        if self._subject_of_a_human_verb(i) or self._agent_subject(i):
            return True
        # A misspelt word for people ("childern", "passangers"): one edit from a person noun, long
        # enough that the edit cannot turn one real word into another, no name of the world, and no
        # word of the parser's English vocabulary ("posters" is one edit from "porters", but a word).
        # The parser may call such a word a verb after a number ("Five colleages stroll"): a count
        # is followed by what it counts.
        counted = i > 0 and self.w[i - 1].pos == "NUM"
        if i > 0 and self.low[i - 1] in lx.ROBOT_WORDS:
            return False  # "the robot glides": the robot's verb, however close to "guides"
        return (len(self.low[i]) >= 6 and (self.w[i].pos in ("NOUN", "PROPN") or counted) and not self.index.knows(lem)
                and not known_word(self.low[i]) and _near_person_noun(self.low[i]) is not None)

    def _multiword_end(self, i: int) -> bool:
        """Whether word i ends a person named by two words ("au pair", "station master")."""
        if self.low[i] not in _MULTIWORD_LAST:
            return False  # asked for every word the reader looks at: the common answer first
        return any(i - len(p) + 1 >= 0 and tuple(self.low[i - len(p) + 1:i + 1]) == p for p in lx.MULTIWORD_PEOPLE)

    def _multiword_start(self, i: int) -> int | None:
        """The last word of a person named by two words starting at i, else None."""
        for p in lx.MULTIWORD_PEOPLE:
            if tuple(self.low[i:i + len(p)]) == p:
                return i + len(p) - 1
        return None

    def _agent_subject(self, i: int) -> bool:
        """A noun for someone who does something ("a busker strums", "the florist arranges"), in no
        list: the parser's subject of a verb that things do not do, ending like an agent noun, and
        no place, robot, thing or time word."""
        word = self.w[i]
        if word.pos not in ("NOUN", "PROPN") or word.dep != "nsubj" or word.head == i:
            return False
        lem = self._lemma(i)
        head = self.w[word.head]
        verb = self._verb(word.head)
        # Not after a verb things do as well ("the sprinklers go off", "the heater stays on").
        return (lem.endswith(lx.AGENT_SUFFIXES) and len(lem) >= 5 and head.pos == "VERB"
                and verb not in lx.THING_VERBS and verb not in lx.INTENT_VERBS and verb not in ("be", "go", "start")
                and not self.index.knows(lem)
                and lem not in lx.ROBOT_WORDS and lem not in lx.NON_PLACES and lem not in lx.NON_PEOPLE
                and lem not in lx.BUILDING_WORDS and lem not in lx.DURATION_UNITS and lem not in lx.HAZARD_NOUNS)

    def _subject_of_a_human_verb(self, i: int) -> bool:
        """A noun no list names, the parser's subject of a verb only people do ("a sommelier
        chats", "two botanists stroll"): a person, unless it names a place, the robot, a group
        word, a time or a hazard."""
        word = self.w[i]
        parsed = word.pos in ("NOUN", "PROPN") and word.dep == "nsubj" and word.head != i and \
            self.w[word.head].pos == "VERB" and self._verb(word.head) in lx.HUMAN_SUBJECT_VERBS
        # The parser may also take the noun for an adjective and the verb for a plural noun ("a
        # sommelier chats"): a determiner or number, the word, then a human verb's "-s" form.
        nxt = i + 1
        mistagged = (0 < i and nxt < self.n and word.pos in ("NOUN", "PROPN", "ADJ")
                     and self.w[i - 1].pos in ("DET", "NUM") and verb_lemma(self.low[nxt]) in lx.HUMAN_SUBJECT_VERBS
                     and self.low[nxt] != verb_lemma(self.low[nxt]) and self.low[nxt].endswith("s"))
        if not (parsed or mistagged):
            return False
        lem = self._lemma(i)
        return (lem.isalpha() and not self.index.knows(lem) and lem not in lx.ROBOT_WORDS
                and lem not in lx.NON_PLACES and lem not in lx.IMPLIED_RANGES and lem not in lx.HAZARD_NOUNS
                and lem not in lx.BUILDING_WORDS and lem not in lx.DURATION_UNITS)

    # -- mentions ----------------------------------------------------------------------------

    def _subject_position(self, s: int) -> bool:
        if s == 0:
            return True
        p = s - 1
        prev = self.low[p]
        if self._is_punct(p) or self.w[p].sentence != self.w[s].sentence:
            return True
        if prev == "with" and self._conversation_partner(p, s):
            return False
        if prev == "with" and self.low[s] in ("their", "his", "her", "its", "our", "my"):
            return False  # "families wait at the gate with their children": the families' own members
        if prev in lx.CLAUSE_STARTERS or prev in lx.EXCEPT_WORDS or prev == "than":
            return True
        if self._led_by(s):
            return True  # "a tour guide leads twelve tourists": a counted group the subject takes along
        if prev == "instead" and self.low[s] != "of":
            return True  # "nobody waits there; instead eight patients queue ..."
        if prev == "for" and p > 0 and self.low[p - 1] in lx.EXCEPT_WORDS:
            return True  # "empty except for two cleaners"
        if prev == "from" and p > 0 and self.low[p - 1] == "apart":
            return True  # "apart from one guard"
        if prev == "by" and p > 0 and self.low[p - 1] in ("followed", "trailed", "accompanied", "joined"):
            return True  # "the manager walks to the boardroom, followed by two assistants"
        if prev in ("are", "is") and self._only_people_before(p):
            return True  # "the only people in the ward are two men"
        if prev in ("are", "is", "were", "was", "be", "'s", "’s", "'re", "’re") and p > 0 and self.low[p - 1] == "there":
            return True
        if verb_lemma(prev) in lx.SCENE_VERBS and (p == 0 or self._is_punct(p - 1) or self.low[p - 1] in
                                                   lx.CLAUSE_STARTERS | {"please", "to", "let's", "lets"}):
            return True
        if prev == "by" and self.w[p].dep == "agent":
            return True  # "the balcony is used by a smoker": the passive's doer
        if prev == "of" and self._event_before(p):
            return True  # "the boardroom meeting of twelve people breaks up"
        return self._parser_subject(s)

    def _parser_subject(self, s: int) -> bool:
        """Whether the phrase at s is the subject the parser found ("At six the staff head out"):
        determiners, numbers and adjectives, then a person noun the parser calls the subject."""
        if s > 0 and self.w[s - 1].pos in ("DET", "ADJ", "NUM") and not (
                self.w[s - 1].pos == "NUM" and self.w[s - 1].head < s - 1 and self.low[s] in lx.DETERMINERS):
            return False  # inside a noun phrase that starts earlier ("the only people"); not "At 8:15 the ..."
        if s > 0 and self.w[s - 1].pos == "SCONJ" and self.low[s - 1] not in lx.CLAUSE_STARTERS:
            return False  # "... until someone collects them", "if anyone asks": nobody who is there
        for k in range(s, min(s + 5, self.n)):
            if self.low[k] in lx.NOBODY_WORDS:
                return False
            if self._is_person_noun(k):
                head = self.w[k].head
                # the small model may tag the verb a noun ("the commuters on platform 1 walk to ...")
                return self.w[k].dep in ("nsubj", "nsubjpass") and (self.w[head].pos in ("VERB", "AUX") or (
                    head > k and verb_lemma(self.low[head]) in lx.INTENT_VERBS and not self.index.knows(self._lemma(head))))
            if self.w[k].pos not in ("DET", "NUM", "ADJ") and self.low[k] not in lx.NP_MODIFIERS:
                return False
        return False

    def _event_before(self, of: int) -> bool:
        """Whether "of" closes a subject noun phrase of no people ("the boardroom meeting of ..."):
        nouns and adjectives back to a determiner at a subject position."""
        k = of - 1
        if k < 0 or self.w[k].pos not in ("NOUN", "PROPN") or self._is_person_noun(k) or \
                self._lemma(k) in lx.IMPLIED_RANGES or self._number_at(k) is not None:
            return False
        while k > 0 and self.w[k - 1].pos in ("NOUN", "PROPN", "ADJ") and not self._is_punct(k - 1):
            k -= 1
        if k > 0 and self.low[k - 1] in ("the", "a", "an", "this", "that"):
            k -= 1
        return self._subject_position(k) if self.low[k - 1:k] != ["of"] else False

    def _mentions(self) -> list[_Mention]:
        found: list[_Mention] = []
        i = 0
        while i < self.n:
            if i in self.no_mention or not self._subject_position(i):
                i += 1
                continue
            m = self._mention_at(i, found)
            if m is None:
                i += 1
                continue
            if found and found[-1].whole_zone and found[-1].relation is None and m.relation is None and \
                    self._after_except(m.first):
                m.exception_of = len(found) - 1  # "everyone in the hall leaves except two guards"
            found.append(m)
            i = m.last + 1
        return found

    def _skip(self, j: int, words: set[str] | frozenset[str]) -> int:
        while j < self.n and self.low[j] in words:
            j += 1
        return j

    def _person_head(self, j: int, *, counted: bool) -> int | None:
        """Index of the person noun of a phrase starting at j ("tired old patients"), or None.

        With a count before it, any plural noun counts ("ten zombies"), unless it names a place,
        a time or a thing of the world."""
        k = j
        while k < self.n and k < j + 4:
            if self.low[k] in lx.ROBOT_WORDS:
                return None  # "the robot glides": whatever follows, the robot is nobody's kind
            end = self._multiword_start(k)
            if end is not None:
                return end  # "the au pair": one person
            if self._is_person_noun(k) and self._does_only_what_things_do(k):
                return None  # "two fans whir in the server room"
            if self._is_person_noun(k) and self.w[k].pos == "ADJ" and k + 1 < self.n and \
                    self.w[k + 1].pos in ("NOUN", "PROPN") and self.w[k + 1].dep != "ROOT" and \
                    (self._is_person_noun(k + 1) or self._lemma(k + 1) in lx.IMPLIED_RANGES):
                k += 1  # "an elderly couple", "a young nurse": the word is an adjective here
                continue
            if self._is_person_noun(k) and self._modifies_next_noun(k):
                return None  # "the outpatient clinic", "security alert": a thing named after people
            if self._is_person_noun(k) or (self._lemma(k) in lx.IMPLIED_RANGES and k + 1 < self.n
                                           and self.low[k + 1] == "of"):
                # ("a queue of eight people": the collective heads the phrase)
                while k + 1 < self.n and self._is_person_noun(k + 1) and self._lemma(k + 1) not in lx.IMPLIED_RANGES \
                        and not self.w[k + 1].tag.startswith("VB") and not (
                            not counted and k + 2 < self.n and self.w[k + 2].pos in ("ADP", "DET", "PUNCT")):
                    # "staff members", "security guards": the last noun heads the phrase; but in "Mum
                    # cooks in the kitchen" the second word is the verb
                    k += 1
                return k
            if self.low[k] in lx.NP_MODIFIERS or self.w[k].pos == "ADJ":
                k += 1
                continue
            if self.w[k].pos in ("NOUN", "PROPN") and k + 1 < self.n and self._is_person_noun(k + 1):
                k += 1  # "flight attendants", "dog walker": a noun naming the kind of person
                continue
            if (counted and self.w[k].tag in ("NNS", "NNPS") and self._lemma(k) not in lx.NON_PLACES
                    and self._lemma(k) not in lx.NON_PEOPLE
                    and self._lemma(k) not in lx.DURATION_UNITS and not self.index.knows(self._lemma(k))
                    and verb_lemma(self.low[k]) not in lx.INTENT_VERBS and self._does_what_people_do(k)):
                return k
            return None
        return None

    def _does_what_people_do(self, k: int) -> bool:
        """Whether a counted noun no list names is the subject of something people do ("ten zombies
        shamble to the exit", "five volunteers hand out leaflets"), not a thing that only is or
        hangs somewhere ("two posters hang in the lobby", "three clocks tick")."""
        head = self.w[k].head
        if self.w[k].dep not in ("nsubj", "nsubjpass") or head == k:
            return True  # the parser gives no verb to judge by: keep the count's reading
        verb = self._verb(head)
        return verb not in lx.THING_VERBS

    def _does_only_what_things_do(self, k: int) -> bool:
        """Whether a person word is the parser's subject of a verb only things do, with no object
        ("two fans whir", not "two nurses hang the posters")."""
        word = self.w[k]
        if word.dep not in ("nsubj", "nsubjpass") or word.head == k or self.w[word.head].pos != "VERB":
            return False
        has_object = any(w.head == word.head and w.dep in ("dobj", "obj") for w in self.w)
        verb = self._verb(word.head)
        return verb in lx.THING_VERBS and verb not in lx.INTENT_VERBS and not has_object  # "line up" is people

    def _modifies_next_noun(self, k: int) -> bool:
        """Whether a person noun only modifies the noun after it ("outpatient clinic", "staff room"):
        that noun is no person, no collective and no verb the lexicon knows, and the parser does not
        make it the sentence's verb ("Mum cooks dinner")."""
        if k + 1 >= self.n:
            return False
        nxt, word = self.w[k + 1], self.low[k + 1]
        if word in ("'s", "’s", "'") or nxt.tag == "POS":
            return True  # "the manager's office"
        if k > 0 and self.w[k - 1].pos == "NUM" and self._lemma(k) != self.low[k] and \
                not self.index.knows(self._lemma(k + 1)) and k + 2 < self.n and \
                self.w[k + 2].pos in ("NOUN", "DET", "ADP", "PRON"):
            return False  # "two interns lug boxes from ...": after a count, the next word is the verb
        # The parser may make the noun after a singular person word the sentence's verb: "Mum cooks"
        # is one, "Security alert:" is not.
        verb_like = (nxt.dep == "ROOT" and (word.endswith("s") or self._lemma(k) != self.low[k])) or \
            self._third_person_verb(k + 1)
        gerund_noun = nxt.tag == "NN" and word.endswith("ing")  # "the team meeting", not "nurses meeting"
        return (nxt.pos == "NOUN" and not verb_like and not nxt.tag.startswith("VB")
                and not self._is_person_noun(k + 1) and self._lemma(k + 1) not in lx.IMPLIED_RANGES
                and (gerund_noun or (verb_lemma(word) not in lx.INTENT_VERBS and verb_lemma(word) not in lx.ROBOT_VERBS))
                and self._lemma(k + 1) not in lx.DURATION_UNITS)

    def _third_person_verb(self, i: int) -> bool:
        """Whether the word at i, which the parser may tag a plural noun, is the verb of the singular
        person noun before it: "a cleaner mops the corridor", "a cleaner mops near the toilets"
        (an "-s" word between a singular person and a determiner, preposition or the end)."""
        if i < 1 or i >= self.n or not self.low[i].endswith("s") or self.low[i].endswith("ss"):
            return False
        before = i - 1
        if not self._is_person_noun(before) or self._lemma(before) != self.low[before] or \
                self.index.knows(self._lemma(i)) or self._is_person_noun(i):
            return False
        after = self.w[i + 1] if i + 1 < self.n else None
        return after is None or after.pos in ("DET", "ADP", "ADV", "PUNCT") or self.low[i + 1] in lx.DETERMINERS

    def _conversation_partner(self, p: int, s: int) -> bool:
        """Whether the phrase at s, after "with" at p, is who a person talks or walks with, not a
        group of its own: one person with no number ("chats with the driver"); "with two friends"
        still names a group."""
        if p < 1 or verb_lemma(self.low[p - 1]) not in lx.INTENT_VERBS | lx.ROBOT_VERBS.keys():
            return False
        k = self._skip(s, {"the", "a", "an", "his", "her", "their", "its", "my", "our", "your"})
        if k == s:
            return False
        while k < self.n and (self.w[k].pos == "ADJ" or self.low[k] in lx.NP_MODIFIERS) and not self._is_person_noun(k):
            k += 1
        if k + 1 < self.n and self.w[k].pos in ("NOUN", "PROPN") and self._is_person_noun(k + 1):
            k += 1  # "the train driver"
        return k < self.n and self._is_person_noun(k) and self._lemma(k) == self.low[k] and \
            self._lemma(k) not in lx.IMPLIED_RANGES

    def _mention_at(self, s: int, found: list[_Mention]) -> _Mention | None:
        low = self.low
        if low[s] in ("the", "these", "those", "all", "its", "their", "our", "his", "her", "my", "your") and \
                s + 1 < self.n and self._number_at(s + 1) is not None:
            inner = self._mention_at(s + 1, found)  # "the four people in the living room"
            if inner is not None:
                inner.first = s
                inner.who = self._span(s, inner.last)
            return inner
        j = s
        exclusive = self._exclusive_context(s)
        # Relations: "one of them", "two of the patients", "some of them"
        num = self._quantifier(j)
        # "a few of" is read with its "of" by the quantifier; "two of" leaves it
        of_at = num[2] if num is not None and num[2] < self.n and low[num[2]] == "of" else (
            num[2] - 1 if num is not None and low[num[2] - 1] == "of" else None)
        if of_at is not None and of_at + 1 < self.n:
            k = of_at + 1
            if low[k] in ("them", "those", "these", "us", "whom") or (low[k] == "the" and k + 1 < self.n and
                                                                   self._is_person_noun(k + 1)):
                last = k if low[k] != "the" else k + 1
                parent = self._parent(found)
                label = found[parent].label if parent is not None else self._lemma(last)
                count = self._count_from_quantifier(num, f"{s}", lx.OTHERS_RANGE)
                return _Mention(s, last, self._span(s, last), label, count,
                                relation=f"subset_of:{parent}" if parent is not None else None)
        # "the others", "the rest", "everyone else"
        j = self._skip(s, {"the"})
        if j < self.n and low[j] in ("others", "rest") and (j == s or low[s] == "the"):
            last = j + 2 if j + 2 < self.n and low[j + 1] == "of" and low[j + 2] in ("them", "us", "the") else j
            parent = self._parent(found, plain=True)
            label = found[parent].label if parent is not None else "person"
            if low[s] == "the" and parent is not None and any(m.relation == f"subset_of:{parent}" for m in found):
                return _Mention(s, last, self._span(s, last), label, None, relation=f"others_of:{parent}",
                                rest_of_parent=True)
            low_, high_ = lx.OTHERS_RANGE
            count = Count("vague", self._choose(low_, high_, f"{s}:others"), low_, high_)
            return _Mention(s, last, self._span(s, last), label, count,
                            relation=f"others_of:{parent}" if parent is not None else None)
        if low[s] in ("everyone", "everybody") and s + 1 < self.n and low[s + 1] == "else":
            parent = self._parent(found)
            label = found[parent].label if parent is not None else "person"
            return _Mention(s, s + 1, self._span(s, s + 1), label, None,
                            relation=f"others_of:{parent}" if parent is not None else None, rest_of_parent=True)
        if low[s] == "the" and s + 1 < self.n and low[s + 1] == "only":
            return None  # "the only people in the ward are two men": the men are the group
        if low[s] == "every" and s + 1 < self.n:
            head = self._person_head(s + 1, counted=False)
            if head is not None:  # "every visitor in the lounge": everyone there
                return _Mention(s, head, self._span(s, head), self._label(head), None, whole_zone=True)
        if low[s] == "half" and s + 1 < self.n:
            half = self._half_of(s)
            if half is not None:
                return half
        # Whole zone: "everyone", "everybody", "all the people", "all patients"
        if low[s] in ("everyone", "everybody") or (low[s] == "all" and not (num and num[0] > 0 and num[1] == "all")):
            last = s
            label = "person"
            if low[s] == "all":
                k = self._skip(s + 1, {"the", "of"})
                n_after = self._number_at(k)
                if n_after is not None:  # "all ten patients": a plain count
                    head = self._person_head(n_after[1], counted=True)
                    if head is not None:
                        return _Mention(s, head, self._span(s, head), self._label(head),
                                        Count("exact", n_after[0], n_after[0], n_after[0]))
                head = self._person_head(k, counted=False)
                if head is None:
                    return None
                last, label = head, self._label(head)
            return _Mention(s, last, self._span(s, last), label, None, whole_zone=True)
        # Someone, somebody, a person
        if low[s] in ("someone", "somebody", "anyone", "anybody"):
            return _Mention(s, s, self.w[s].text, "person", Count("exclusive" if exclusive else "exact", 1, 1, 1),
                            exclusive=exclusive)
        # "a few more", "two more patients", "another nurse"
        if low[s] == "another":
            head = self._person_head(s + 1, counted=False)
            parent = self._parent(found, plain=True)
            if head is not None and self._lemma(head) in lx.IMPLIED_RANGES:
                collective = self._collective(head, None, s)  # "another group": a group's size, not one
                if collective is not None:
                    collective.relation = f"more_of:{parent}" if parent is not None else None
                    return collective
            last = head if head is not None else s
            label = self._label(head) if head is not None else (found[parent].label if parent is not None else "person")
            return _Mention(s, last, self._span(s, last), label, Count("exact", 1, 1, 1),
                            relation=f"more_of:{parent}" if parent is not None else None)
        if num is not None:
            value_part, after = num, num[2]
            if after < self.n and low[after] == "more":
                parent = self._parent(found, plain=True)
                head = self._person_head(after + 1, counted=True)
                last = head if head is not None else after
                label = self._label(head) if head is not None else (found[parent].label if parent is not None else "person")
                return _Mention(s, last, self._span(s, last), label, self._count_from_quantifier(value_part, f"{s}:more"),
                                relation=f"more_of:{parent}" if parent is not None else None)
            if after < self.n and low[after] in ("others", "other"):
                parent = self._parent(found, plain=True)
                head = self._person_head(after + 1, counted=False) if low[after] == "other" else None
                if low[after] == "other" and head is None:
                    return None
                last = head if head is not None else after
                label = self._label(head) if head is not None else (found[parent].label if parent is not None else "person")
                return _Mention(s, last, self._span(s, last), label,
                                self._count_from_quantifier(value_part, f"{s}:others", lx.OTHERS_RANGE),
                                relation=f"others_of:{parent}" if parent is not None else None)
            return self._counted(s, value_part, found, exclusive)
        # Bare phrases: "visitors", "the nurses", "a nurse", "other visitors", "people"
        k = self._skip(s, {"the", "a", "an", "other", "their", "his", "her", "our", "its"})
        det = low[s] if k > s else ""
        other = "other" in low[s:k]
        head = self._person_head(k, counted=False)
        if head is None:
            # "ten in the pharmacy": a bare number borrowing the last group's noun is handled in _counted
            return None
        singular = self._lemma(head) == low[head] and low[head] not in ("people", "staff", "police", "crowd")
        label = self._label(head)
        if det == "the" and any(m.label == label or self._lemma(head) == m.label for m in found):
            return None  # "... one person; the person wanders around": the same people again
        noun = self._lemma(head)
        collective = self._collective(head)
        if collective is not None:
            return collective
        if det in ("a", "an") or (singular and det == "the"):
            kind = "exclusive" if exclusive else "exact"
            return _Mention(s, head, self._span(s, head), label, Count(kind, 1, 1, 1), exclusive=exclusive)
        if singular and noun not in lx.GENERIC_PEOPLE and not other:
            if (self._verb_after(head) or self._after_except(s) or self._coordinated_person(head)) \
                    and noun not in lx.PRONOUN_PEOPLE \
                    and noun not in lx.NOBODY_WORDS:  # "everyone except grandma": the exception, named
                return _Mention(s, head, self._span(s, head), label, Count("exclusive" if exclusive else "exact", 1, 1, 1),
                                exclusive=exclusive)  # "Mum cooks in the kitchen": one person, named by a role
            return None  # "staff" as a verb-less word, or a singular without determiner: not a subject
        low_, high_ = lx.OTHERS_RANGE if other else lx.BARE_PLURAL_RANGE
        parent = self._parent(found)
        relation = f"others_of:{parent}" if other and parent is not None else None
        if noun in lx.FAMILY_PLURALS and not other and (det == "the" or low[s] in ("their", "his", "her", "our", "my")):
            low_, high_ = lx.FAMILY_PLURALS[noun]  # "the parents": the two of one family
            return _Mention(s, head, self._span(s, head), label,
                            Count("implied", self._choose(low_, high_, f"{s}:family"), low_, high_))
        return _Mention(s, head, self._span(s, head), label,
                        Count("vague", self._choose(low_, high_, f"{s}:bare"), low_, high_), relation=relation)

    def _half_of(self, s: int) -> _Mention | None:
        """"half the open office", "half of the patients in the lobby": half of everyone in a zone
        (the zone named right there, or by the clause)."""
        k = self._skip(s + 1, {"of"})
        k = self._skip(k, {"the", "all"})
        if k == s + 1 or k >= self.n:
            return None  # "half an hour", "half a dozen" are read elsewhere
        head = self._person_head(k, counted=False)
        if head is not None:
            return _Mention(s, head, self._span(s, head), self._label(head), None, whole_zone=True, fraction=0.5)
        place = self._place_phrase(k, "in", s, record_unknown=False)
        if place is None or place.match is None or place.match.kind != "zone":
            return None
        return _Mention(s, place.end - 1, self._span(s, place.end - 1), "person", None, whole_zone=True,
                        fraction=0.5, zone_place=place)

    def _led_by(self, s: int) -> bool:
        """Whether the phrase at s is the counted object of a verb of leading right after a person
        ("a tour guide leads twelve tourists", "two nurses escort five patients")."""
        p = s - 1
        return p >= 1 and verb_lemma(self.low[p]) in lx.LEADING_VERBS and self._is_person_noun(p - 1) and \
            self._number_at(s) is not None and self._number_at(s)[0] > 1

    def _coordinated_person(self, head: int) -> bool:
        """Whether a person word is joined by "and" to another person phrase ("Mum and two kids
        walk", "Mum and Dad chat"): the first of two subjects, though no verb follows it."""
        if head + 2 >= self.n or self.low[head + 1] != "and":
            return False
        q = self._quantifier(head + 2)
        start = q[2] if q is not None else self._skip(head + 2, lx.DETERMINERS)
        return start < self.n and self._person_head(start, counted=q is not None) is not None

    def _after_except(self, s: int) -> bool:
        """Whether the phrase at s follows a word of exception ("except", "apart from", "other than")."""
        prev = self.low[s - 1] if s > 0 else ""
        before = self.low[s - 2] if s > 1 else ""
        return prev in lx.EXCEPT_WORDS - {"but"} or (prev == "from" and before == "apart") or \
            (prev == "than" and before == "other") or (prev == "for" and before in lx.EXCEPT_WORDS)

    def _only_people_before(self, p: int) -> bool:
        sentence = self.w[p].sentence
        return any(self.low[k] == "only" and k + 1 < self.n and self.low[k + 1] in ("people", "person", "ones", "one")
                   for k in range(p) if self.w[k].sentence == sentence)

    def _verb_after(self, k: int) -> bool:
        """Whether the word after k is a verb (so the word at k is the subject of a clause)."""
        if k + 1 >= self.n:
            return False
        nxt = self.low[k + 1]
        # the small model tags "cooks" in "Mum cooks in the kitchen" as a plural noun, but as the root
        return (self.w[k + 1].tag in ("VBZ", "VBP", "VBD") or self.w[k + 1].dep == "ROOT" or self._third_person_verb(k + 1)
                or (verb_lemma(nxt) in lx.INTENT_VERBS and nxt != verb_lemma(nxt)) or nxt in ("is", "are", "was", "were"))

    def _exclusive_context(self, s: int) -> bool:
        """Whether the phrase at s is the exception to "nobody" in its sentence ("nobody ... except one
        guard", "apart from two pilots, nobody is ...", "the only people in X are two men")."""
        sentence = self.w[s].sentence
        words_ = [k for k in range(self.n) if self.w[k].sentence == sentence]
        saw_nobody = any(self.low[k] in lx.NOBODY_WORDS or (self.low[k] == "no" and k + 1 < self.n and
                                                           self.low[k + 1] in ("one", "people", "person", "body"))
                         or self.low[k] in ("empty", "deserted") for k in words_)
        near = [self.low[k] for k in words_ if k < s][-2:]
        if near[-1:] in (["are"], ["is"]) and self._only_people_before(s - 1):
            return True
        return saw_nobody and (any(x in lx.EXCEPT_WORDS for x in near) or near[-1:] == ["than"]
                               or near == ["apart", "from"])

    def _parent(self, found: list[_Mention], *, plain: bool = False) -> int | None:
        """The group a relation refers to: the last one that is not itself a subset ("one of them"),
        or with `plain` the last one with no relation at all ("the others", "a few more")."""
        for k in range(len(found) - 1, -1, -1):
            relation = found[k].relation or ""
            if not relation.startswith("subset_of") and not (plain and relation):
                return k
        return None

    def _label(self, head: int | None) -> str:
        if head is None:
            return "person"
        noun = self._lemma(head)
        if noun not in lx.PERSON_NOUNS and len(self.low[head]) >= 6 and not known_word(self.low[head]):
            noun = _near_person_noun(self.low[head]) or noun  # "nurzes" -> nurse, but "posters" stays
        if self._multiword_end(head):
            return next(" ".join(p) for p in lx.MULTIWORD_PEOPLE if tuple(self.low[head - len(p) + 1:head + 1]) == p)
        if noun in ("member", "person") and head > 0 and self._is_person_noun(head - 1):
            noun = self._lemma(head - 1)  # "staff members", "family members"
        if noun in lx.GENERIC_PEOPLE or noun in lx.NUMBER_WORDS or noun in lx.PRONOUN_PEOPLE:
            return "person"
        return noun

    def _span(self, a: int, b: int) -> str:
        return self.prompt[self.w[a].start:self.w[b].end]

    def _quantifier(self, j: int) -> tuple[int, str, int, int | None] | None:
        """(value or 0, kind, index after, high) of a count expression at j.

        kind: "exact" | "approximate" | "vague:<word>" | "range" | "one" (a/an)."""
        low = self.low
        if j >= self.n:
            return None
        approx = False
        k = j
        if low[k] in lx.APPROXIMATE_WORDS and k + 1 < self.n and self._number_at(k + 1) is not None:
            approx, k = True, k + 1
        else:
            for phrase in lx.APPROXIMATE_PHRASES:
                if tuple(low[k:k + len(phrase)]) == phrase and self._number_at(k + len(phrase)) is not None:
                    approx, k = True, k + len(phrase)
                    break
        if low[k] == "between" and self._number_at(k + 1):
            a = self._number_at(k + 1)
            if a[1] < self.n and low[a[1]] == "and" and self._number_at(a[1] + 1):
                b = self._number_at(a[1] + 1)
                return (a[0], "range", b[1], b[0])
        num = self._number_at(k)
        if num is not None:
            value, after = num
            if tuple(low[after:after + 2]) == ("or", "so"):
                return (value, "approximate", after + 2, None)  # "fifteen or so women"
            if after < self.n and low[after] == "odd":
                return (value, "approximate", after + 1, None)  # "twenty-odd customers"
            if tuple(low[after:after + 2]) == ("-", "odd"):
                return (value, "approximate", after + 2, None)
            if after + 1 < self.n and low[after] in ("to", "-", "or") and self._number_at(after + 1):
                b = self._number_at(after + 1)
                if b[0] > value:
                    return (value, "range", b[1], b[0])
            return (value, "approximate" if approx else "exact", after, None)
        if low[k] in ("a", "an") and k + 1 < self.n:
            nxt = low[k + 1]
            if nxt == "couple" and tuple(low[k + 2:k + 4]) == ("of", "dozen"):
                return (24, "approximate", k + 4, None)  # "a couple of dozen tourists": about 24
            if nxt in ("couple", "pair") and k + 2 < self.n and low[k + 2] == "of":
                return (2, "exact", k + 3, None)
            if nxt in ("few", "handful", "number", "lot") :
                after = k + 2
                if after < self.n and low[after] == "of":
                    after += 1
                return (0, f"vague:{nxt}", after, None)
            return None
        if low[k] in ("few", "several", "some", "many", "lots", "dozens", "various", "multiple", "numerous", "scores",
                      "hundreds"):
            after = k + 1
            if after < self.n and low[after] == "of" and low[k] in ("lots", "dozens", "scores", "hundreds"):
                after += 1
            return (0, f"vague:{low[k]}", after, None)
        return None

    def _count_from_quantifier(self, q: tuple[int, str, int, int | None], key: str,
                               default: tuple[int, int] = lx.BARE_PLURAL_RANGE) -> Count:
        value, kind, _, high = q
        if kind == "exact":
            return Count("exact", value, value, value)
        if kind == "approximate":
            spread = max(1, round(value * lx.APPROXIMATE_SPREAD))
            return Count("approximate", value, max(1, value - spread), value + spread)
        if kind == "range":
            return Count("vague", self._choose(value, high or value, key), value, high or value)
        word = kind.split(":", 1)[1]
        low_, high_ = lx.VAGUE_RANGES.get(word, default)
        return Count("vague", self._choose(low_, high_, key), low_, high_)

    def _collective(self, head: int, number: tuple | None = None, first: int | None = None) -> _Mention | None:
        """Mentions built on a collective noun: "a family", "two families of three", "a group of nurses"."""
        noun = self._lemma(head)
        if noun not in lx.IMPLIED_RANGES or self._multiword_end(head):
            return None  # "the au pair" is no pair
        low = self.low
        s = first if first is not None else head
        while s > 0 and first is None and (low[s - 1] in ("a", "an", "the") or low[s - 1] in lx.NP_MODIFIERS
                                           or (self.w[s - 1].pos == "ADJ" and s > 1 and self.w[s - 2].pos == "DET")):
            s -= 1  # "a long queue of ...": the adjective is the collective's
        parties = 1
        exact_parties = True
        if number is not None:
            value, kind, _, high = number
            if kind in ("exact", "approximate") and value > 1:
                parties = value
            elif kind.startswith("vague") or kind == "range":
                c = self._count_from_quantifier(number, f"{head}:parties")
                parties, exact_parties = c.value, False
        together = noun in lx.TOGETHER_COLLECTIVES
        last = head
        size: tuple[int, int] | None = None
        label = noun
        if head + 2 < self.n and low[head + 1] == "of":
            inner = self._number_at(head + 2)
            loose = self._quantifier(head + 2)
            if loose is not None and loose[1] in ("approximate", "range") and parties == 1 and exact_parties:
                # "a queue of about thirty passengers", "a crowd of 80 to 100 fans": the people inside
                # the collective, counted loosely
                member = self._person_head(loose[2], counted=True)
                last = member if member is not None and member <= loose[2] + 2 else loose[2] - 1
                if member is not None and noun not in lx.TOGETHER_COLLECTIVES | lx.QUEUE_COLLECTIVES:
                    label = self._label(member)
                elif member is not None and noun in ("group", "crowd", "bunch", "party", "team", "queue", "line"):
                    label = self._label(member)
                mention = _Mention(s, last, self._span(s, last), label,
                                   self._count_from_quantifier(loose, f"{head}:inside"), together=together)
                mention.collective = noun
                return mention
            if inner is not None:
                size = (inner[0], inner[0])
                last = inner[1] - 1
                member = self._person_head(inner[1], counted=True)
                if member is not None and member <= inner[1] + 2:
                    last = member
                    if noun in ("group", "crowd", "bunch", "party", "team", "queue", "line", "class", "tour"):
                        label = self._label(member)
            else:
                member = self._person_head(self._skip(head + 2, {"the", "their", "our"}), counted=False)
                if member is not None:
                    last = member
                    if noun in ("group", "crowd", "bunch", "party", "team", "class", "tour", "delegation", "gang",
                                "couple", "pair", "handful"):
                        label = self._label(member)
        mention = self._collective_mention(noun, s, last, label, size, parties, exact_parties, together, head)
        mention.collective = noun
        return mention

    def _collective_mention(self, noun: str, s: int, last: int, label: str, size: tuple[int, int] | None,
                            parties: int, exact_parties: bool, together: bool, head: int) -> _Mention:
        if size is None and noun in lx.QUANTIFYING_COLLECTIVES and label != noun:
            # "a crowd of visitors": the collective only says how many, vaguely
            low_, high_ = lx.IMPLIED_RANGES[noun]
            return _Mention(s, last, self._span(s, last), label,
                            Count("vague", self._choose(low_, high_, f"{head}:{noun}"), low_, high_), together=together)
        if size is None:
            low_, high_ = lx.IMPLIED_RANGES[noun]
            party = self._choose(low_, high_, f"{head}:{noun}")
            if parties == 1:
                return _Mention(s, last, self._span(s, last), label,
                                Count("implied", party, low_, high_, *((1, party) if together else (None, None))),
                                together=together)
            value = parties * party
            return _Mention(s, last, self._span(s, last), label,
                            Count("structured", value, parties * low_, parties * high_, parties, party), together=together)
        if parties == 1 and exact_parties:
            return _Mention(s, last, self._span(s, last), label, Count("exact", size[0], size[0], size[0], 1, size[0]),
                            together=together)
        value = parties * size[0]
        return _Mention(s, last, self._span(s, last), label, Count("structured", value, value, value, parties, size[0]),
                        together=together)

    def _counted(self, s: int, q: tuple[int, str, int, int | None], found: list[_Mention],
                 exclusive: bool) -> _Mention | None:
        """A phrase that starts with a count: "ten patients", "about 20 people", "two families of three"."""
        after = q[2]
        if after < self.n and self.low[after] == "of":
            after += 1
            after = self._skip(after, {"the", "their", "our"})
        head = self._person_head(after, counted=True)
        if head is None:
            # "twenty people in the cafeteria and ten in the pharmacy": the number borrows the noun
            if (found and q[0] > 0 and after < self.n and (self.low[after] in lx.PLACE_PREPOSITIONS
                                                           or verb_lemma(self.low[after]) in lx.INTENT_VERBS)
                    and s > 0 and self.low[s - 1] not in ("at", "until", "till", "after", "before", "since")):
                label = found[-1].label
                return _Mention(s, after - 1, self._span(s, after - 1), label,
                                self._count_from_quantifier(q, f"{s}:ellipsis"))
            return None
        if q[1] == "exact" and q[0] == 1 and self._lemma(head) in lx.IMPLIED_RANGES and self.low[s] == "one":
            q = (1, "exact", q[2], None)
        collective = self._collective(head, q, s)
        if collective is not None:
            return collective
        count = self._count_from_quantifier(q, f"{s}:count")
        if exclusive:
            count = replace(count, kind="exclusive")
        return _Mention(s, head, self._span(s, head), self._label(head), count, exclusive=exclusive)

    # -- clauses ---------------------------------------------------------------------------

    def read(self) -> PromptReading:
        mentions = self._mentions()
        robot_clauses = self._robot_clauses(mentions)
        robot_tokens = {i for rc in robot_clauses for i in rc.tokens}
        robot = self._robot_reading(robot_clauses)
        if not mentions:
            evacuated = self._evacuated_zone_without_people()
            if evacuated is not None:
                return replace(evacuated, robot=robot)
            self._scan_unknown_places([i for i in range(self.n) if i not in robot_tokens])
            return PromptReading(self.prompt, (), tuple(dict.fromkeys(self.unknown)),
                                 ("no group of people found in the prompt",), robot=robot)
        # Each group owns its words up to the next mention; a sentence's words before its first
        # mention are its preamble, read for every group of that sentence.
        # A fronted phrase between two groups belongs to the one after it ("..., and from the office,
        # eight people walk ...", "...; for 90 seconds, two residents wait ...").
        starts = [mentions[0].first] + [self._fronted_start(mentions[k - 1].last, mentions[k].first)
                                        for k in range(1, len(mentions))]
        spans: list[tuple[int, int]] = []
        for k, m in enumerate(mentions):
            end = starts[k + 1] if k + 1 < len(mentions) else self.n
            sentence_end = next((i for i in range(m.last + 1, end) if self.w[i].sentence != self.w[m.first].sentence),
                                end)
            spans.append((starts[k], sentence_end))
        claimed = {i for a, b in spans for i in range(a, b)}
        preamble_of: dict[int, list[int]] = {}
        negated = self._negated_clause_tokens()
        for i in range(self.n):
            if i not in claimed and i not in negated and i not in robot_tokens:
                preamble_of.setdefault(self.w[i].sentence, []).append(i)
        # The robot's own clauses belong to no group: a group's places never come from them.
        mention_tokens = {i for m in mentions for i in range(m.first, m.last + 1)} | robot_tokens
        scenes = {}
        for s_, toks in preamble_of.items():
            # a clause about animals or things ("two goldfish swim in a tank") names no place to refuse
            first = next((i for i in toks if self.w[i].pos not in ("DET", "NUM") and self.low[i] not in
                          lx.NP_MODIFIERS), None)
            self.quiet = first is not None and self._lemma(first) in lx.NON_PEOPLE
            scenes[s_] = self._clause(toks, mention_tokens, scene=True)
            self.quiet = False
        # A sentence with no people ("Evacuate the pharmacy.") sets the scene of the sentences after it.
        with_people = {self.w[m.first].sentence for m in mentions}
        carried: _Clause | None = None
        for sentence in range(self.w[-1].sentence + 1):
            own = scenes.get(sentence)
            if carried is not None:
                scenes[sentence] = carried if own is None else replace(
                    own, places=carried.places + own.places, evacuate=own.evacuate or carried.evacuate,
                    intent=own.intent or carried.intent)
            if sentence not in with_people and own is not None:
                carried = scenes[sentence]
        clauses = [self._clause(list(range(a, b)), mention_tokens, robot_after=self._robot_clause_after(a, b, robot_clauses))
                   for a, b in spans]
        for k, m in enumerate(mentions):
            if m.zone_place is not None:  # "half the open office goes ...": where they are
                clauses[k].places.insert(0, m.zone_place)
        evacuation = any(self.low[i] in lx.EVACUATION_CUES or verb_lemma(self.low[i]) in lx.EVACUATION_CUES
                         or self._hazard(i) for i in range(self.n))
        # A group with no action of its own shares the next group's ("ten patients and two nurses walk out").
        for k in range(len(clauses) - 2, -1, -1):
            between = range(mentions[k].last + 1, mentions[k + 1].first)
            in_places = {x for p in clauses[k].places for x in range(p.index, p.end)}
            leftover = [x for x in between if x not in in_places and not self._is_punct(x)
                        and self.low[x] not in ("and", "as", "well", "plus", "with")]
            if not clauses[k].has_action and clauses[k + 1].has_action and mentions[k + 1].relation is None and \
                    not leftover and \
                    self.w[mentions[k].first].sentence == self.w[mentions[k + 1].first].sentence and \
                    not any(self.low[x] in (";", ".", ":") for x in between):
                own = clauses[k]
                shared = replace(clauses[k + 1], places=own.places + clauses[k + 1].places)
                clauses[k] = shared
        for k, m in enumerate(mentions):
            if m.exception_of != k - 1 or k == 0:
                continue
            in_places = {x for p in clauses[k - 1].places for x in range(p.index, p.end)}
            between = [x for x in range(mentions[k - 1].last + 1, m.first) if x not in in_places]
            if all(self.low[x] in lx.EXCEPT_WORDS | {"apart", "from", "for", "other", "than", ","} for x in between) \
                    and not clauses[k - 1].has_action and clauses[k].has_action:
                # "Everybody except the receptionist leaves": the verb is the everybody's; the
                # exception does not do it, so stays where it is
                clauses[k - 1] = replace(clauses[k], places=clauses[k - 1].places + clauses[k].places)
                clauses[k] = _Clause()
        for k, m in enumerate(mentions):
            if k > 0 and self._led_by(m.first) and mentions[k - 1].last == m.first - 2:
                # the leader takes the route the led group is said to take
                clauses[k - 1] = replace(clauses[k], places=clauses[k - 1].places + clauses[k].places,
                                         intent=clauses[k].intent or "walk", has_action=True)
        groups: list[GroupReading] = []
        for k, (m, clause) in enumerate(zip(mentions, clauses)):
            scene = scenes.get(self.w[m.first].sentence)
            groups.append(self._group(k, m, clause, scene, evacuation, self._own_span(spans[k], m, robot_tokens),
                                      groups))
        # "everyone has gone home (except ...)", "after everyone has left": people no longer there
        gone = [k for k, m in enumerate(mentions) if m.whole_zone and m.relation is None
                and self._already_gone(spans[k]) and len(mentions) > 1]
        if gone and not any(g.relation for g in groups):
            # "Everyone has gone home except two engineers": the everyone is no longer there
            for k in gone:
                self.notes = [n for n in self.notes if not n.startswith(f"'{groups[k].who}': ")]
                self.notes.append(f"'{groups[k].who}' have already left: they are not in the scenario")
            groups = [g for k, g in enumerate(groups) if k not in gone]
        return PromptReading(self.prompt, tuple(groups), tuple(dict.fromkeys(self.unknown)), tuple(self.notes),
                             robot=robot)

    def _own_span(self, span: tuple[int, int], m: _Mention, robot_tokens: set[int]) -> tuple[int, int]:
        """A group's span without a robot clause that ends it ("..., while a robot crosses the hall")."""
        end = next((i for i in range(m.last + 1, span[1]) if i in robot_tokens), span[1])
        while end > m.last + 1 and (self._is_punct(end - 1) or self.low[end - 1] in lx.CLAUSE_STARTERS):
            end -= 1
        return span[0], end

    # -- the robot ----------------------------------------------------------------------------

    def _robot_clauses(self, mentions: Sequence[_Mention]) -> list[_RobotClause]:
        """The clauses whose subject is the robot: "a (delivery) robot <verb> ...", "it <verb> ..." once
        the robot is named, "send / have the robot ...". Each runs to the next group's mention, the
        next clause about someone else, or the end of its sentence. A passive ("the robot is followed
        by ...") is the people's clause, not the robot's."""
        starts = {m.first for m in mentions}
        taken = {i for m in mentions for i in range(m.first, m.last + 1)}
        out: list[_RobotClause] = []
        i = 0
        while i < self.n:
            found = self._robot_subject(i, taken)
            if found is None:
                i += 1
                continue
            first, verb, command = found
            end = self._robot_clause_end(verb if verb is not None else i + 1, starts)
            out.append(_RobotClause(list(range(first, end)), verb, command))
            i = end
        return out

    def _robot_subject(self, i: int, taken: set[int]) -> tuple[int, int | None, bool] | None:
        """(first word, verb index, command) when the robot (or "it" for it) is the subject at i."""
        low = self.low
        is_robot = low[i] in lx.ROBOT_WORDS
        is_it = low[i] == "it" and any(x in lx.ROBOT_WORDS for x in low[:i]) and self.w[i].dep in ("nsubj", "")
        if not (is_robot or is_it) or i in taken:
            return None
        first = i
        if is_robot:
            while first > 0 and not self._is_punct(first - 1) and (
                    self.w[first - 1].pos in ("DET", "ADJ", "NOUN", "PROPN", "NUM") or low[first - 1] in lx.NP_MODIFIERS
                    or (low[first - 1] == "-" and first > 1)) and low[first - 1] not in lx.CLAUSE_STARTERS \
                    and low[first - 1] not in lx.PLACE_PREPOSITIONS and (first - 1) not in taken:
                first -= 1  # "a delivery robot", "the small cleaning robot"
        before = first - 1
        command = before >= 0 and verb_lemma(low[before]) in lx.ROBOT_COMMAND_VERBS and (
            before == 0 or self._is_punct(before - 1) or low[before - 1] in lx.CLAUSE_STARTERS | {"please"})
        subject = (first == 0 or self._is_punct(before) or low[before] in lx.CLAUSE_STARTERS
                   or self.w[before].sentence != self.w[first].sentence
                   or (before >= 0 and self.w[before].pos == "NUM" and self.w[first].sentence == self.w[before].sentence
                       and before > 0 and low[before - 1] == "at"))  # "At 9 the robot ..."
        if command:
            first = before
        elif not subject:
            return None
        j = i + 1
        while j < self.n and (self.w[j].pos == "ADV" or self.w[j].tag == "MD" or low[j] in ("then", "also", "now", "first")) \
                and not self._is_punct(j):
            j += 1
        if j >= self.n or self._is_punct(j):
            return None
        if command:
            if low[j] == "to" and j + 1 < self.n and self._verb_follows(j + 1):
                return first, j + 1, True  # "tell the robot to wait by the door"
            if self.w[j].pos == "VERB" or self.w[j].tag == "VB":
                return first, j, True  # "have the robot patrol the lobby"
            return first, None, True  # "send the robot to ward A": the sender's verb moves it
        if verb_lemma(low[j]) == "be":
            k = j + 1
            while k < self.n and self.w[k].pos == "ADV":
                k += 1
            if k < self.n and self.w[k].tag == "VBN":
                return None  # "the robot is followed by two children": the people's clause
            if k < self.n and self.w[k].tag == "VBG":
                return first, k, False  # "the robot is crossing the hall"
            if k < self.n and self._preposition(k) is not None:
                return first, j, False  # "the robot is in the lobby": it stays there
            return None
        if self.w[j].pos in ("VERB", "AUX") or self.w[j].tag.startswith("VB") or self._third_person_verb_after_robot(j):
            return first, j, False
        return None

    def _third_person_verb_after_robot(self, j: int) -> bool:
        """The small parser may tag the robot's verb a plural noun ("the robot rolls", "the robot
        patrols"): an "-s" word the lexicon knows as a verb, right after the robot."""
        word = self.low[j]
        return word.endswith("s") and verb_lemma(word) != word and (
            verb_lemma(word) in lx.INTENT_VERBS or verb_lemma(word) in lx.ROBOT_WAIT_VERBS | lx.ROBOT_PATROL_VERBS
            | lx.ROBOT_FOLLOW_VERBS | lx.ROBOT_CROSS_VERBS)

    def _robot_clause_end(self, k: int, starts: set[int]) -> int:
        """Where a robot clause from k ends: the next group's mention (less the words joining it),
        a new subject after a clause word ("... as a family buys tickets"), a semicolon or colon, or
        the end of the sentence."""
        sentence = self.w[k].sentence if k < self.n else -1
        j = k
        while j < self.n and self.w[j].sentence == sentence and self.low[j] not in (";", ":"):
            if j in starts:
                break
            if self.low[j] in lx.CLAUSE_STARTERS - {"and", "then", "with"} and j > k and \
                    self._new_subject_after(j + 1):
                break
            if self.low[j] in ("and", ",") and j > k and self._new_subject_after(j + 1) and \
                    not (j + 1 < self.n and self.low[j + 1] in lx.ROBOT_WORDS):
                break
            j += 1
        while j > k and (self.low[j - 1] in lx.CLAUSE_STARTERS or self._is_punct(j - 1)
                         or verb_lemma(self.low[j - 1]) in lx.SCENE_VERBS):
            j -= 1  # "send the robot to the kitchen and have ...": not the robot's words
        return j

    def _new_subject_after(self, k: int) -> bool:
        """Whether a new subject starts at k: a person phrase, a pronoun for people, or a starter."""
        k = self._skip(k, {","} | (lx.CLAUSE_STARTERS - {"with"}))
        if k >= self.n:
            return False
        if self.low[k] in ("they", "he", "she", "we", "people", "everyone", "everybody", "someone", "somebody",
                           "nobody", "visitors", "staff"):
            return True
        q = self._quantifier(k)
        start = q[2] if q is not None else self._skip(k, lx.DETERMINERS | lx.NP_MODIFIERS)
        return start < self.n and self._person_head(start, counted=q is not None) is not None

    def _robot_reading(self, clauses: Sequence[_RobotClause]) -> RobotReading | None:
        """What the robot's clauses ask of it: a task from their verbs and the places by role."""
        if not clauses:
            return None
        task: str | None = None
        task_score, task_reason = 1.0, ""
        start = destination = location = None
        via: list[str] = []
        follows: str | None = None
        read_from: dict[str, _Place] = {}
        texts: list[str] = []
        for rc in clauses:
            quiet, self.quiet = self.quiet, False
            clause = self._clause(rc.tokens, set())
            self.quiet = quiet
            verb = self._verb(rc.verb) if rc.verb is not None else ""
            has_places = any(p.match is not None for p in clause.places)
            kind = self._robot_task(verb, clause, rc.command)
            if kind is None:
                if not has_places:
                    continue
                kind, task_score, task_reason = "cross", 0.6, f"'{verb}' is read as the robot going somewhere"
            task = task or kind
            if kind == "follow" and rc.verb is not None and follows is None:
                k = self._skip(rc.verb + 1, {"close", "closely", "right", "just", "along", "behind", "after"})
                end = self._skip(k, lx.DETERMINERS | lx.NP_MODIFIERS)
                if end < self.n and (self._is_person_noun(end) or self.low[end] in ("him", "her", "them", "us")):
                    follows = self._span(k, end)
            stationary = kind in ("wait", "patrol")
            for place in clause.places:
                if place.match is None:
                    continue
                name = place.match.name
                read_from.setdefault(name, place)
                role = self._robot_role(place, rc.verb, stationary)
                if role == "start" and start is None:
                    start = name
                elif role == "destination":
                    destination = name
                elif role == "location" and location is None:
                    location = name
                elif role == "via" and name not in via:
                    via.append(name)
            texts.append(self._span(rc.tokens[0], rc.tokens[-1]))
        if task is None or (task == "cross" and not (start or destination or via)):
            return None  # "when the robot comes near": it moves, but the sentence sets no route
        if task in ("wait", "patrol") and location is None:
            location = destination or (via[0] if via and task == "patrol" else None)
            if location == destination:
                destination = None
            if location is not None and location in via:
                via.remove(location)
        confidence = _place_confidences({"start": start, "destination": destination, "location": location}, via,
                                        read_from)
        if task_score < 1.0:
            confidence.insert(0, FieldConfidence("task", task_score, task_reason))
        return RobotReading(task, start, destination, location, tuple(via), " ... ".join(texts), tuple(confidence),
                            follows)

    def _robot_task(self, verb: str, clause: _Clause, command: bool) -> str | None:
        if verb in lx.ROBOT_FOLLOW_VERBS:
            return "follow"
        if verb in lx.ROBOT_PATROL_VERBS or lx.INTENT_VERBS.get(verb) == "wander" or clause.intent == "wander":
            return "patrol"
        if verb in lx.ROBOT_WAIT_VERBS or (verb and lx.INTENT_VERBS.get(verb) == "wait"):
            return "wait"
        if verb in lx.ROBOT_CROSS_VERBS or lx.INTENT_VERBS.get(verb) in ("walk", "evacuate") or \
                (command and not verb):
            return "cross"
        return None

    def _robot_role(self, p: _Place, verb_index: int | None, stationary: bool) -> str:
        prep = p.prep
        if prep in ("from", "obj:start", "out"):
            return "start"
        if stationary:
            return "location"
        if prep in lx.DESTINATION_PREPOSITIONS or prep in ("obj:dest", "for"):
            return "destination"
        if prep in lx.VIA_PREPOSITIONS or prep in ("obj:via", "obj:at"):
            return "via"
        if verb_index is not None and p.index < verb_index:
            return "start"  # "the robot in the lobby drives to ward A"
        return "via"  # "drives to ward A, stopping at the nurse station"

    def _already_gone(self, span: tuple[int, int]) -> bool:
        """Whether a clause says its people have left already: a verb of leaving in the perfect
        ("has gone home", "have left")."""
        return any(verb_lemma(self.low[i]) in lx.DEPARTURE_VERBS | {"go"} and self.w[i].tag == "VBN"
                   and self.low[i - 1] in ("has", "have", "had", "'s", "'ve", "already")
                   for i in range(max(span[0], 1), span[1]))

    def _evacuated_zone_without_people(self) -> PromptReading | None:
        """"The entire concourse is evacuated through the side entrance", "Evacuate the pharmacy.":
        a zone is emptied and nobody is named, so everyone in it leaves (a whole-zone group), and the
        reading says that it assumed them."""
        clause = self._clause(list(range(self.n)), set(), scene=True)
        for i in range(2, self.n):  # the subject of a passive evacuation: "<the X> is evacuated"
            aux = i - 2 if self.low[i - 1] in ("being", "been") else i - 1
            if verb_lemma(self.low[i]) == "evacuate" and self.w[i].tag == "VBN" and aux >= 1 and \
                    verb_lemma(self.low[aux]) in ("be", "get"):
                first = aux - 1
                while first > 0 and self.w[first - 1].pos in ("NOUN", "PROPN", "ADJ", "DET", "NUM") and \
                        not self._is_punct(first - 1):
                    first -= 1
                place = self._place_phrase(first, "obj:start", first, record_unknown=False)
                if place is not None:
                    clause.places.append(place)
        for place in self._emptied_zones(range(self.n)):
            clause.places.insert(0, place)
            clause.evacuate = True
            clause.intent = clause.intent or "evacuate"
        emptied = [(p, p.match) for p in clause.places if p.prep in ("obj:start", "from") and p.match is not None]
        if not emptied or not (clause.evacuate or clause.intent == "evacuate"):
            return None
        place, match = emptied[0]
        zone = match.zone
        mention = _Mention(place.index, place.end - 1, f"everyone in {match.name}", "person", None, whole_zone=True)
        group = self._group(0, mention, clause, None, True, (0, self.n), [])
        group = replace(group, who="everyone", text=self.prompt, confidence=group.confidence + (
            FieldConfidence("group", 0.45, f"no people are named: everyone in {zone} is assumed"),))
        self.notes.append(f"no people are named: everyone in {zone} is evacuated")
        return PromptReading(self.prompt, (group,), tuple(dict.fromkeys(self.unknown)), tuple(self.notes))

    def _hazard(self, i: int) -> bool:
        """A hazard named on its own ("Fire!", "a bomb scare", "smoke in the kitchen"), not as the
        first word of a thing's name ("the fire exit", "the smoke detector")."""
        if self._lemma(i) not in lx.HAZARD_NOUNS or self.w[i].pos not in ("NOUN", "PROPN"):
            return False
        return self.w[i].dep != "compound" and not (i + 1 < self.n and self.w[i + 1].pos == "NOUN")

    def _urgent(self, own: Sequence[int]) -> bool:
        """Whether the clause says leaving cannot wait ("must get out", "get out now") or the prompt
        names a hazard ("Fire! ... get out")."""
        return any(self.low[i] in lx.URGENCY_WORDS for i in own) or any(self._hazard(i) for i in range(self.n))

    def _passive_emptying(self, k: int) -> bool:
        """Whether the words from k say the subject before them is emptied: "(must|has to|is being)
        (be) cleared / emptied / vacated / evacuated"."""
        j = k
        while j < self.n and j < k + 4 and (self.w[j].pos in ("AUX", "PART") or self.low[j] in ("to", "being", "be")
                                               or self.w[j].tag == "MD" or verb_lemma(self.low[j]) in ("have", "need")):
            j += 1
        return j > k and j < self.n and self.w[j].tag == "VBN" and verb_lemma(self.low[j]) in lx.ZONE_EMPTYING_VERBS

    def _emptied_zones(self, tokens: Sequence[int]) -> list[_Place]:
        """Zones that are the subject of an emptying verb used without an object: "the cafeteria
        clears out", "the whole boardroom empties into the corridor", "the kitchen empties in
        seconds". Everybody in them leaves (their start), as in an evacuation. "clear the tables"
        has an object and "the kitchen is clear" no verb: neither is one."""
        out: list[_Place] = []
        for i in tokens:
            if i < 1 or verb_lemma(self.low[i]) not in lx.ZONE_EMPTYING_VERBS or self.low[i] == verb_lemma(self.low[i]):
                continue  # the base form is an imperative or infinitive ("clear the ward"), read elsewhere
            if self.w[i].tag == "VBN":
                # the passive, wherever it stands: "..., so the ticket hall has to be emptied"
                j = i - 1
                while j > 0 and (self.low[j] in ("be", "been", "being", "is", "are", "was", "were", "to", "has",
                                                 "have", "had", "needs", "need", "got", "gets", "get")
                                 or self.w[j].tag == "MD"):
                    j -= 1
                if j == i - 1:
                    continue  # no auxiliary: "the emptied room"
                end = j + 1
            elif self.w[i].pos == "VERB" or self.w[i].tag in ("VBZ", "VBD", "VBP", "NNS"):
                nxt = self.low[i + 1] if i + 1 < self.n else ""
                if nxt in lx.DETERMINERS or (nxt and self.index.knows(lemma(nxt)) and nxt != "out"):
                    continue  # an object follows: "empties the bins"
                end = i
            else:
                continue
            first = end
            while first > 0 and not self._is_punct(first - 1) and (
                    self.w[first - 1].pos in ("NOUN", "PROPN", "ADJ", "DET", "NUM")
                    or self.low[first - 1] in lx.PLACE_MODIFIERS) and self.low[first - 1] not in lx.CLAUSE_STARTERS:
                first -= 1
            words = tuple(self.low[first:end])
            lemmas = [t for t in phrase_lemmas(list(words)) if t not in lx.PLACE_MODIFIERS]
            match = self.index.match(lemmas) if lemmas else None
            if match is None or match.kind != "zone" or self._is_person_phrase(lemmas):
                continue
            self.context_zones.append(match.zone)
            out.append(_Place("obj:start", first, words, match, end))
        return out

    def _hyphen_inside(self, j: int) -> bool:
        """A hyphen joining two words ("self-service", "forty-five"), not a dash between clauses."""
        return self.low[j] == "-" and 0 < j < self.n - 1 and self.low[j - 1][-1:].isalnum() and \
            self.low[j + 1][:1].isalnum() and self.w[j].start == self.w[j - 1].end

    def _fronted_start(self, previous_last: int, first: int) -> int:
        """Where the group mentioned at `first` starts owning words: before it, a fronted phrase with
        no verb, opened by a preposition and closed by a comma; else the mention itself."""
        b = first - 1
        if b <= previous_last or self.low[b] != ",":
            return first
        j = b - 1
        while j > previous_last and (not self._is_punct(j) or self._hyphen_inside(j)) \
                and self.low[j] not in lx.CLAUSE_STARTERS:
            j -= 1
        fronted = range(j + 1, b)
        if not fronted or self.low[j + 1] not in lx.PLACE_PREPOSITIONS | {"for", "during", "from"}:
            return first
        if any(self.w[x].pos == "VERB" and verb_lemma(self.low[x]) in lx.INTENT_VERBS
               and not self.index.knows(lemma(self.low[x])) for x in fronted):
            return first  # a clause of its own, not a fronted phrase ("sitting" in "the sitting room" is a name)
        return j + 1

    def _robot_clause_after(self, a: int, b: int, robot_clauses: Sequence[_RobotClause]) -> int | None:
        """The first word of a robot clause that a group's clause leads into with a word of time
        ("two patients step aside as it passes"): the group reacts to the robot there."""
        for rc in robot_clauses:
            r = rc.tokens[0]
            if a < r <= b and r > 0 and self.low[r - 1] in ("as", "when", "whenever", "while", "once", "until"):
                return r
        return None

    def _clause(self, toks: list[int], mention_tokens: set[int], scene: bool = False,
                robot_after: int | None = None) -> _Clause:
        c = _Clause()
        low = self.low
        own = [i for i in toks if i not in mention_tokens]
        ownset = set(own)
        used: set[int] = set()
        # Robot interaction: phrases, then verbs, then feelings, when the robot is in the clause.
        # "it" is the robot after the robot was named in the sentence ("when the robot enters, they run up to it")
        robot_at = [i for i in own if low[i] in lx.ROBOT_WORDS or (
            low[i] in ("it", "its") and any(low[k] in lx.ROBOT_WORDS for k in range(i)))]
        if robot_after is not None:
            robot_at.append(robot_after)  # "... step aside as it passes": the robot of the next clause
        for n_mention, r in enumerate(robot_at):
            if c.robot is not None:
                break
            for phrase, interaction in lx.ROBOT_AFTER_PHRASES.items():
                if tuple(low[r + 1:r + 1 + len(phrase)]) == phrase or (
                        low[r] == "its" and tuple(low[r:r + len(phrase)]) == ("its", *phrase[1:])):
                    c.robot = interaction  # "stands in the robot's way", "blocks its path"
            # The verb closest before the robot governs it ("stop and stare at the robot": look); with
            # two mentions, the words since the one before ("curious about the robot and follow it").
            since = robot_at[n_mention - 1] if n_mention else -1
            for i in sorted((x for x in own if since < x < r), reverse=True):
                if c.robot is not None:
                    break
                for phrase, interaction in lx.ROBOT_PHRASES.items():
                    taken = self._phrase_words(i, len(phrase), ownset)
                    if taken == phrase:
                        c.robot = interaction
                        break
                # any verb of walking, known or only tagged a verb by the parser ("waddle over to it")
                if c.robot is None and (lx.INTENT_VERBS.get(self._verb(i)) == "walk" or (
                        self.w[i].pos == "VERB" and self._verb(i) not in lx.INTENT_VERBS)):
                    for tail in lx.ROBOT_APPROACH_TAILS:
                        if self._phrase_words(i + 1, len(tail), ownset) == tail:
                            c.robot = "approach"  # "the twins toddle up to the robot"
                            break
                v = self._verb(i)
                if c.robot is None and v in lx.ROBOT_VERBS and not self._after_determiner(i):
                    c.robot = lx.ROBOT_VERBS[v]
                if c.robot is None and self._lemma(i) in lx.ROBOT_NOUNS:
                    c.robot = lx.ROBOT_NOUNS[self._lemma(i)]  # "stop to take photos of the robot"
            if c.robot is None:
                # "give the robot a wide berth": a noun just after the robot names it
                for i in range(r + 1, min(r + 5, self.n)):
                    if i not in ownset or self._is_punct(i):
                        break
                    if self._lemma(i) in lx.ROBOT_NOUNS:
                        c.robot = lx.ROBOT_NOUNS[self._lemma(i)]
                        break
            if c.robot is None and r + 3 < self.n and verb_lemma(low[r + 1]) == "be" and \
                    verb_lemma(low[r + 2]) in lx.ROBOT_VERBS and low[r + 3] == "by":
                c.robot = lx.ROBOT_VERBS[verb_lemma(low[r + 2])]  # "the robot is followed by ..."
        if robot_at and c.robot is None:
            for i in own:
                if low[i] in lx.ROBOT_FEELINGS:
                    c.robot = lx.ROBOT_FEELINGS[low[i]]
                    break
        if robot_at and c.robot is None and any(low[r - 1] == "at" or (low[r - 1] == "the" and low[r - 2] == "at")
                                                 for r in robot_at if r >= 2):
            c.robot = "look"  # "gawk at the robot", "smile at the robot": a verb the lexicon lacks, aimed at it
        if c.robot is not None:
            c.has_action = True
        # Places, purposes and durations, phrase by phrase.
        i_pos = 0
        while i_pos < len(own):
            i = own[i_pos]
            w = low[i]
            nxt = low[i + 1] if i + 1 < self.n else ""
            if w == "for" and not (i > 0 and low[i - 1] in lx.EXCEPT_WORDS):
                dur = self._duration(i + 1)
                if dur is not None:
                    c.wait_seconds, end = dur
                    used.update(range(i, end))
                    i_pos = self._advance(own, end)
                    continue
                # "head for the exit", "make a beeline for gate B2", "queue for the coffee machine": a
                # place by its whole name after a determiner; "for coffee", "for their prescriptions",
                # "head out the back for a cigarette" are purposes, whatever they match.
                right_after_verb = self._verb_just_before(i) in lx.FOR_DESTINATION_VERBS
                if right_after_verb or (nxt in ("the", "this", "that") and self._names_place(i + 2)):
                    place = self._place_phrase(i + 1, "for", i, record_unknown=right_after_verb)
                    if place is not None:
                        c.places.append(place)
                        used.update(range(i, place.end))
                        i_pos += 1
                        continue
                end = self._phrase_end(i + 1)
                if end > i + 1 and not any(low[x] in lx.ROBOT_WORDS for x in range(i + 1, end)) and \
                        not (nxt in ("their", "his", "her") and i + 2 < self.n and low[i + 2] == "turn"):
                    c.purpose = c.purpose or self.prompt[self.w[i].start:self.w[end - 1].end]
                    used.update(range(i, end))
                    i_pos = self._advance(own, end)
                    continue
            if i > 0 and lx.INTENT_VERBS.get(self._verb(i - 1)) in lx.STATIONARY_INTENTS and \
                    c.wait_seconds is None:
                dur = self._duration(i)  # "waits 15 minutes outside the room": a duration without "for"
                if dur is not None:
                    c.wait_seconds, end = dur
                    used.update(range(i, end))
                    i_pos = self._advance(own, end)
                    continue
            negated = next((p for p in lx.NEGATED_PLACE_PHRASES if tuple(low[i:i + len(p)]) == p), None)
            if negated is not None:
                # "go to the imaging instead of the waiting room": a place nobody goes to
                k = i + len(negated)
                place = self._place_phrase(k, "at", i, record_unknown=False)
                end = place.end if place is not None else self._phrase_end(k)
                used.update(range(i, end))
                i_pos = self._advance(own, end)
                continue
            if w in ("evacuation", "evacuating", "clearing") and nxt == "of":
                place = self._place_phrase(i + 2, "obj:start", i)
                c.evacuate = c.evacuate or w != "clearing"
                if place is not None:
                    c.places.append(place)
                    used.update(range(i, place.end))
                    i_pos = self._advance(own, place.end)
                    continue
            if w == "to" and nxt == "be" and i + 2 < self.n and verb_lemma(low[i + 2]) in lx.ZONE_EMPTYING_VERBS:
                i_pos += 1
                continue  # "the hall has to be emptied": the zone's evacuation, read by _emptied_zones
            if w == "to" and (nxt == "" or self._verb_follows(i + 1)) and not self._names_place(i + 1):
                end = self._phrase_end(i + 2, allow_objects=True)
                c.purpose = c.purpose or self.prompt[self.w[i].start:self.w[max(end - 1, i + 1)].end]
                used.update(range(i, end))
                i_pos = self._advance(own, end)
                continue
            if w == "in" and nxt == "order" and i + 2 < self.n and low[i + 2] == "to":
                end = self._phrase_end(i + 4, allow_objects=True)
                c.purpose = c.purpose or self.prompt[self.w[i + 2].start:self.w[max(end - 1, i + 3)].end]
                used.update(range(i, end))
                i_pos = self._advance(own, end)
                continue
            prep = self._preposition(i)
            if prep is not None:
                name, width = prep
                if name == "from" and self._after_transaction(i, own):
                    name = "at"  # "buy tickets from the machines": where they stand, not where they start
                # "pour off platform 2" names a place; "drop off a parcel" only a particle and a thing
                place = self._place_phrase(i + width, name, i, record_unknown=name != "off")
                if place is not None:
                    c.places.append(place)
                    used.update(range(i, place.end))
                    i_pos = self._advance(own, place.end)  # "check in counter a": its "in" is not a new phrase
                    continue
                i_pos += 1
                continue
            v = self._verb(i)
            object_verbs = (lx.START_OBJECT_VERBS | lx.DESTINATION_OBJECT_VERBS | lx.LOCATION_OBJECT_VERBS
                            | lx.VIA_OBJECT_VERBS)
            if v in lx.NEGATING_VERBS and (nxt in lx.DETERMINERS or self._names_place(i + 1)):
                # "skip the critical care and go to ...": a place they do not go to
                place = self._place_phrase(i + 1, "obj:at", i, record_unknown=False)
                end = place.end if place is not None else i + 1
                used.update(range(i, end))
                i_pos = self._advance(own, end)
                continue
            if v in lx.ZONE_EMPTYING_VERBS and self.w[i].pos == "VERB" and not self._after_determiner(i) and \
                    nxt in lx.DETERMINERS | {"out"}:
                # "clear the platform", "empty out the ward": the zone everybody leaves
                place = self._place_phrase(self._skip(i + 1, {"out"}), "obj:start", i, record_unknown=False)
                if place is not None and place.match is not None and place.match.kind == "zone":
                    c.places.append(place)
                    c.evacuate = True
                    used.update(range(i + 1, place.end))
                    i_pos = self._advance(own, place.end)
                    continue
            if ((self.w[i].pos == "VERB" or self._third_person_verb(i)) and v not in lx.INTENT_VERBS
                    and v not in lx.ROBOT_VERBS and (nxt in lx.DETERMINERS or self._names_place(i + 1))
                    and not self._after_determiner(i) and self._names_place(self._skip(i + 1, lx.DETERMINERS))):
                # "a cleaner sweeps platform 2", "mops the corridor": the object of a verb the lexicon lacks
                place = self._place_phrase(i + 1, "obj:at", i, record_unknown=False)
                if place is not None:
                    c.places.append(place)
                    c.has_action = True  # a verb of its own, though no list names it: no sharing the next group's
                    used.update(range(i, place.end))
            elif not self._after_determiner(i) and v in object_verbs:
                if nxt in lx.DETERMINERS or (nxt and self.index.knows(lemma(nxt))):
                    role = ("obj:start" if v in lx.START_OBJECT_VERBS else "obj:via" if v in lx.VIA_OBJECT_VERBS
                            else "obj:at" if v in lx.LOCATION_OBJECT_VERBS else "obj:dest")
                    place = self._place_phrase(i + 1, role, i)
                    if place is not None and not any(x in lx.ROBOT_WORDS for x in place.words):
                        c.places.append(place)
            i_pos += 1
        if scene and any(low[i] in lx.ROBOT_WORDS for i in own):
            c.places = [p for p in c.places if p.index < min(i for i in own if low[i] in lx.ROBOT_WORDS)]
            # "When the robot enters the lobby, ...": the robot's places, not the people's
        if scene:
            # "Gate B1 clears out when the alarm sounds; its passengers ...": where they all leave
            for place in self._emptied_zones(own):
                c.places.insert(0, place)
                c.evacuate = True
        if scene and own:
            # "The cafeteria is empty except for ...": a place as the subject of "to be" is where
            # the sentence's people are.
            # So is a place that heads the sentence before a colon ("Gate A1: 25 people seated") or
            # names the event the people come from ("the boardroom meeting of twelve people"); the
            # subject of a passive takes the role the verb gives its object ("Ward B is visited by").
            subject = self._place_phrase(own[0], "at", own[0], record_unknown=False)
            after = low[subject.end] if subject is not None and subject.end < self.n else ""
            if subject is not None and subject.match is not None and self._passive_emptying(subject.end):
                # "Platform 1 must be cleared: ...", "the ward has to be emptied": where everybody leaves
                c.places.append(replace(subject, prep="obj:start"))
                c.evacuate = True
                used.update(range(own[0], subject.end))
            elif subject is not None and (verb_lemma(after) in ("be", "stay", "remain", "get") or after in (":", "of")):
                passive = subject.end + 1 < self.n and self.w[subject.end + 1].tag == "VBN"
                verb = verb_lemma(low[subject.end + 1]) if passive else ""
                if verb in lx.START_OBJECT_VERBS:
                    subject = replace(subject, prep="obj:start")
                elif verb in lx.DESTINATION_OBJECT_VERBS:
                    subject = replace(subject, prep="obj:dest")
                c.places.append(subject)
                used.update(range(own[0], subject.end))
        # Intents: phrasal verbs first, then single verbs; a verb inside a place phrase is not one.
        candidates: list[tuple[int, str, str]] = []
        for i in own:
            if i in used and low[i] not in ("line", "wait", "stand", "sit", "queue", "walk", "mill", "hang"):
                continue
            for phrase, intent in lx.PHRASAL_INTENTS.items():
                if tuple(verb_lemma(x) if t == 0 else x for t, x in enumerate(low[i:i + len(phrase)])) == phrase:
                    candidates.append((i, intent, phrase[0]))
                    break
            else:
                if i in used or self._after_determiner(i) or self._in_place_name(i, c.places):
                    continue
                v = self._verb(i)
                if v in lx.INTENT_VERBS and not (v == "line" and self.w[i].pos != "VERB"):
                    if v in ("make", "get") and not (i + 1 < self.n and low[i + 1] in ("their", "its", "his", "her",
                                                                                     "way", "to")):
                        continue
                    candidates.append((i, lx.INTENT_VERBS[v], v))
        if any(self.w[i].pos == "VERB" and self.w[i].lemma not in ("be", "have") and i not in used for i in own):
            c.has_action = True  # "a nurse pushes a cart to ward b": a verb of its own, even one the lexicon lacks
        if any(i not in self.relative for i, _, _ in candidates):
            candidates = [c_ for c_ in candidates if c_[0] not in self.relative]
        if len(candidates) > 1 and own and candidates[0][0] == own[0] and self.w[own[0]].tag == "VBG":
            candidates = candidates[1:]  # "the family sleeping in the bedrooms escape": who they are, not what they do
        if candidates:
            c.has_action = True
            c.moves = any(kind in ("walk", "evacuate") for _, kind, _ in candidates)
            c.intent, c.verb, c.verb_index = self._main_intent(candidates, c)
            c.verb_index = candidates[0][0] if c.verb_index is None else c.verb_index
        if any(verb_lemma(low[i]) in ("evacuate", "flee", "escape") or low[i] in ("evacuation",) for i in own):
            c.evacuate = True
        for i in own:
            pair = (self._verb(i), low[i + 1] if i + 1 < self.n else "")
            if pair in lx.EVACUATION_PHRASES or (pair in lx.URGENT_EXIT_PHRASES and self._urgent(own)):
                c.evacuate = True  # "empty out through the back door", "must get out via the east exit"
                if not candidates or c.intent in lx.STATIONARY_INTENTS:
                    c.intent, c.verb, c.verb_index, c.moves, c.has_action = "evacuate", pair[0], i, True, True
                break
        if any(self._verb(i) in lx.DEPARTURE_VERBS for i in own) and any(low[i] in lx.IMMEDIACY_WORDS for i in own):
            c.evacuate = True  # "everyone must leave immediately through the customs exit"
        # Follow someone: the person after a follow verb.
        if c.intent == "follow" and c.verb_index is not None:
            k0 = self._skip(c.verb_index + 1, {"close", "closely", "right", "just", "along"})
            k1 = self._skip(k0, {"behind", "after"})
            k = self._skip(k1, lx.DETERMINERS)
            if k + 1 < self.n and self.w[k].pos in ("NOUN", "ADJ", "PROPN") and self._is_person_noun(k + 1):
                k += 1  # "follow the charge nurse"
            if k < self.n and (self._is_person_noun(k) or low[k] in ("them", "him", "her", "others", "leader", "guide",
                                                                     "us", "everyone")):
                c.follows = self._span(c.verb_index + 1, k)
            elif k1 > k0 or k0 >= self.n or self._is_punct(k0) or low[k0] in lx.CLAUSE_STARTERS:
                c.follows = "the group before"  # "a porter follows close behind"
            else:
                c.intent = "walk"  # "follow the signs to the exit": walking, nobody is followed
        # Pace and togetherness
        lemmas = {verb_lemma(low[i]) for i in own} | {low[i] for i in own}
        if lemmas & lx.FAST_WORDS or ("in", "a", "hurry") in self._trigrams(own):
            c.pace = "fast"
        elif lemmas & lx.SLOW_WORDS or ("take", "their", "time") in {(verb_lemma(a), b, d) for a, b, d in self._trigrams(own)}:
            c.pace = "slow"
        if {low[i] for i in own} & lx.TOGETHER_WORDS or any(i in self.no_mention for i in own):
            c.together = True
        return c

    def _phrase_words(self, i: int, n: int, ownset: set[int]) -> tuple[str, ...]:
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

    def _trigrams(self, own: Sequence[int]) -> set[tuple[str, str, str]]:
        return {tuple(self.low[i:i + 3]) for i in own if i + 3 <= self.n}

    def _main_intent(self, candidates: list[tuple[int, str, str]], c: _Clause) -> tuple[str, str, int]:
        kinds = [k for _, k, _ in candidates]
        has_destination = any(p.prep in lx.DESTINATION_PREPOSITIONS or p.prep == "obj:dest" for p in c.places
                              if p.match is not None)
        for wanted in ("queue", "converse", "wait", "wander", "follow", "evacuate"):
            if wanted in kinds:
                i, _, verb = candidates[kinds.index(wanted)]
                if wanted == "wander" and has_destination and "walk" not in kinds[:kinds.index(wanted)]:
                    if not self._around_follows(i):
                        return "walk", verb, i  # "stroll to the cafe": a slow walk with a destination
                return wanted, verb, i
        i, kind, verb = candidates[0]
        if kind == "walk" and self._around_follows(i) and not has_destination:
            return "wander", verb, i
        return kind, verb, i

    def _around_follows(self, i: int) -> bool:
        return i + 1 < self.n and self.low[i + 1] in ("around", "about")

    def _after_determiner(self, i: int) -> bool:
        return i > 0 and self.low[i - 1] in ("the", "a", "an", "their", "its", "his", "her", "our", "my", "this", "that")

    def _in_place_name(self, i: int, places: Sequence[_Place]) -> bool:
        return any(p.index < i < p.end for p in places)

    def _verb_follows(self, k: int) -> bool:
        """Whether the word at k is a verb (after "to": a purpose, not a place)."""
        if k >= self.n:
            return False
        w = self.low[k]
        if w in lx.DETERMINERS or self.w[k].pos in ("DET", "NUM", "PROPN"):
            return False
        if self.index.knows(lemma(w)) and self.w[k].tag != "VB":
            return False
        if k + 1 < self.n and _IDENTIFIER.fullmatch(self.low[k + 1]) and self.index.knows(lemma(w)):
            return False  # "to gate C4": a place word with its number, though the parser calls "gate" a verb
        return self.w[k].tag == "VB" or self.w[k].pos == "VERB" or verb_lemma(w) != w or w in (
            "register", "check", "pick", "buy", "pay", "collect", "see", "get", "eat", "drink", "use")

    def _past_part(self, k: int) -> int:
        """Past "the corner of", "the far end of" at k: a part of a place is the place."""
        j = k
        while j < self.n and j < k + 3 and (self.low[j] in lx.PLACE_MODIFIERS or lemma(self.low[j]) in lx.PLACE_PARTS):
            j += 1
        if j > k and j < self.n and self.low[j] == "of" and lemma(self.low[j - 1]) in lx.PLACE_PARTS:
            return self._skip(j + 1, lx.DETERMINERS)
        return k

    def _names_place(self, k: int) -> bool:
        """Whether the words at k name a place of the world by its whole name or an alias ("ward a")."""
        k = self._past_part(k)
        words: list[str] = []
        for j in range(k, min(k + 4, self.n)):
            if self._is_punct(j) or (words and self.low[j] in lx.PLACE_PREPOSITIONS | {"to", "for"}):
                break  # "queue at the copier": the name ends where another place phrase starts
            words.append(self.low[j])
        for n in range(len(words), 0, -1):
            match = self.index.match(phrase_lemmas(words[:n]))
            if match is not None and match.exact:
                # the name starts here: "to pick up wheelchairs" is a purpose, though "wheelchairs" is a name
                entry = self.index.entry(match.name)
                first = next((lemma(w) for w in words[:n] if w not in lx.DETERMINERS), "")
                return entry is None or first in entry.tokens
        return False

    def _after_transaction(self, i: int, own: Sequence[int]) -> bool:
        """Whether a verb of getting something governs the preposition at i ("buy tickets from")."""
        before = [k for k in own if i - 4 <= k < i]
        return any(verb_lemma(self.low[k]) in lx.TRANSACTION_VERBS for k in before)

    def _verb_just_before(self, i: int) -> str | None:
        """The verb (or "beeline") right before i, past adverbs ("head straight for the exit")."""
        j = i - 1
        while j >= 0 and (self.w[j].pos == "ADV" or self.low[j] in ("straight", "directly", "off", "back")):
            j -= 1
        if j < 0:
            return None
        word = self.low[j]
        return word if word in lx.FOR_DESTINATION_VERBS else verb_lemma(word)

    def _previous_verb(self, own: Sequence[int], pos: int) -> str | None:
        for k in range(pos - 1, -1, -1):
            v = self._verb(own[k])
            if v in lx.INTENT_VERBS or v in lx.FOR_DESTINATION_VERBS:
                return v
        return None

    def _advance(self, own: Sequence[int], end: int) -> int:
        return next((p for p, i in enumerate(own) if i >= end), len(own))

    def _phrase_end(self, k: int, allow_objects: bool = False) -> int:
        """End (exclusive) of a short phrase: up to punctuation, a clause word or a place preposition."""
        j = k
        while j < self.n and j < k + 6:
            w = self.low[j]
            if self._is_punct(j) or w in lx.CLAUSE_STARTERS or (w in lx.PLACE_PREPOSITIONS and j > k) or w == "for":
                break
            if not allow_objects and j > k and verb_lemma(w) in lx.INTENT_VERBS and self.w[j].pos == "VERB":
                break
            j += 1
        return j

    def _duration(self, k: int) -> tuple[float, int] | None:
        """(seconds, index after) of "five minutes", "a minute", "half an hour", "a few minutes"."""
        low = self.low
        if k >= self.n:
            return None
        if low[k] == "half" and k + 2 < self.n and low[k + 1] in ("a", "an") and lemma(low[k + 2]) in lx.DURATION_UNITS:
            return lx.DURATION_UNITS[lemma(low[k + 2])] / 2, k + 3
        j = k + 1 if low[k] in ("a", "one") else k
        if (j + 3 < self.n and low[j] == "quarter" and low[j + 1] == "of" and low[j + 2] in ("a", "an")
                and lemma(low[j + 3]) in lx.DURATION_UNITS):
            return lx.DURATION_UNITS[lemma(low[j + 3])] / 4, j + 4  # "a quarter of an hour"
        q = self._quantifier(k)
        if q is not None:
            value, kind, after, high = q
            if after < self.n and lemma(low[after]) in lx.DURATION_UNITS:
                unit = lx.DURATION_UNITS[lemma(low[after])]
                if kind.startswith("vague"):
                    low_, high_ = lx.VAGUE_RANGES.get(kind.split(":")[1], (2, 4))
                    value = (low_ + high_) / 2
                elif kind == "range":
                    value = (value + (high or value)) / 2
                return float(value) * unit, after + 1
        if low[k] in ("a", "an", "one") and k + 1 < self.n and lemma(low[k + 1]) in lx.DURATION_UNITS:
            return lx.DURATION_UNITS[lemma(low[k + 1])], k + 2
        return None

    def _preposition(self, i: int) -> tuple[str, int] | None:
        """(role preposition, width) for a place preposition at i, multi-word ones included."""
        low = self.low
        w = low[i]
        two = tuple(low[i:i + 2])
        three = tuple(low[i:i + 3])
        if three in (("in", "front", "of"),):
            return "at", 3
        if two in (("out", "of"), ("away", "from")):
            return "from", 2
        if two in (("next", "to"), ("close", "to"), ("up", "to"), ("over", "to"), ("down", "to"), ("on", "to"),
                   ("in", "to")):
            return ("at" if two[0] in ("next", "close") else "to"), 2
        if w == "down" and i + 1 < self.n and low[i + 1] in lx.DETERMINERS:
            return "down", 1
        if w == "out" and i + 1 < self.n and low[i + 1] in lx.DETERMINERS:
            return "out", 1  # "head out the back", "walk out the front door"
        if w in lx.PLACE_PREPOSITIONS - {"down", "next"}:
            return w, 1
        return None

    def _place_phrase(self, k: int, prep: str, at: int, record_unknown: bool = True) -> _Place | None:
        """The noun phrase after a place preposition, matched against the world."""
        low = self.low
        j = k
        if tuple(low[j:j + 2]) in (("one", "of"), ("each", "of"), ("any", "of"), ("some", "of")):
            j += 2  # "sits on one of the concourse benches": the benches
        while j < self.n and (low[j] in lx.DETERMINERS or low[j] in ("'s", "’s")):
            j += 1
        j = self._past_part(j)
        if j == k and prep in ("in", "at", "to", "by", "on", "from", "about", "around") and j < self.n and \
                not self.index.knows(lemma(low[j])):
            return None  # "in line", "at once", "on time": no determiner and no place word
        phrase: list[str] = []
        joined = False  # the word follows a hyphen inside the phrase ("check-in")
        while j < self.n and len(phrase) < 6:
            w = low[j]
            if w == "-" and phrase and j + 1 < self.n and low[j + 1][:1].isalnum():
                joined = True
                j += 1
                continue
            if phrase and not joined and self._extends_name(phrase, j):
                phrase.append(w)  # "check in counter a": a preposition inside a name the world has
                j += 1
                continue
            if self._is_punct(j) or (w in lx.CLAUSE_STARTERS and not joined) or \
                    w in ("who", "which", "that", "where", "for", "of", "with", "then", "to"):
                break
            if w in ("'s", "’s"):
                j += 1
                continue
            if w in lx.PLACE_PREPOSITIONS and not joined and not (phrase and self.index.knows(lemma(w))):
                break
            after_hyphen, joined = joined, False
            if phrase and self.w[j].pos in ("VERB", "AUX") and not self.index.knows(lemma(w)):
                break
            if phrase and verb_lemma(w) in lx.INTENT_VERBS and self.index.knows(lemma(w)) and \
                    not w.endswith("ing") and self._whole_name(phrase) and \
                    not any(self._whole_name([*phrase, *low[j:end]]) for end in range(j + 1, min(j + 3, self.n) + 1)) \
                    and (j + 1 >= self.n or not self._is_person_noun(j + 1)):
                # "at gate B2 boards the plane", "the check-in hall queue at": a whole name, then a verb
                # that only happens to be a place word too ("departures board", the tag "queue"); but
                # "the pharmacy waiting chairs" and "the boardroom meeting" are names and nouns
                break
            if phrase and verb_lemma(w) in lx.INTENT_VERBS and not self.index.knows(lemma(w)) and (
                    self.w[j].tag.startswith("VB") or self.index.match([lemma(x) for x in phrase]) is not None
                    or self.index.is_nameless([lemma(x) for x in phrase])):
                # "in the cafeteria evacuate", "across the hospital evacuate": the verb after the place or
                # the building ("gift shop" is a noun)
                break
            if phrase and w in lx.DETERMINERS and j + 1 < self.n and self.w[j + 1].pos in ("NOUN", "PROPN", "ADJ", "NUM") \
                    and not self._extends_name(phrase, j) and not self._whole_name([*phrase, w]):
                break  # "on platform 2 a man sits": the place ends where a new noun phrase starts
            if w.isdigit() or w in lx.UNITS:
                if not phrase:
                    break
                phrase.append(w if w.isdigit() else str(lx.UNITS[w]))
                j += 1
                continue
            if self.w[j].pos in ("ADV", "PRON", "ADP", "CCONJ", "SCONJ", "PART") and not self.index.knows(lemma(w)) \
                    and not after_hyphen:
                break
            phrase.append(w)
            j += 1
            if self.w[j - 1].text.endswith(".") and len(self.w[j - 1].text) > 1:
                break  # "room b." at a sentence end: the full stop closes the phrase
        if not phrase:
            return None
        lemmas = tuple(phrase_lemmas(phrase)) or tuple(lemma(w) for w in phrase)
        if any(w in lx.ROBOT_WORDS for w in phrase):
            return None
        if self._is_person_phrase(lemmas):
            return None
        if lemmas and lemmas[-1] in lx.DURATION_UNITS:
            return None  # "in seconds", "within minutes": a time, though "second" starts a room's name
        match = None
        if prep == "out" and not set(lemmas) & lx.DOOR_WORDS:
            door = self.index.match((*lemmas, "door"))  # "out the back": out through the back door
            match = door if door is not None and door.kind == "door" else None
        match = match or self._in_context(self.index.match(lemmas), lemmas)
        if match is None and k < self.n and low[k] in ("her", "his", "their", "my", "our", "its"):
            return None  # "on her rounds", "in their pyjamas": the person's own things, not a place to refuse
        if at >= 1 and k < self.n and low[k] in ("a", "an") and self._is_person_noun(at - 1) and \
                (low[at] in ("in", "with") or (low[at] == "on" and match is None)):
            # "a woman in a wheelchair", "a mother with a pram", "a man on crutches": what the person
            # has or wears, not where they are ("a man on a bench" is still the bench)
            return None
        if match is not None and not match.exact and lemmas and lemmas[-1] in lx.NON_PLACES:
            return None  # "off the train": a word that names no place, though an alias shares it
        if match is not None and not self._identifiers_agree(lemmas, match):
            match = None  # "gate C4" where the gates are A1 to B2: a place the world does not have
        if match is None and record_unknown and not self.quiet and not self.index.is_nameless(lemmas):
            self.unknown.append(" ".join(phrase))
        if match is None:
            return None
        self.context_zones.append(match.zone)
        if match.kind == "zone" and prep in ("in", "at", "on", "inside", "within"):
            self.frame_zones.append(match.zone)
        score, reason, alternatives = self._match_confidence(phrase, lemmas, match)
        return _Place(prep, at, tuple(phrase), match, j, score, reason, alternatives)

    def _match_confidence(self, phrase: Sequence[str], lemmas: Sequence[str],
                          match: PlaceMatch) -> tuple[float, str, tuple[str, ...]]:
        """How sure a place match is, why, and the places that fit the phrase as well: a whole name or
        alias found and no other place like it is sure; a place only sharing words with the phrase
        is less so; two places scoring alike are unsure, unless a zone the prompt named before
        decides between them."""
        said = " ".join(phrase)
        tied = [m for m in self.index.candidates(lemmas)
                if m.name != match.name and m.score >= match.score - 1e-9
                and not (match.kind == "zone" and m.zone == match.name)
                and not (m.kind == "zone" and match.zone == m.name)]
        alternatives = tuple(dict.fromkeys(m.name for m in tied))[:4]
        if alternatives and match.zone in self.context_zones[:-1]:
            return (0.7, f"'{said}' fits {len(alternatives) + 1} places; {match.name} is in {match.zone}, "
                         f"named before", alternatives)
        if alternatives:
            return 0.4, f"'{said}' fits {match.name} and {', '.join(alternatives)} alike", alternatives
        if not match.exact:
            return 0.75, f"'{said}' shares words with {match.name} but is not its name", ()
        return 1.0, "", ()

    def _whole_name(self, phrase: Sequence[str]) -> bool:
        """Whether the words are exactly a name or alias of a place (determiners aside)."""
        lemmas = tuple(t for t in phrase_lemmas(list(phrase)) if t not in lx.PLACE_MODIFIERS)
        return bool(lemmas) and any(lemmas == p for e in self.index.entries for p in e.phrases)

    def _identifiers_agree(self, lemmas: Sequence[str], match: PlaceMatch) -> bool:
        """Whether every identifier of a place phrase ("c4", "2", the "b" of "ward b") belongs to the
        place matched or to one of the places it ties with: a number or letter names one place of a
        series, so a place whose series lacks it is not that place."""
        ids = [t for k, t in enumerate(lemmas) if _IDENTIFIER.fullmatch(t) and (k > 0 or not t.isalpha())]
        if not ids:
            return True
        entry = self.index.entry(match.name)
        return entry is None or all(t in entry.tokens for t in ids) or any(
            all(t in (self.index.entry(m.name) or entry).tokens for t in ids)
            for m in self.index.candidates(lemmas)[:8])

    def _in_context(self, match: PlaceMatch | None, lemmas: Sequence[str]) -> PlaceMatch | None:
        """Of places that tie for a phrase ("the desk", "the jet bridge"), the one in a zone the prompt
        has already named ("Gate A1: ... staff at the desk")."""
        if match is None or not self.context_zones or match.zone in self.context_zones:
            return match
        candidates = self.index.candidates(lemmas)
        tied = [m for m in candidates if m.score >= match.score - 1e-9]
        for zone in reversed(self.context_zones):
            for m in tied:
                if m.zone == zone:
                    return m
        if match.kind != "entity":
            return match  # a room or door named outright is that one, wherever the sentence was before
        # "On platform 2 a man sits on the bench": a fixture of the zone named before, called by the
        # phrase's own head word, though another zone's fixture has it as its whole name
        # (only a zone the people are in, "on platform 2", "in the pharmacy", not one they leave)
        content = [t for t in lemmas if t not in lx.PLACE_MODIFIERS]
        for zone in reversed(self.frame_zones):
            for m in candidates:
                entry = self.index.entry(m.name)
                if m.zone == zone and m.kind == "entity" and entry is not None and set(content) <= entry.tokens:
                    return m
        return match

    def _extends_name(self, phrase: Sequence[str], j: int) -> bool:
        """Whether the words from j on continue `phrase` into a longer whole name or alias of the world."""
        if self.low[j] not in ("in", "of", "and", "on", "up", "out"):
            return False  # "to", "from", "through" ... always mark a new place: never inside a name
        here = self.index.match(phrase_lemmas(list(phrase)))
        for end in range(j + 2, min(j + 4, self.n) + 1):
            extended = phrase_lemmas(list(phrase) + self.low[j:end])
            longer = self.index.match(extended)
            if longer is None or not longer.exact or (here is not None and here.exact and longer.name == here.name):
                continue
            # every word of the longer phrase must be the one place's: "check in counter a", not
            # "ward c to the nurses" (two places either side of a preposition)
            entry = self.index.entry(longer.name)
            if entry is not None and all(t in entry.tokens for t in extended):
                return True
        return False

    def _is_person_phrase(self, lemmas: Sequence[str]) -> bool:
        content = [t for t in lemmas if t not in lx.PLACE_MODIFIERS]
        return bool(content) and (content[-1] in lx.PERSON_NOUNS or content[-1] in lx.PRONOUN_PEOPLE) and \
            not self.index.knows(content[-1])

    def _scan_unknown_places(self, tokens: Sequence[int]) -> None:
        for i in tokens:
            prep = self._preposition(i)
            if prep is not None:
                self._place_phrase(i + prep[1], prep[0], i)

    # -- groups ----------------------------------------------------------------------------

    def _group(self, k: int, m: _Mention, c: _Clause, scene: _Clause | None, evacuation: bool,
               span: tuple[int, int], earlier: list[GroupReading]) -> GroupReading:
        intent = c.intent or (scene.intent if scene is not None and scene.intent else None)
        if intent is None:
            # No verb of action ("a cleaner is in the cafeteria"): people who are somewhere stay
            # there; only a place they are sent to ("... to the exit") makes them walk.
            # A way taken ("push a bed along the corridor") is walking too.
            # So is being the doer of a passive whose subject is a destination ("the desk is approached by").
            sends = any(p.prep in lx.DESTINATION_PREPOSITIONS | lx.VIA_PREPOSITIONS or p.prep == "obj:dest"
                        for p in c.places) or (scene is not None and any(p.prep == "obj:dest" for p in scene.places))
            intent = "walk" if sends or c.robot else "wait"
        if m.first >= 2 and self.low[m.first - 1] == "by" and \
                self.low[m.first - 2] in ("followed", "trailed", "accompanied", "joined") and earlier:
            # "..., followed by two assistants": they go where the group before goes, behind it
            leader = earlier[-1]
            intent = "follow" if self.low[m.first - 2] in ("followed", "trailed") else intent
            c = replace(c, follows=leader.who, places=c.places or [])
            if not c.places:
                return replace(leader, who=m.who, label=m.label, count=m.count or leader.count,
                               intent=intent if intent == "follow" else leader.intent, relation=None,
                               follows=leader.who if intent == "follow" else None, robot_interaction=None,
                               robot_reaction=None, together=m.together,
                               text=self.prompt[self.w[span[0]].start:self.w[span[1] - 1].end])
        if self._led_by(m.first) and earlier and c.robot is None:
            intent = "follow"  # "leads twelve tourists": they follow the one who leads
            c = replace(c, follows=earlier[-1].who)
        robot = c.robot if c.robot is not None else (scene.robot if scene is not None else None)
        if m.collective in lx.QUEUE_COLLECTIVES and c.intent in (None, "wait") and intent in ("wait", "walk"):
            intent = "queue"  # "a queue of eight people forms at the ticket office", "a line of five waiting"
        if robot is not None:
            intent = "robot"  # also "Startled by the robot, a woman ...", "The robot is followed by ..."
        if (evacuation or c.evacuate or (scene is not None and scene.evacuate)) and intent in ("walk", "evacuate"):
            intent = "evacuate"
        start = destination = location = None
        via: list[str] = []
        places = list(c.places)
        scene_places = list(scene.places) if scene is not None else []
        # Someone who looks at the robot or blocks it, with no verb of motion, stays where they are.
        stationary = intent in lx.STATIONARY_INTENTS or (intent == "robot" and (
            c.intent in lx.STATIONARY_INTENTS or (c.intent is None and robot in ("look", "block", "avoid"))))
        verb = c.verb or ""
        verb_index = c.verb_index
        said_to = False  # the destination came with "to", "into" ...: a later "at" does not replace it
        read_from: dict[str, _Place] = {}  # the place phrase each named place was read from
        for p in places + scene_places:
            name = p.match.name if p.match is not None else None
            if name is None:
                continue
            read_from.setdefault(name, p)
            role = self._role(p, verb, verb_index, stationary, intent, p in scene_places)
            marked = p.prep in lx.DESTINATION_PREPOSITIONS or p.prep == "obj:dest"
            if role == "start" and (start is None or self._narrower(name, start)):
                start = name
            elif role == "destination" and (destination is None or self._narrower(name, destination)
                                            or (marked and not said_to)):
                # "drops her bags off at the lockers and heads to the café": the café
                destination, said_to = name, said_to or marked
            elif role == "location" and (location is None or self._narrower(name, location)):
                location = name
            elif role == "via" and name not in via:
                via.append(name)
        if intent == "evacuate" and start is None and location is not None:
            start, location = location, None
        if intent == "queue" and location is None and start is not None and destination is None:
            # "a queue snakes back from the check-in counter": a queue stands where its head is
            start, location = None, start
        if stationary and location is None and destination is not None and intent != "robot":
            # "walk to the cafeteria and wait there": they go there, then stay; without a verb of
            # motion ("queue to the desk") the place is only where they are.
            location = destination
            if not c.moves:
                destination = None
        kind, _, parent_index = (m.relation or "").partition(":")
        if kind == "subset_of" and parent_index.isdigit() and int(parent_index) < len(earlier):
            parent = earlier[int(parent_index)]
            if start is None and destination is None and location is None:
                # "one of them stares at the robot": a member of a group keeps its route unless told otherwise
                start, destination = parent.start, parent.destination
                location = parent.location if stationary else None
                via = list(parent.via)
            elif start is None and not stationary:
                start = parent.start or parent.location  # "a few of them leave": from where the group is
        if m.exception_of is not None and m.exception_of < len(earlier) and \
                start is None and destination is None and location is None:
            parent = earlier[m.exception_of]
            location = parent.start or parent.location  # "... except three patients, who stay seated"
        count = m.count
        if count is not None and count.kind in ("implied", "vague") and m.relation is None:
            count = self._count_after_comma(m, span) or count
        if m.whole_zone:
            zone = start or location or destination
            area = self.index.zone_area(zone) if zone else sum(e.area for e in self.index.entries if e.kind == "zone")
            low_ = max(1, min(lx.WHOLE_ZONE_CAP, round(area * lx.WHOLE_ZONE_DENSITY[0])))
            high_ = max(low_, min(lx.WHOLE_ZONE_CAP, round(area * lx.WHOLE_ZONE_DENSITY[1])))
            if m.fraction < 1.0:
                low_, high_ = max(1, round(low_ * m.fraction)), max(1, round(high_ * m.fraction))
            count = Count("whole_zone", self._choose(low_, high_, f"{m.first}:whole"), low_, high_)
            if zone is None:
                self.notes.append(f"'{m.who}': no place says where everyone is; the whole building is filled")
        if m.rest_of_parent:
            parent = int((m.relation or "x:-1").split(":")[1]) if m.relation else -1
            if 0 <= parent < len(earlier):
                taken = sum(g.count.value for g in earlier if g.relation == f"subset_of:{parent}")
                rest = max(0, earlier[parent].count.value - taken)
                count = Count("implied", rest, rest, rest)
                if rest == 0:
                    self.notes.append(f"'{m.who}': nobody is left of '{earlier[parent].who}'")
            else:
                low_, high_ = lx.OTHERS_RANGE
                count = Count("vague", self._choose(low_, high_, f"{m.first}:rest"), low_, high_)
        if count is None:  # unreachable by construction: every mention kind sets or settles its count
            count = Count("vague", lx.BARE_PLURAL_RANGE[0], *lx.BARE_PLURAL_RANGE)
        if m.exclusive and count.kind != "exclusive":
            count = replace(count, kind="exclusive")
        interaction = robot
        pace = c.pace if c.pace != "normal" or scene is None else scene.pace
        together = m.together or c.together or count.kind == "structured"
        wait = c.wait_seconds
        if wait is None and scene is not None and intent in lx.STATIONARY_INTENTS:
            wait = scene.wait_seconds
        confidence = self._count_confidence(m, count) + _place_confidences(
            {"start": start, "destination": destination, "location": location}, via, read_from)
        if robot is not None and c.robot is None and scene is not None and scene.robot is not None:
            confidence.append(FieldConfidence("robot_interaction", 0.7, "read from the sentence's words about the "
                                                                      "robot, not from this group's own"))
        return GroupReading(
            who=m.who, label=m.label, count=count, intent=intent,
            robot_interaction=interaction, robot_reaction=lx.ROBOT_REACTIONS.get(interaction) if interaction else None,
            start=start, destination=destination, location=location, via=tuple(via),
            purpose=c.purpose or (scene.purpose if scene is not None else None), wait_seconds=wait,
            together=together, pace=pace, relation=m.relation, follows=c.follows,
            text=self.prompt[self.w[span[0]].start:self.w[span[1] - 1].end] if span[1] > span[0] else m.who,
            confidence=tuple(confidence))

    def _count_confidence(self, m: _Mention, count: Count) -> list[FieldConfidence]:
        """How sure a count is: said outright (not listed), approximate, a vague word's range, a
        collective's usual size, a share of a zone's floor, or no number at all (a guess)."""
        said = f"'{m.who}'"
        if count.kind in ("exact", "structured", "exclusive"):
            return []
        if count.kind == "approximate":
            return [FieldConfidence("count", 0.9, f"{said}: about {count.value} ({count.low}-{count.high})")]
        if count.kind == "whole_zone":
            return [FieldConfidence("count", 0.6, f"{said}: {count.value} people from the place's floor area "
                                                  f"({count.low}-{count.high})")]
        if count.kind == "implied" and m.collective is not None:
            return [FieldConfidence("count", 0.65, f"the size of {said} is not said: {count.value} chosen in "
                                                   f"{count.low}-{count.high}")]
        if count.kind == "implied":
            return [FieldConfidence("count", 0.8, f"{said}: {count.value}, from the rest of the sentence")]
        first = self.low[m.first]
        worded = self._quantifier(m.first) is not None or first in ("others", "other", "rest") or \
            self.low[m.first] in ("a", "an") or (first == "the" and m.relation is not None)
        if worded:
            return [FieldConfidence("count", 0.7, f"{said} gives no number: {count.value} chosen in "
                                                  f"{count.low}-{count.high}")]
        return [FieldConfidence("count", 0.5, f"no number is given for {said}: {count.value} guessed in "
                                              f"{count.low}-{count.high}", (str(count.low), str(count.high)))]

    def _count_after_comma(self, m: _Mention, span: tuple[int, int]) -> Count | None:
        """A count said on its own after the group's phrase, between a comma and the clause's end:
        "a long line of people at the counter, maybe a dozen", "visitors, about twenty, wait"."""
        for i in range(m.last + 2, span[1]):
            if self.low[i - 1] != ",":
                continue
            q = self._quantifier(i)
            if q is None and self.low[i] in lx.APPROXIMATE_WORDS:
                q = self._quantifier(i + 1)
                q = (q[0], "approximate", q[2], q[3]) if q is not None and q[1] == "exact" else q
            if q is None or q[1] not in ("exact", "approximate", "range"):
                continue
            if q[2] >= self.n or self._is_punct(q[2]):
                return self._count_from_quantifier(q, f"{m.first}:apposition")
        return None

    def _narrower(self, name: str, than: str) -> bool:
        """Whether `name` is a door or thing inside the zone `than` ("the coffee machine in the kitchen")."""
        entry = next((e for e in self.index.entries if e.name == name), None)
        return entry is not None and entry.kind != "zone" and entry.zone == than

    def _role(self, p: _Place, verb: str, verb_index: int | None, stationary: bool, intent: str,
              from_scene: bool) -> str:
        prep = p.prep
        is_door = p.match is not None and p.match.kind == "door"
        if prep == "out":
            return "destination" if is_door else "start"
        if prep in ("from", "obj:start"):
            return "start"
        if prep == "for":
            return "location" if stationary else "destination"
        if prep in ("to", "into", "towards", "toward", "onto", "obj:dest"):
            return "destination"
        if prep == "obj:via":
            return "via"
        if prep in lx.VIA_PREPOSITIONS and stationary and not is_door:
            return "location"  # "pace up and down the corridor", "wander through the concourse"
        if prep in lx.VIA_PREPOSITIONS:
            if is_door and verb in lx.DEPARTURE_VERBS | {"evacuate"} or (is_door and intent == "evacuate"):
                return "destination"
            entry = self.index.entry(p.match.name) if is_door and p.match is not None else None
            if entry is not None and entry.exit and verb not in lx.ARRIVAL_VERBS:
                return "destination"  # "go home through the back door": out of an exit is where they end
            if is_door and verb in lx.ARRIVAL_VERBS:
                return "start"
            return "via"
        if prep == "by" and is_door and (verb in lx.DEPARTURE_VERBS or intent == "evacuate"):
            return "destination"
        if prep == "obj:at":
            return "location" if stationary else "via"
        # at / in / on / near / around ...
        if stationary:
            return "location"
        before_verb = from_scene or verb_index is None or p.index < verb_index
        if before_verb:
            return "start"
        if verb in lx.ARRIVAL_VERBS:
            return "destination"
        return "start"
