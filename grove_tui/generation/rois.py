"""Strategic layer: which Regions of Interest of the world the prompt is about.

Semantic tokens of the prompt are matched against the world's one place index (language/places.py:
zone, door and entity names split on underscores, types, tags, aliases, with the reader's
lemmatiser) with IDF-weighted lexical scoring, a small table of place synonyms and, when given, an
embedding similarity. Each prompt word selects the RoIs that
match it best, so "pharmacy counter" picks the counter (and through it the pharmacy) rather than
every counter. Zones nobody mentions are dropped from the bt model's context; a place the prompt
names that the world does not have is an error listing the closest real names.
"""

from __future__ import annotations

import difflib
import json
import math
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

from grove_tui.generation.presets import Preset, PromptError
from grove_tui.language import lexicon as lx
from grove_tui.language.lexicon import NUMBER_WORDS, PERSON_NOUNS, STOPWORDS
from grove_tui.language.places import PlaceEntry, place_index
from grove_tui.language.reading import PromptReading, read_prompt
from grove_tui.language.tokens import lemma, name_tokens, words

# The word tables (place synonyms, determiners, place modifiers, door and behavior words, locatives)
# are the one lexicon's: language/lexicon.py.
SYNONYMS = lx.PLACE_SYNONYMS
_LOCATIVES = lx.LOCATIVE_WORDS
_BREAKS = frozenset(_LOCATIVES) | {"and", "or", "while", "then", "with", "but", "where", "when"}
_DETERMINERS = lx.DETERMINERS
_PLACE_MODIFIERS = lx.PLACE_MODIFIERS


@dataclass(frozen=True)
class RoIMatch:
    kind: str  # "zone" | "door" | "entity"
    name: str
    zone: str
    score: float
    matched: tuple[str, ...]  # prompt tokens that selected it; empty when added by a rule
    reason: str  # "prompt" | "preset" | "container" | "default" | "model"


@dataclass
class RoISelection:
    """What the strategic layer hands on: selected RoIs, their zones, and the text the bt model sees."""

    matches: list[RoIMatch]
    zones: list[str]  # selected zone names, in prompt order
    named_zones: list[str]  # zones the prompt itself names (directly or through a door/entity), for grounding
    summary: str  # compact description of the selected RoIs for the bt model
    roi_names: list[str] = field(default_factory=list)  # every name the draft may use as a target
    exits: list[str] = field(default_factory=list)  # exit door names offered to the model

    @property
    def names(self) -> list[str]:
        return [m.name for m in self.matches]


@dataclass(frozen=True)
class _Entry:
    kind: str
    name: str
    zone: str
    tokens: frozenset[str]  # names, aliases and type: what people call it
    tag_tokens: frozenset[str]  # tags: what it is for; weaker evidence
    phrases: tuple[tuple[str, ...], ...]  # name and aliases, lemmatised, for whole-phrase matches
    obj: Any


BEHAVIOR_WORDS = lx.BEHAVIOR_WORDS
DOOR_WORDS = lx.DOOR_WORDS


def _contains(run: Sequence[str], phrase: Sequence[str]) -> bool:
    n = len(phrase)
    return any(tuple(run[i:i + n]) == tuple(phrase) for i in range(len(run) - n + 1))


def _name_tokens(text: str) -> list[str]:
    """A name's words as the prompt side sees them: the place index's lemmas, stopwords out (the
    prompt's words are stripped of them too, so "ward a" meets the prompt as "ward")."""
    return [t for t in name_tokens(text) if t not in STOPWORDS]


def _entry(place: PlaceEntry, obj: Any) -> _Entry:
    """The strategic layer's view of one entry of the place index (language/places.py)."""
    phrases = tuple(p for p in (tuple(t for t in phrase if t not in STOPWORDS) for phrase in place.phrases) if p)
    return _Entry(place.kind, place.name, place.zone, frozenset(place.tokens - STOPWORDS),
                  frozenset(place.tag_tokens - STOPWORDS), phrases, obj)


