"""The one place index of the product: a noun phrase of the prompt -> a zone, door or entity of the world.

A world's places are indexed by what people call them: their `name` split on underscores, their
aliases, their type and (more weakly) their tags. A phrase is scored against each place with
IDF-weighted word matches; the whole name or an alias inside the phrase beats anything that only
shares one word, a zone beats its own fixtures on a tie, and a door is chosen only when the
phrase speaks of a door or names that door. Words for the whole building ("the hospital") and
generic heads ("area", "room") never have to match.

When words do not decide (no place shares the phrase's words, or several score alike), places are
scored by meaning: the phrase against each place's names with the sentence-embedding model
(language/meaning.py; "the big meeting room" is nearest "large meeting room"). A place also knows
the kinds of people it belongs to ("director's office", "kids room", "guards' room"), so "her
office" is read against the offices of that kind of person.
"""

from __future__ import annotations

import math
import re
from collections.abc import Collection, Sequence
from dataclasses import dataclass
from functools import lru_cache

from grove_tui.language.bare_place_names import bare_place_name
from grove_tui.language.lexicon import (BUILDING_WORDS, DOOR_WORDS, GENERIC_PLACE_HEADS, NON_PLACES, OWNER_KINDS,
                                        PERSON_NOUNS, PLACE_MODIFIERS, PLACE_SYNONYMS)
from grove_tui.language.meaning import MiniLM, PhraseVectors, Vectors
from grove_tui.language.place_first_words import names_its_zone
from grove_tui.language.room_exits import room_exit
from grove_tui.language.place_compounds import KIND_HEADS, head_only_modifies, names_another_kind
from grove_tui.language.tier_places import tier_place
from grove_tui.language.tokens import name_tokens
from grove_tui.language.trade_places import TRADE_PLACES
from grove_tui.world.model import World

SYNONYM_DISCOUNT = 0.6
TAG_DISCOUNT = 0.3
WHOLE_PHRASE_BONUS = 2.0


@dataclass(frozen=True)
class PlaceEntry:
    kind: str  # "zone" | "door" | "entity"
    name: str
    zone: str
    tokens: frozenset[str]  # name, aliases and type: what people call it
    tag_tokens: frozenset[str]  # what it is for: weaker evidence
    phrases: tuple[tuple[str, ...], ...]  # the name and each alias, lemmatised
    exit: bool = False
    area: float = 0.0
    said: tuple[str, ...] = ()  # the name (as words), the type and each alias, as people write them
    types: frozenset[str] = frozenset()  # the type as written in `said`
    owners: frozenset[str] = frozenset()  # kinds of people it belongs to ("child" for "kids room")
    description: str = ""  # what the world says it is and what it is for


@dataclass(frozen=True)
class PlaceMatch:
    name: str
    kind: str
    zone: str
    score: float
    exact: bool  # the phrase contains the whole name or an alias


@dataclass(frozen=True)
class MeaningMatch:
    """A place scored by meaning: its cosine similarity to the phrase, and its name that came nearest."""

    entry: PlaceEntry
    similarity: float
    nearest: str