class RoIMatcher:
    """The world's places, from the one place index, matched against a whole prompt; build once per world."""

    def __init__(self, world: Any, embed: Callable[[list[str]], Any] | None = None) -> None:
        self.world = world
        self._embed = embed
        self.index = place_index(world)
        objects: dict[str, Any] = {}
        for zone in world.zones:
            objects[zone.name] = zone
            objects.update((door.name, door) for door in zone.doors)
            objects.update((entity.name, entity) for entity in zone.entities)
        self.entries: list[_Entry] = [_entry(place, objects[place.name]) for place in self.index.entries]
        self.idf = self.index.idf
        self.vocabulary = frozenset(t for t in self.index.vocabulary if t not in STOPWORDS)
        self._embeddings: Any = None  # (entries, dim) float32, computed at the first query

    # ---- scoring ------------------------------------------------------------------------------

    def _token_weight(self, entry: _Entry, token: str) -> float:
        if token in entry.tokens:
            return self.idf.get(token, 0.0)
        for group in SYNONYMS:
            if token in group:
                hits = [t for t in entry.tokens if t in group]
                if hits:
                    return 0.6 * max(self.idf.get(t, 0.0) for t in hits)
        if token in entry.tag_tokens and token not in BEHAVIOR_WORDS:
            return 0.5 * self.idf.get(token, 0.0)
        return 0.0

    def runs(self, entry: _Entry, tokens: Sequence[str | None]) -> list[tuple[float, int, int]]:
        """(score, first, last) of each mention of the entry: a maximal run of consecutive prompt words it matches.

        Words of one run name one thing ("pharmacy counter"); words far apart ("kitchen ... living room
        ... front door") are separate mentions, so an RoI whose name happens to share words with several
        of them does not add them up.
        """
        out: list[tuple[float, int, int]] = []
        i = 0
        n = len(tokens)
        while i < n:
            t = tokens[i]
            w = self._token_weight(entry, t) if t is not None else 0.0
            if w <= 0:
                i += 1
                continue
            j, total = i, 0.0
            while j < n and (tj := tokens[j]) is not None and (wj := self._token_weight(entry, tj)) > 0:
                total += wj
                j += 1
            run = [t for t in tokens[i:j] if t is not None]
            literal = set(run) & entry.tokens
            if entry.kind == "door" and not (literal & (DOOR_WORDS | set(_name_tokens(entry.name)) - self._zone_words)):
                i = j
                continue
            if all(t in BEHAVIOR_WORDS for t in run) and not any(len(p) > 1 and _contains(run, p) for p in entry.phrases):
                # "wait", "queue" alone describe what people do, even when a name contains the word
                i = j
                continue
            for phrase in entry.phrases:
                if _contains(run, phrase):
                    # The whole name or an alias is in the prompt: it beats anything sharing one of its words.
                    total += 0.5 + 0.5 * sum(self.idf.get(t, 0.0) for t in phrase)
                    break
            out.append((total, i, j - 1))
            i = j
        return out

    @property
    def _zone_words(self) -> set[str]:
        if not hasattr(self, "_zone_words_cache"):
            self._zone_words_cache = {t for e in self.entries if e.kind == "zone" for t in e.tokens}
        return self._zone_words_cache

    def _place_tokens(self, prompt: str) -> list[str | None]:
        """Prompt words that can name a place, None where a word breaks a mention (numbers, person words)."""
        raw: list[str | None] = []
        toks = words(re.sub(r"'s\b", "", prompt))
        for i, w in enumerate(toks):
            if w in _BREAKS and not self._locative_as_noun(toks, i):
                raw.append(None)  # "the coffee machine in the cafeteria" mentions two places
            elif w not in STOPWORDS:
                raw.append(lemma(w))
        out: list[str | None] = []
        for i, t in enumerate(raw):
            if t is None:
                out.append(None)
                continue
            if t in NUMBER_WORDS or t in PERSON_NOUNS:
                nxt = raw[i + 1] if i + 1 < len(raw) else None
                # Person words count only inside a place name ("nurse station", "doctor's office").
                if t in NUMBER_WORDS or nxt is None or not any(t in e.tokens and nxt in e.tokens for e in self.entries):
                    out.append(None)
                    continue
            out.append(t)
        return out

    def _locative_as_noun(self, toks: Sequence[str], i: int) -> bool:
        """"the exit", "the nearest exit", "emergency exit": a locative verb the world knows as a place, used as a noun."""
        w = toks[i]
        if w not in _LOCATIVES or not self._known(lemma(w)) or i == 0:
            return False
        before = toks[i - 1]
        return before in _DETERMINERS or before in _PLACE_MODIFIERS or lemma(before) in self.vocabulary

    def _embedding_bonus(self, prompt: str) -> dict[str, float]:
        if self._embed is None:
            return {}
        import numpy as np

        if self._embeddings is None:
            texts = [f"{e.name.replace('_', ' ')} {' '.join(sorted(e.tokens))}" for e in self.entries]
            self._embeddings = np.asarray(self._embed(texts), dtype=np.float32)
        query = np.asarray(self._embed([prompt]), dtype=np.float32)[0]
        sims = self._embeddings @ query
        return {e.name: float(s) for e, s in zip(self.entries, sims)}

    # ---- selection ----------------------------------------------------------------------------

    def match(self, prompt: str) -> list[RoIMatch]:
        """RoIs the prompt names: for each mention, the best-scoring RoIs; a zone beats its own parts on a tie."""
        tokens = self._place_tokens(prompt)
        bonus = self._embedding_bonus(prompt)
        best_at: dict[int, list[tuple[float, _Entry, int, int]]] = {}
        for e in self.entries:
            extra = 0.5 * max(bonus.get(e.name, 0.0), 0.0)
            for score, first, last in self.runs(e, tokens):
                for k in range(first, last + 1):
                    best_at.setdefault(k, []).append((score + extra, e, first, last))
        chosen: dict[str, tuple[float, _Entry, int, tuple[str, ...]]] = {}
        for k in sorted(best_at):
            holders = best_at[k]
            top = max(h[0] for h in holders)
            winners = [h for h in holders if h[0] >= top - 1e-9]
            zones = {h[1].name for h in winners if h[1].kind == "zone"}
            for score, e, first, last in winners:
                if e.kind != "zone" and e.zone in zones:
                    continue  # "the restroom": the room, not every fixture whose name repeats it
                matched = tuple(t for t in tokens[first:last + 1] if t is not None)
                if e.name not in chosen or chosen[e.name][0] < score:
                    chosen[e.name] = (score, e, first if e.name not in chosen else min(first, chosen[e.name][2]), matched)
        ordered = sorted(chosen.values(), key=lambda v: (v[2], -v[0], v[1].name))
        ordered = self._one_exit_per_mention(ordered)
        return [RoIMatch(e.kind, e.name, e.zone, round(score, 4), matched, "prompt") for score, e, _, matched in ordered]

    def _one_exit_per_mention(self, ordered: list) -> list:
        """"the exit" matches every exit door equally; a person means one: the exit nearest the other places
        the prompt names (the world's first exit when it names none)."""
        mentions: dict[int, list] = {}
        for item in ordered:
            mentions.setdefault(item[2], []).append(item)
        tied_doors = {id(item) for items in mentions.values()
                      if len(items) > 1 and all(i[1].kind == "door" for i in items) for item in items}
        anchors = [self._position(item[1]) for item in ordered
                   if not (item[1].kind == "door" and getattr(item[1].obj, "exit", False)) and id(item) not in tied_doors]
        drop: set[str] = set()
        for items in mentions.values():
            exits = [item for item in items if item[1].kind == "door" and getattr(item[1].obj, "exit", False)]
            if not exits or any(item[1].kind != "door" for item in items) or \
                    len({round(item[0], 6) for item in items}) > 1:
                continue
            # "the exit" also ties doors only named "..._exit" inside the building: it means an exit door
            drop |= {item[1].name for item in items if item not in exits}
            if len(exits) < 2:
                continue
            if anchors:
                cx = sum(p[0] for p in anchors) / len(anchors)
                cy = sum(p[1] for p in anchors) / len(anchors)
                keep = min(exits, key=lambda item: (math.dist(self._position(item[1]), (cx, cy)), item[1].name))
            else:
                order = [d.name for d in self.world.exits()]
                keep = min(exits, key=lambda item: order.index(item[1].name) if item[1].name in order else len(order))
            drop |= {item[1].name for item in exits if item is not keep}
        return [item for item in ordered if item[1].name not in drop]

    @staticmethod
    def _position(entry: _Entry) -> tuple[float, float]:
        obj = entry.obj
        if entry.kind == "zone":
            return tuple(obj.centroid)
        if entry.kind == "door":
            return tuple(obj.position)
        return tuple(obj.interaction_point)

    def unknown_places(self, prompt: str) -> list[str]:
        """Noun phrases in a place role ("to the swimming pool") that name nothing in the world: the
        prompt reader's answer (language/reading.py), the one rule for what is a place."""
        return list(read_prompt(prompt, self.world).unknown_places)

    def _known(self, token: str) -> bool:
        return self.index.knows(token)

    def close_matches(self, phrase: str, n: int = 5) -> list[str]:
        names = [e.name for e in self.entries]
        label = {e.name.replace("_", " "): e.name for e in self.entries}
        for e in self.entries:
            for t in e.tokens:
                label.setdefault(t, e.name)
        hits = difflib.get_close_matches(phrase.lower(), list(label), n=n * 2, cutoff=0.4)
        out = list(dict.fromkeys(label[h] for h in hits))
        if len(out) < n:
            # Fall back to the zones themselves so the user always sees what exists.
            out += [z.name for z in self.world.zones if z.name not in out]
        return [name for name in out if name in names][:n]


def select_rois(world: Any, preset: Preset, prompt: str, matcher: RoIMatcher | None = None,
                max_default_zones: int = 3, reading: PromptReading | None = None) -> RoISelection:
    """The strategic layer: RoIs named by the prompt plus what the preset needs, summarised.

    Places the reading gives a role (start, destination, location, via) are always selected, so the
    model may name them; only the reading's unknown places (noun phrases in a place role) are refused."""
    matcher = matcher or RoIMatcher(world)
    unknown = list(reading.unknown_places) if reading is not None else matcher.unknown_places(prompt)
    if unknown:
        parts = [f"'{p}' (closest: {', '.join(matcher.close_matches(p))})" for p in unknown]
        raise PromptError(f"the prompt names a place world '{world.name}' does not have: " + "; ".join(parts))
    if preset.context == "world":
        return _whole_world(world, matcher.match(prompt))
    matches = matcher.match(prompt)
    have = {m.name for m in matches}
    for name in reading_places(reading):
        if name not in have:
            obj = world.find(name)
            kind = "zone" if hasattr(obj, "entities") else "door" if hasattr(obj, "leads_to") else "entity"
            matches.append(RoIMatch(kind, name, obj.name if kind == "zone" else obj.zone, 0.0, (), "reading"))
            have.add(name)
    named_zones = list(dict.fromkeys(m.zone for m in matches))
    if not matches:
        # Nothing named: the busiest hubs (most doors) make a plausible default stage.
        hubs = sorted(world.zones, key=lambda z: (-len(world.doors_of(z.name)), -z.area, z.name))[:max_default_zones]
        matches = [RoIMatch("zone", z.name, z.name, 0.0, (), "default") for z in hubs]
    selected = {m.name for m in matches}
    for m in list(matches):
        if m.kind != "zone" and m.zone not in selected:
            matches.append(RoIMatch("zone", m.zone, m.zone, 0.0, (), "container"))
            selected.add(m.zone)
    exits: list[str] = []
    if "exits" in preset.required_rois:
        for door in world.exits():
            exits.append(door.name)
            if door.name not in selected:
                matches.append(RoIMatch("door", door.name, door.zone, 0.0, (), "preset"))
                selected.add(door.name)
    zones = list(dict.fromkeys(m.zone if m.kind != "zone" else m.name for m in matches if m.kind == "zone" or m.reason != "preset"))
    roi_names = list(dict.fromkeys(m.name for m in matches))
    summary = summarize(world, zones, {m.name for m in matches}, exits)
    return RoISelection(matches, zones, named_zones or zones, summary, roi_names, exits)