class PlaceIndex:
    """Index of one world's places; build once per world (`place_index(world)` caches it)."""

    def __init__(self, world: World) -> None:
        self.world = world
        self.entries: list[PlaceEntry] = []
        for zone in world.zones:
            self.entries.append(_entry("zone", zone.name, zone.name, zone.type, zone.tags, zone.aliases,
                                       area=float(zone.area), description=zone.description))
            for door in zone.doors:
                self.entries.append(_entry("door", door.name, zone.name, "exit door" if door.exit else "door",
                                           door.tags, door.aliases, exit=door.exit, description=door.description))
            for entity in zone.entities:
                self.entries.append(_entry("entity", entity.name, zone.name, entity.type, entity.tags,
                                           entity.aliases, description=entity.description))
        df: dict[str, int] = {}
        for e in self.entries:
            for t in e.tokens | e.tag_tokens:
                df[t] = df.get(t, 0) + 1
        n = len(self.entries)
        self.idf = {t: math.log(1.0 + n / c) for t, c in df.items()}
        self.vocabulary = frozenset(df)
        self.building_words = BUILDING_WORDS | frozenset(name_tokens(getattr(world, "name", "")))
        self.zone_words = frozenset(t for e in self.entries if e.kind == "zone" for t in e.tokens)
        self._zone_words = self.zone_words
        self._token_weights: dict[str, dict[int, float]] = {}
        self._candidates: dict[tuple[str, ...], list[PlaceMatch]] = {}
        # What a misspelling can be corrected to: the words of names, aliases and types (never tags,
        # which say what a place is for, not what it is called), and the neighbouring word pairs of
        # each name, so "sever room" can be told to complete "server room" and "livingroom" to be
        # two words run together.
        self.name_words = frozenset(t for e in self.entries for t in e.tokens if t.isalpha() and len(t) >= 4)
        self.name_pairs = frozenset(pair for e in self.entries for p in e.phrases for pair in zip(p, p[1:]))
        self.joined_pairs = {a + b: (a, b) for a, b in self.name_pairs if a.isalpha() and b.isalpha()}
        # A type many places share ("gallery", "office") says nothing about which: meaning compares
        # names, aliases and the types only one place has.
        said_by: dict[str, int] = {}
        for e in self.entries:
            for text in e.said:
                said_by[text] = said_by.get(text, 0) + 1
        self._said = [(i, text) for i, e in enumerate(self.entries) for k, text in enumerate(e.said)
                      if k == 0 or text not in e.types or said_by[text] == 1]
        self._vectors = PhraseVectors([text for _, text in self._said])
        # What each room and fixture is for, in the world's words ("Queue-number ticket dispenser."):
        # compared with what people go to do ("to take a queue number"), computed only when asked
        self._described = [(i, e.description) for i, e in enumerate(self.entries) if e.description and e.kind != "door"]
        self._description_vectors = PhraseVectors([text for _, text in self._described])
        self._order_cache = {e.name: i for i, e in enumerate(self.entries)}
        self._by_name = {e.name: e for e in self.entries}

    # ---- meaning ---------------------------------------------------------------------------------

    def by_meaning(self, text: str, among: Collection[str] | None = None) -> list[MeaningMatch]:
        """Places ranked by how near `text` is in meaning to one of their names (best first), all of
        them or those named in `among`; empty when the embedding model is not installed."""
        model = MiniLM.shared()
        if model is None or not self._said:
            return []
        vectors = self._vectors.vectors(model)
        similarity = vectors @ _query_vector(model, text)
        best: dict[int, tuple[float, str]] = {}
        for (i, said), value in zip(self._said, similarity.tolist()):
            if (among is None or self.entries[i].name in among) and value > best.get(i, (-2.0, ""))[0]:
                best[i] = (value, said)
        ranked = sorted(best.items(), key=lambda item: (-item[1][0], self._order(self.entries[item[0]].name)))
        return [MeaningMatch(self.entries[i], round(value, 4), said) for i, (value, said) in ranked]

    def by_description(self, text: str) -> list[MeaningMatch]:
        """Places ranked by how near `text` is in meaning to what the world says they are for (their
        description), best first; empty without the model or descriptions."""
        model = MiniLM.shared()
        if model is None or not self._described:
            return []
        similarity = self._description_vectors.vectors(model) @ _query_vector(model, text)
        ranked = sorted(zip((i for i, _ in self._described), similarity.tolist()),
                        key=lambda item: (-item[1], self._order(self.entries[item[0]].name)))
        return [MeaningMatch(self.entries[i], round(value, 4), self.entries[i].description) for i, value in ranked]

    def near_building(self, text: str) -> float:
        """How near `text` is in meaning to what the world is ("train" to a station: 0.47), 0 without
        the model."""
        model = MiniLM.shared()
        name = str(getattr(self.world, "name", "") or "").replace("_", " ")
        if model is None or not name:
            return 0.0
        return float(_query_vector(model, text) @ _query_vector(model, name))

    def warm_meaning(self) -> bool:
        """Load the model and this world's name vectors now (from disk when a process did before)."""
        model = MiniLM.shared()
        if model is None:
            return False
        self._vectors.vectors(model)
        return True

    def sharing(self, phrase: Sequence[str]) -> list[str]:
        """The places (no doors, unless the phrase speaks of one) that share a word of the phrase."""
        doors = any(t in DOOR_WORDS for t in phrase)
        found = {i for t in phrase if t not in PLACE_MODIFIERS for i in self._weights_of(t)}
        return [self.entries[i].name for i in sorted(found) if self.entries[i].kind != "door" or doors]

    # ---- owners ----------------------------------------------------------------------------------

    def owned_by(self, person: str) -> list[PlaceEntry]:
        """The places that belong to a kind of person: "director" owns "director's office", "child"
        owns "kids room", "guard" owns "guards' room"."""
        kinds = owner_kinds(person)
        # a person word the lexicon lacks still owns the places named after it ("the curator's office")
        return [e for e in self.entries if e.owners & kinds or set(person.split()) <= e.tokens]

    def knows(self, token: str) -> bool:
        """Whether some place of the world is called by this word or a synonym of it."""
        if token in self.vocabulary:
            return True
        return any(token in group and any(t in group for t in self.vocabulary) for group in PLACE_SYNONYMS)

    def names_word(self, entry: PlaceEntry, token: str) -> bool:
        """Whether a word is one of a place's words, a synonym of one, or one of its tags."""
        return self._weight(entry, token) > 0

    def _weight(self, entry: PlaceEntry, token: str) -> float:
        if token in entry.tokens:
            return self.idf.get(token, 0.0)
        for group in PLACE_SYNONYMS:
            if token in group:
                hits = [t for t in entry.tokens if t in group]
                if hits:
                    return SYNONYM_DISCOUNT * max(self.idf.get(t, 0.0) for t in hits)
        if token in entry.tag_tokens:
            return TAG_DISCOUNT * self.idf.get(token, 0.0)
        return 0.0

    def _weights_of(self, token: str) -> dict[int, float]:
        """Entry index -> weight of one word, computed once per word: most entries share no word
        with a phrase, so a phrase is scored only against the entries its words touch."""
        cached = self._token_weights.get(token)
        if cached is None:
            cached = {}
            for i, e in enumerate(self.entries):
                w = self._weight(e, token)
                if w > 0:
                    cached[i] = w
            self._token_weights[token] = cached
        return cached

    def candidates(self, phrase: Sequence[str]) -> list[PlaceMatch]:
        """Every place the lemmatised phrase could mean, best first."""
        key = tuple(phrase)
        if key not in self._candidates:
            if len(self._candidates) > 4096:
                self._candidates.clear()
            self._candidates[key] = self._score(key)
        return self._candidates[key]

    def _score(self, phrase: Sequence[str]) -> list[PlaceMatch]:
        tokens = [t for t in phrase if t]
        if not tokens:
            return []
        content = [t for t in tokens if t not in PLACE_MODIFIERS or t in self.vocabulary]
        if not content:
            return []
        head = content[-1]
        speaks_of_door = any(t in DOOR_WORDS for t in content)
        scored: list[PlaceMatch] = []
        per_token = [self._weights_of(t) for t in content]
        touched = sorted({i for weights in per_token for i in weights})
        for i in touched:
            e = self.entries[i]
            weights = [weights_.get(i, 0.0) for weights_ in per_token]
            total = sum(weights)
            if total <= 0:
                continue
            matched = [p for p in e.phrases if _contains(content, p) or _reordered(content, p)]
            exact = bool(matched)
            if exact:
                # The longest name or alias found in the phrase: "pharmacy counter" is the counter's
                # whole name but only the pharmacy's name plus a stray word.
                total += WHOLE_PHRASE_BONUS + sum(self.idf.get(t, 0.0) for t in max(matched, key=len))
            elif head not in GENERIC_PLACE_HEADS and head not in self.building_words and weights[-1] <= 0:
                continue  # "the coffee machine": a phrase whose head names nothing of this entry is not it
            elif head in KIND_HEADS and len(content) > 1 and self.is_nameless(content):
                continue  # "the shopping centre" of a supermarket is the building, not its shopping aisles
            elif head_only_modifies(e, content):
                continue  # "the garden centre" is no "centre court": the head is only its first word
            elif len(content) == 1 and any(head in p for p in e.phrases) and \
                    all(p[0] == head and len(p) > 1 for p in e.phrases if head in p) and \
                    not any(head in t.split() for t in e.types) and not names_its_zone(self.entries, e, head):
                continue  # "a box": only the first word of "box office", which names an office
            own_words = e.tokens - self._zone_words
            if e.kind == "door" and not exact and not speaks_of_door and not set(content) <= own_words:
                continue  # the rooms a door joins are not the door; "the jet bridge" is the door's own name
            if e.kind == "door" and not exact and not (set(content) & (e.tokens - self._zone_words) or
                                                      (e.exit and ({"exit"} & set(content)))):
                continue
            scored.append(PlaceMatch(e.name, e.kind, e.zone, round(total, 4), exact))
        if not scored:
            return []
        rank = {"zone": 0, "entity": 1, "door": 2}
        scored.sort(key=lambda m: (-m.score, rank[m.kind], self._order(m.name)))
        return scored

    def match(self, phrase: Sequence[str]) -> PlaceMatch | None:
        """The place a phrase names; a zone wins a tie with its own fixtures ("the restroom")."""
        way_out = room_exit(self, phrase)
        if way_out is not None:
            return way_out
        found = self.candidates(phrase)
        if not found:
            return None
        best = found[0]
        if best.kind == "zone":
            # "the nurses' desk": the room and its desk both answer to the whole phrase; the head
            # word is the desk's own kind and not the room's, so the desk
            head = next((t for t in reversed(phrase) if t and t not in PLACE_MODIFIERS), "")
            zone = self._by_name.get(best.name)
            for m in found[1:]:
                if m.score < best.score - 1e-9:
                    break
                entry = self._by_name.get(m.name)
                if m.kind == "entity" and m.zone == best.name and m.exact and entry is not None and \
                        zone is not None and head in _kind_words(entry) and head not in _kind_words(zone) and \
                        not _contains(phrase, zone.phrases[0]):  # "the phone booths": the room's own name
                    return m
        if best.kind != "zone":
            for m in found[1:]:
                if m.score < best.score - 1e-9:
                    break
                if m.kind == "zone" and m.name == best.zone:
                    return m
        return best

    def _order(self, name: str) -> int:
        return self._order_cache.get(name, len(self.entries))

    def is_nameless(self, phrase: Sequence[str]) -> bool:
        """A place phrase that names nothing in particular: the building, a time, a person, a manner."""
        content = [t for t in phrase if t not in PLACE_MODIFIERS]
        if not content:
            return True
        head = content[-1]
        if len(content) >= 2 and any(ch.isdigit() for ch in head) and content[-2] in NON_PLACES:
            return True  # "flight BA123", "train 42": a service and its number, not a place
        if names_another_kind(self, content) or tier_place(phrase) is not None or bare_place_name(content, 0):
            return False  # "the garden centre" in a supermarket: a kind of place, not the building
        if head == "area" and any(t not in self.building_words and t not in _WHOLE_AREA for t in content[:-1]):
            return False  # "the smoking area", "the coffee area": a part of the building, not all of it
        return (head in NON_PLACES or head in PERSON_NOUNS and head not in TRADE_PLACES or head in self.building_words
                or all(t.isdigit() for t in content) or (head in GENERIC_PLACE_HEADS and len(content) == 1))

    def entry(self, name: str) -> PlaceEntry | None:
        return self._by_name.get(name)

    def zone_area(self, name: str) -> float:
        for e in self.entries:
            if e.name == name:
                zone = e.zone
                break
        else:
            return 0.0
        return next((e.area for e in self.entries if e.kind == "zone" and e.name == zone), 0.0)

    def exits(self) -> list[str]:
        return [e.name for e in self.entries if e.kind == "door" and e.exit]