def reading_places(reading: PromptReading | None) -> list[str]:
    """Every place the reading gives a role, in group order."""
    if reading is None:
        return []
    names: list[str] = []
    for g in reading.groups:
        names += [p for p in (g.start, g.location, *g.via, g.destination) if p]
    return list(dict.fromkeys(names))


def _whole_world(world: Any, named: list[RoIMatch]) -> RoISelection:
    zones = [z.name for z in world.zones]
    everything = []
    for z in world.zones:
        everything.append(RoIMatch("zone", z.name, z.name, 0.0, (), "world"))
        everything += [RoIMatch("door", d.name, z.name, 0.0, (), "world") for d in z.doors]
        everything += [RoIMatch("entity", e.name, z.name, 0.0, (), "world") for e in z.entities]
    exits = [d.name for d in world.exits()]
    names = [m.name for m in everything]
    named_zones = list(dict.fromkeys(m.zone for m in named)) or zones
    return RoISelection(everything, zones, named_zones, summarize(world, zones, set(names), exits, full=True), names, exits)


def _fmt(v: float) -> str:
    return f"{v:.1f}".rstrip("0").rstrip(".") if abs(v - round(v)) > 1e-9 else str(int(round(v)))


def _pt(p: Sequence[float]) -> str:
    return f"({_fmt(p[0])},{_fmt(p[1])})"