# Words before "area" that still mean the whole scene ("the surrounding area", "the general area").
_WHOLE_AREA = frozenset("surrounding general local immediate wide wider entire same public common this that".split())


def _entry(kind: str, name: str, zone: str, type_: str, tags: Sequence[str], aliases: Sequence[str], *,
           exit: bool = False, area: float = 0.0, description: str = "") -> PlaceEntry:
    tokens: set[str] = set(name_tokens(name)) | set(name_tokens(type_ or ""))
    phrases = [tuple(name_tokens(name))]
    for alias in aliases or ():
        alias_tokens = name_tokens(alias)
        tokens |= set(alias_tokens)
        if len(alias_tokens) > 1 or (alias_tokens and alias_tokens[0] not in GENERIC_PLACE_HEADS):
            phrases.append(tuple(alias_tokens))  # an alias that is only "room" names no room in particular
    tag_tokens: set[str] = set()
    for tag in tags or ():
        tag_tokens |= set(name_tokens(tag))
    said = [name.replace("_", " ")] + ([type_.replace("_", " ")] if type_ and kind != "door" else []) + \
        [a for a in aliases or () if a]
    owners = {t for phrase in phrases for t in phrase if t in PERSON_NOUNS and t not in ("person", "people")}
    return PlaceEntry(kind, name, zone, frozenset(tokens), frozenset(tag_tokens - tokens),
                      tuple(p for p in phrases if p), exit, area, tuple(dict.fromkeys(said)),
                      frozenset({type_.replace("_", " ")} if type_ and kind != "door" else set()),
                      frozenset(k for t in owners for k in owner_kinds(t)), " ".join((description or "").split()))