def summarize(world: Any, zones: Sequence[str], selected: set[str], exits: Sequence[str], full: bool = False) -> str:
    """The selected places as the bt model reads them.

    Guided presets get one line per selected zone naming exactly the places the draft may use there
    (its selected doors and entities), then the exits: no coordinates, boundaries or descriptions,
    because the model writes names only and post-processing resolves them to points (issue 20: the
    long form cost ~100 tokens per zone of prefill). `full` (the vanilla baseline) lists the whole
    zone with boundary, door positions, tags and descriptions, as the paper's baseline does.
    """
    if not full:
        return _compact_summary(world, zones, selected, exits)
    lines: list[str] = []
    for name in zones:
        z = world.zone(name)
        head = f"zone {z.name} ({z.type})"
        if z.aliases:
            head += " aka " + ", ".join(z.aliases)
        lines.append(f"{head}: {z.description}".rstrip(": ") if z.description else head)
        lines.append("  boundary: " + " ".join(_pt(p) for p in z.boundary))
        if z.tags:
            lines.append("  tags: " + ", ".join(z.tags))
        doors = [d for d in world.doors() if d.zone == z.name or d.leads_to == z.name]
        if doors:
            parts = []
            for d in doors:
                other = d.leads_to if d.zone == z.name else d.zone
                parts.append(f"{d.name} {_pt(d.position)} to {other}" + (" EXIT" if d.exit else ""))
            lines.append("  doors: " + "; ".join(parts))
        ents = list(z.entities)
        if ents:
            parts = []
            for e in ents:
                text = f"{e.name} ({e.type}) at {_pt(e.interaction_point)}"
                if e.description:
                    text += f" - {e.description}"
                parts.append(text)
            lines.append("  entities: " + "; ".join(parts))
    if exits:
        exit_doors = [d for d in world.exits() if d.name in exits]
        lines.append("exits: " + "; ".join(f"{d.name} {_pt(d.position)} in {d.zone}" for d in exit_doors))
    return "\n".join(lines)