def _kind_words(entry: PlaceEntry) -> set[str]:
    """The words of a place's type ("desk", "nurse station")."""
    return {w for kind in entry.types for w in kind.split()}


def owner_kinds(person: str) -> frozenset[str]:
    """A kind of person and the kinds it counts as for owning a place ("kid" -> kid, child)."""
    kind = OWNER_KINDS.get(person)
    return frozenset({person, kind} if kind else {person})


@lru_cache(maxsize=512)
def _query_vector(model: MiniLM, text: str) -> Vectors:
    vector: Vectors = model.encode([text])[0]
    return vector


def _reordered(run: Sequence[str], phrase: Sequence[str]) -> bool:
    """Whether a name with a number or a letter in it is said with its words in another order: "the B1
    desk" for "desk b1", "the 2 platform" for "platform 2", "the A counter" for "counter a"."""
    n = len(phrase)
    if n < 2 or not any(_IDENTIFIER.fullmatch(t) for t in phrase):
        return False
    wanted = sorted(phrase)
    return any(sorted(run[i:i + n]) == wanted for i in range(len(run) - n + 1))


_IDENTIFIER = re.compile(r"[a-z]?\d+[a-z]?|[a-z]")


def _contains(run: Sequence[str], phrase: Sequence[str]) -> bool:
    n = len(phrase)
    return any(tuple(run[i:i + n]) == tuple(phrase) for i in range(len(run) - n + 1))


_INDEXES: dict[int, tuple[World, PlaceIndex]] = {}


def place_index(world: World) -> PlaceIndex:
    """The index of `world`, built once per world object."""
    key = id(world)
    cached = _INDEXES.get(key)
    if cached is None or cached[0] is not world:
        if len(_INDEXES) > 16:
            _INDEXES.clear()
        cached = (world, PlaceIndex(world))
        _INDEXES[key] = cached
    return cached[1]