def _compact_summary(world: Any, zones: Sequence[str], selected: set[str], exits: Sequence[str]) -> str:
    """`- pharmacy (pharmacy): pharmacy_counter (counter), pharmacy_door (door to main_corridor)` per zone."""
    lines: list[str] = []
    shown: set[str] = set()
    for name in zones:
        z = world.zone(name)
        places = [f"{e.name} ({e.type})" for e in z.entities if e.name in selected]
        shown |= {e.name for e in z.entities if e.name in selected}
        for d in world.doors():
            if d.name in selected and d.name not in shown and (d.zone == z.name or d.leads_to == z.name):
                other = d.leads_to if d.zone == z.name else d.zone
                places.append(f"{d.name} ({'exit' if d.exit else 'door to ' + other})")
                shown.add(d.name)
        lines.append(f"- {z.name} ({z.type})" + (": " + ", ".join(places) if places else ""))
    rest = [d for d in world.exits() if d.name in exits and d.name not in shown]
    if rest:
        lines.append("- exits: " + ", ".join(f"{d.name} (in {d.zone})" for d in rest))
    return "\n".join(lines)


def describe_selection(selection: RoISelection) -> list[dict[str, Any]]:
    """JSON-ready record of the selection for generation.json."""
    return [{"kind": m.kind, "name": m.name, "zone": m.zone, "score": m.score, "matched": list(m.matched),
             "reason": m.reason} for m in selection.matches]



def ambiguous_mentions(selection: RoISelection) -> list[list[RoIMatch]]:
    """Prompt matches that tie on the same words ("the restroom" -> men's and women's): the model may choose."""
    groups: dict[tuple[tuple[str, ...], float], list[RoIMatch]] = {}
    for m in selection.matches:
        if m.reason == "prompt":
            groups.setdefault((m.matched, m.score), []).append(m)
    return [g for g in groups.values() if len(g) > 1]


def refine_with_model(world: Any, preset: Preset, prompt: str, selection: RoISelection, llm: Any, seed: int = 0,
                      cancel: Any = None) -> tuple[RoISelection, int, int]:
    """Let the roi model pick one RoI per ambiguous mention, under a grammar that only allows the candidates.

    Returns the refined selection and the prompt/completion tokens spent. Unambiguous matches are
    never touched, so a weak model can only choose between places the prompt already named.
    """
    from grove_tui.llm.grammar import schema_to_gbnf

    prompt_tokens = completion_tokens = 0
    dropped: set[str] = set()
    for group in ambiguous_mentions(selection):
        names = [m.name for m in group]
        lines = []
        for m in group:
            obj = world.find(m.name)
            aliases = ", ".join(getattr(obj, "aliases", ()) or ())
            lines.append(f"- {m.name}" + (f" ({aliases})" if aliases else ""))
        messages = [
            {"role": "system", "content": "You choose which place a sentence means. Answer with JSON only."},
            {"role": "user", "content": f"Sentence: {prompt}\nThe words '{' '.join(group[0].matched)}' could mean:\n"
                                        + "\n".join(lines) + '\nAnswer {"place": NAME}.'},
        ]
        schema = {"type": "object", "properties": {"place": {"enum": names}}, "required": ["place"],
                  "additionalProperties": False}
        generation = llm.generate(messages, grammar=schema_to_gbnf(schema), max_tokens=32, seed=seed, cancel=cancel)
        prompt_tokens += generation.prompt_tokens
        completion_tokens += generation.completion_tokens
        try:
            choice = json.loads(generation.text)["place"]
        except (ValueError, KeyError, TypeError):
            continue  # the grammar makes this unreachable; keeping every candidate is the safe answer
        if choice in names:
            dropped |= set(names) - {choice}
    if not dropped:
        return selection, prompt_tokens, completion_tokens
    kept = [m for m in selection.matches if m.name not in dropped]
    # A zone that was only there to contain a dropped door or entity goes too.
    kept = [m for m in kept if m.reason != "container" or any(k.zone == m.name and k.kind != "zone" for k in kept)]
    zones = list(dict.fromkeys(m.zone for m in kept if m.reason != "preset"))
    named = [z for z in selection.named_zones if z in zones]
    summary = summarize(world, zones, {m.name for m in kept}, selection.exits)
    return (RoISelection(kept, zones, named or zones, summary, [m.name for m in kept], selection.exits),
            prompt_tokens, completion_tokens)
