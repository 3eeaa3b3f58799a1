"""Pass 4, in the sentence: the noun phrases in a place role ("to the pharmacy", "leave the ward", "on platform 2") and the world's place each names, with how sure that is.

Words are matched by the world's one place index (language/places.py), then by meaning when they do
not decide; a zone named before decides between fixtures alike ("On platform 2 ... the bench"); a phrase in a place role naming nothing of the world is an unknown place, unless a time, person, manner or building."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from grove_tui.language import lexicon as lx
from grove_tui.language.emptied import EmptiedZones
from grove_tui.language.handled_doors import handled_door_room
from grove_tui.language.held_on_to import held_on_to
from grove_tui.language.model import FieldConfidence
from grove_tui.language.people import People
from grove_tui.language.particle_names import first_lemma
from grove_tui.language.place_around import around, beside_thing, stairs
from grove_tui.language.place_idioms import is_idiom_phrase
from grove_tui.language.place_entrance import main_entrance
from grove_tui.language.place_kinds import absent_kind, gerund_before_room, gerund_kind, kind_continues, tier_place
from grove_tui.language.place_ordinals import ordinal_place
from grove_tui.language.place_number import said_in_number
from grove_tui.language.pronoun_places import may_be_place, pronoun_place
from grove_tui.language.outside_contrast import outside_contrasted
from grove_tui.language.outdoor_places import past_the_doors
from grove_tui.language.place_outside import zone_around
from grove_tui.language.place_of_zone import exit_of_room_said, ones_of_zone, thing_of_zone_said, zone_then_thing
from grove_tui.language.place_names import CHAT_TIME_WORDS, INFORMAL_SURE, TIME_NOUNS, TIME_WORDS, chat_ends_name, informal_at, informal_room
from grove_tui.language.place_meaning import Decided, PlaceMeaning, gerund_room
from grove_tui.language.named_owners import elided_owned, owned_by_name, owner_at, said_owner_name
from grove_tui.language.named_kinds import by_head_alone
from grove_tui.language.sibling_kinds import sibling_kind
from grove_tui.language.ridden_things import ridden_on
from grove_tui.language.worked_states import past_state
from grove_tui.language.worn_fixtures import worn_fixture
from grove_tui.language.place_possessed import own_rooms, owned_places
from grove_tui.language.its_places import its_place
from grove_tui.language.movers import carried_in, taken_in
from grove_tui.language.on_the_way import on_ones_way
from grove_tui.language.not_places import heading_adverb, infinitive_verb, no_place_said, not_a_place
from grove_tui.language.stage_parts import stage_part
from grove_tui.language.bare_alias_kinds import by_bare_alias, other_kind_of_room
from grove_tui.language.bare_place_names import bare_place_name
from grove_tui.language.where_elsewhere import elsewhere
from grove_tui.language.places import PlaceMatch
from grove_tui.language.other_possessors import other_of_kind, setting_words
from grove_tui.language.room_fixtures import fixture_of_room, fixtures_as_room, room_fixture_said
from grove_tui.language.room_numbers import bare_room_number
from grove_tui.language.sentence import IDENTIFIER, Sentence
from grove_tui.language.verb_after_place import verb_after_place
from grove_tui.language.noun_heads import hyphened_name_word, place_before_verb
from grove_tui.language.tokens import lemma, name_tokens, phrase_lemmas, verb_lemma
from grove_tui.language.to_things import to_a_thing_before


@dataclass
class Place:
    """A place phrase of the sentence and the world's place it names."""

    prep: str  # the preposition or "obj:start" / "obj:dest" / "obj:via" / "obj:at" for verb objects
    index: int  # word index of the preposition
    words: tuple[str, ...]
    match: PlaceMatch | None
    end: int = 0  # word index after the phrase
    score: float = 1.0  # how sure the match is (1.0: the phrase holds the place's whole name or an alias)
    reason: str = ""
    alternatives: tuple[str, ...] = ()  # other places the phrase fits as well
    sequel: bool = False  # said after the place before, in its role ("to the café and then the pharmacy")
    out_of: bool = False  # "out of the north doors": the "from" of "out of"
    written: str = ""  # the preposition as written ("from"), whatever role word it was read as


def place_confidences(roles: dict[str, str | None], via: Sequence[str],
                      read_from: dict[str, Place]) -> list[FieldConfidence]:
    """The confidence of each place field (start, destination, location, via) whose phrase was
    matched less than surely: a field not listed was read outright."""
    out: list[FieldConfidence] = []
    for name, value in [*roles.items(), *(("via", v) for v in via)]:
        place = read_from.get(value) if value else None
        if place is not None and place.score < 1.0:
            out.append(FieldConfidence(name, place.score, place.reason, place.alternatives))
    return out


class PlacePhrases(EmptiedZones, PlaceMeaning):
    """Place phrases of one sentence, read in order: it remembers the zones named so far, which
    decide later ties, and the phrases in a place role the world does not have."""

    def __init__(self, s: Sentence, people: People) -> None:
        self.s = s
        self.people = people
        self.unknown: list[str] = []
        self.unknown_towards: list[int] = []  # where "to"/"towards" a refused place is said: still a destination
        self.context_zones: list[str] = []  # zones of the places read so far, in reading order
        self.frame_zones: list[str] = []  # zones named as where people are ("on platform 2"), in order
        self.quiet = False  # True while reading a clause whose places nobody goes to
        self.owner: str | None = None  # the kind of people whose clause is read ("her office" is theirs)
        self.named: list[str] = []  # every place a phrase names, in reading order (not those nobody goes to)
        self.covered: set[int] = set()  # the words of every place phrase read
        self.fronted: dict[int, str] = {}  # sentence -> the zone its first words put it in ("At gate B2, ...")
        self.history: list[Place] = []  # every place read that people are at or go to, in reading order
        self.refused: set[int] = set()  # the words of informal names refused whole ("the hole in the wall")

    def phrase(self, k: int, prep: str, at: int, record_unknown: bool = True, mentioned: bool = True) -> Place | None:
        """The noun phrase from word k, after the place preposition (or verb) at `at`; `mentioned`
        False for a place said to be where nobody goes ("instead of the lobby")."""
        s, low = self.s, self.s.low
        prep = "to" if prep in ("at", "by", "in", "on", "near", "beside") and to_a_thing_before(s, at) else prep  # "to his cab by the exit"
        prep = "at" if prep in ("to", "onto") and held_on_to(s, at) else prep  # "cling to the barrier"
        if k in self.refused:
            return None  # "the wall" of "the hole in the wall", refused as one name
        record_unknown = record_unknown and prep != "between" and not no_place_said(s, k, prep, at)  # a time; a cause
        if on_ones_way(s, k, prep, at) or ridden_on(s, k, prep, at) or not_a_place(s, k, prep, at) or is_idiom_phrase(s, k, prep, at) and not self.names_place(k):
            return None  # "argue about a bug", "bursts into tears": a topic or a feeling, no place
        if k < s.n and (low[k] in ("where", "wherever", "upstairs", "downstairs") or may_be_place(s, k, prep, at)):
            return self.where_place(k, prep, at, mentioned)
        elided = k < s.n and (low[k] in ("hers", "theirs", "ours", "mine") or low[k] == "his" and (
            k + 1 >= s.n or s.is_punct(k + 1) or low[k + 1] in lx.CLAUSE_STARTERS))
        if elided and (owned := elided_owned(self, k, at)) is not None:
            # "the guards drink tea in their room while the director works in hers": her own room
            self.context_zones.append(owned[0].zone)
            if mentioned:
                self.named.append(owned[0].name)
            self.covered.add(k)
            return Place(prep, at, (low[k],), owned[0], k + 1, *owned[1:], written=low[at])
        things = [p.words for p in self.history if p.match is not None and p.match.kind != "zone"]
        if things and (ones := ones_of_zone(s.index, low, k, things[-1], self._words)):  # "not the ones in the bar"
            return self._record(Place(prep, at, tuple(low[k:ones[1]]), ones[0], ones[1], written=low[at]), k, mentioned)
        j = k
        if tuple(low[j:j + 2]) in (("one", "of"), ("each", "of"), ("any", "of"), ("some", "of")):
            j += 2  # "sits on one of the concourse benches": the benches
        while j < s.n and (low[j] in lx.DETERMINERS or low[j] in ("'s", "’s")):
            j += 1
        j = self.past_part(j)
        if j == k and prep in ("in", "at", "to", "by", "on", "from", "about", "around") and j < s.n and \
                not s.index.knows(lemma(low[j])) and "&" not in low[j] and not self.names_place(j) and not bare_place_name(low, j) and around(s.index, (lemma(low[j]),)) is None and not said_owner_name(s, j):  # "in A&E"; "at trackside": the track's; "to Priya Shah's office"
            return None  # "in line", "at once", "on time": no determiner and no place word
        if prep in ("through", "over") and at >= 1 and lx.INTENT_VERBS.get(verb_lemma(low[at - 1])) == "converse" \
                and not self.names_place(j):
            return None  # "talk through the roadmap", "chat over the plans": what they talk about
        start = j
        phrase, j = self._words(j)
        informal = self._informal(start, phrase, j)
        if informal is not None:
            phrase, j = informal[0], informal[1]  # "the hole in the wall": one name, not "hole" and "wall"
        if not phrase:
            return None
        if prep == "to" and start == k and informal is None and (len(phrase) == 1 and lx.INTENT_VERBS.get(verb_lemma(
                phrase[0])) is not None or infinitive_verb(s, k, at)) and not self.whole_name(phrase):
            return None  # "sit waiting to board", "to sign for": a verb, though "board" is a word of "departures board"
        lemmas = informal[2] if informal is not None else \
            tuple(phrase_lemmas(phrase)) or tuple(lemma(w) for w in phrase)
        if any(w in lx.ROBOT_WORDS for w in phrase) and not self.whole_name(phrase) or self.people.is_person_phrase(lemmas) and not absent_kind(s.index, lemmas):
            return None
        if lemmas and lemmas[-1] in lx.DURATION_UNITS:
            return None  # "in seconds", "within minutes": a time, though "second" starts a room's name
        said_before, j = ((d, j) if (d := self._said_before(k, at, lemmas) or ordinal_place(s.index, lemmas)) else main_entrance(s.index, lemmas, low, j, s.index.match(lemmas)) or (None, j))  # "that door", "the last lift", "the way in"
        match = said_before[0] if said_before is not None else None
        if prep == "out" and not set(lemmas) & lx.DOOR_WORDS:
            door = s.index.match((*lemmas, "door"))  # "out the back": out through the back door
            match = door if door is not None and door.kind == "door" else None
        match = match or self._in_context(s.index.match(lemmas), lemmas, k)
        if (of_zone := None if said_before else thing_of_zone_said(s.index, low, lemmas, match, j, self._words)):
            (said_before, j), match = of_zone, of_zone[0][0]  # "the door of court 2", "the robing room table"
        # "pitch-side", "by the water": the room around the thing
        thing = match if match is not None and match.exact else around(s.index, lemmas) or match
        match = beside_thing(s.index, prep, thing)
        beside = match is not thing  # the room around the thing: decided, whoever stands there
        match, said_before = room_fixture_said(s, k, j) or (fixture_of_room(s, k, j) or (match if prep == "on" else fixtures_as_room(s, k, j, lemmas, match)), said_before)
        possessive = k < s.n and low[k] in ("her", "his", "their", "my", "our", "its", "your")
        # "the kids' bed", "the director's desk": a person named as the owner inside the phrase
        named_owner = next((s.lemma(x) for x in range(k, j - 1) if low[x + 1] in ("'s", "'", "’s", "’")
                            and self.people.is_person_noun(x)), None)
        named_entry = s.index.entry(match.name) if named_owner and match is not None else None
        if named_entry is not None and named_owner in named_entry.tokens and lemmas and lemmas[-1] in named_entry.tokens:
            named_owner = None  # "the women's toilet": the owner is part of the place's own name
        owner = named_owner or (owner_at(s, self.owner, at) if possessive else None)  # "Little Tom's" a child
        owned = owned_by_name(s, at, k, lemmas) or (self._owned(lemmas, match, owner or "") if (owner or possessive) and said_before is None else None)
        owned = handled_door_room(s, prep, at, lemmas, owned[0] if owned else match, lambda ls: owned_by_name(
            s, at, k, ls) or (self._owned(ls, None, owner) if owner else None)) or owned  # "shuts her office door"
        if owned is None and possessive and low[k] == "its":  # "platform one ... through its emergency exit": that platform's
            owned = its_place(s.index, lemmas, [p.match.zone for p in self.history if p.match and p.match.kind == "zone"])
        if owned is not None:
            match = owned[0]
        if match is None and possessive:
            return None  # "on her rounds", "in their pyjamas": the person's own things, not a place to refuse
        if possessive and at >= 2 and low[at] in ("in", "on") and self.people.is_person_noun(at - 1) and \
                (any(verb_lemma(low[x]) in lx.LEADING_VERBS for x in range(max(0, at - 5), at - 1)) or taken_in(s, at)):
            return None  # "porters roll a patient in her bed": what carries the person moved, not a place
        if at >= 1 and k < s.n and (low[k] in ("a", "an") and (self.people.is_person_noun(at - 1) or carried_in(s, at, lemmas))
                                    or worn_fixture(s, k, at, j, match, self.people.is_person_noun)) \
                and (low[at] in ("in", "with") or (low[at] == "on" and match is None)):
            # "a woman in a wheelchair", "a man on crutches": what one has or wears ("on a bench" is a bench)
            return None
        if prep == "by" and lemmas and lemmas[-1] in lx.HELD_BY and (match is None or not match.exact):
            return None  # "leads a pupil by the arm", "by the scruff of his collar": where one is held, no place
        if match is not None and not match.exact and lemmas and lemmas[-1] in lx.NON_PLACES and not tier_place(lemmas):
            return None  # "off the train": a word that names no place, though an alias shares it
        numbered = any(IDENTIFIER.fullmatch(t) and not t.isalpha() for t in lemmas)
        if absent_kind(s.index, lemmas) is not None or owned is None and by_head_alone(s.index, lemmas, match) or (owned is None and other_of_kind(
                s.index, match, lemmas, setting_words(s, start, j, self.people.is_person_noun))):  # "the planetarium (room)", "the members' enclosure"
            numbered, match = True, None
        if match is not None and not self._identifiers_agree(lemmas, match):
            match = None  # "gate C4" where the gates are A1 to B2: a place the world does not have
        if match is None and past_the_doors(s, lemmas, at) and s.index.exits():
            # "to the street", "out to the car park": out through the exit nearest the scene
            exits = [m for e in s.index.exits() if (m := s.index.match(name_tokens(e))) is not None and m.kind == "door"]
            match = self._nearest_exit(exits) if exits and self.context_zones else exits[0] if exits else None
        kinds = tuple(t for t in lemmas[:-1] if t not in lx.PLACE_MODIFIERS) if informal is not None else \
            self.noun_modifiers(start, j, gerunds=gerund_kind(s, lemmas, j))
        if match is not None and (not match.exact or by_bare_alias(s.index, match, lemmas)) and owned is None and \
                (informal is not None or not self.modifiers_agree(
                    self.noun_modifiers(start, j, gerunds=gerund_kind(s, lemmas, j)),
                    match.name, phrase)) or other_kind_of_room(s.index, match, lemmas, kinds) or sibling_kind(s, start, j, match):
            match = None  # "the ice-cream stand" is no phone stand; an informal name is its whole name or near
        meant = None
        described = None if numbered else self._described(phrase, lemmas, j, match is not None and match.exact)
        if described is not None:
            # "the room where kids do crafts": the place by what happens there, the relative clause part of it
            meant, j = described
            match = meant[0]
        if match is None and not numbered and not s.index.is_nameless(lemmas):
            said = list(lemmas) if informal is not None else phrase  # an informal name by what it means
            meant = self._by_meaning(said, lemmas)  # "the eating area": no word of it names a place
            if meant is None and (record_unknown or prep == "named"):
                # about to be refused: a place the world has under another word ("the stockroom", "the
                # nurses' post") is still clearly nearest one of its names, if less near
                meant = self.rescued(said, lemmas)
            if meant is not None and not self.modifiers_agree(kinds, meant[0].name, head=lemmas[-1] if lemmas else ""):
                meant = None  # "the stockroom" is near "boardroom" by its letters, not by what it is
            match = meant[0] if meant is not None else None
        match = match or (stage_part(s.index, lemmas) if not numbered else None)  # "from the wings"
        if match is None and record_unknown and not self.quiet and not s.index.is_nameless(lemmas):
            self.unknown.append(" ".join(phrase))
            self.unknown_towards += [at] if prep in lx.DESTINATION_PREPOSITIONS else []
        if match is None:
            if informal is not None:
                self.refused.update(range(start, j))
            return None
        sure = owned[1:] if owned is not None else meant[1:] if meant is not None else \
            said_before[1:] if said_before is not None else None
        score, reason, alternatives = sure or self._confidence(phrase, lemmas, match)
        if not numbered and sure is None and not beside and not self._context_decided(match, alternatives):
            chosen = self._words_do_not_decide(phrase, lemmas, match, score, alternatives)
            if chosen is not None:
                match, (score, reason, alternatives) = chosen[0], chosen[1:]
        if informal is not None and score > INFORMAL_SURE:
            match, score = informal_room(s.index, lemmas, match), INFORMAL_SURE  # "the loo": the room, not its toilet
            reason = f"'{' '.join(phrase)}' is an informal name: read as '{' '.join(lemmas)}', {match.name}"
        if possessive and owned is None and not (match.exact or self._names_kind(lemmas, match)):
            return None  # "a film on her phone": her own thing, not a place that only shares a word ("phone shop")
        match = match if described else said_in_number(s.index, phrase, gerund_room(s.index, phrase, match))  # "at the till": the till counter
        if (out := zone_around(s, at, j, match)) is not None and \
                not outside_contrasted(s, at, out[0].name, self.history):  # "outside the pharmacy", "lined up for the Viper"
            match, reason = out
        return self._record(Place(prep, at, tuple(phrase), match, j, score, reason, alternatives,
                                  out_of=prep == "from" and s.low[at] == "out", written=s.low[at]), k, mentioned)

    def where_place(self, k: int, prep: str, at: int, mentioned: bool) -> Place | None:
        """"to where you get your bags back", "wait where the trains come in", "in it": the place so said."""
        found = self.where_clause(k) if self.s.low[k] in ("where", "wherever") else pronoun_place(self, k, prep, at) \
            if self.s.low[k] == "it" else stairs(self.s.index, k)  # "to where you go", "in it", "upstairs"
        if found is None:
            return None
        (match, score, reason, alternatives), end = found
        if (other := elsewhere(self.s.index, self.s, self.history, prep, at, self.s.low[k:end], match, alternatives,
                                reason)) is not None:
            match, alternatives, reason = other  # "from the pro shop to where ...": somewhere other than where they left
        return self._record(Place(prep, at, tuple(self.s.low[k:end]), match, end, score, reason, alternatives,
                                  written=self.s.low[at]), k, mentioned)

    def _record(self, place: Place, k: int, mentioned: bool) -> Place:
        """A place read: its zone decides later ties; a zone people are in frames the sentence."""
        s, match, at = self.s, place.match, place.index
        assert match is not None
        self.context_zones.append(match.zone)
        if match.kind == "zone" and place.prep in ("in", "at", "on", "inside", "within"):
            self.frame_zones.append(match.zone)
            if at == 0 or s.w[at - 1].sentence != s.w[at].sentence:
                self.fronted.setdefault(s.w[at].sentence, match.zone)  # "At gate B2, ...": the sentence's frame
        self.covered.update(range(k, place.end))
        if mentioned:
            self.named.append(match.name)
            self.history.append(place)
        return place

    def _names_kind(self, lemmas: Sequence[str], match: PlaceMatch) -> bool:
        """Whether the phrase's head is the kind of place matched ("ward" of ward_a) or a word for rooms."""
        content = [t for t in lemmas if t not in lx.PLACE_MODIFIERS]
        entry = self.s.index.entry(match.name)
        if not content or entry is None:
            return False
        kinds = {w for kind in entry.types for w in kind.split()} | (
            {w for kind in (self.s.index.entry(entry.zone) or entry).types for w in kind.split()})
        return content[-1] in kinds or content[-1] in lx.GENERIC_PLACE_HEADS

    def _context_decided(self, match: PlaceMatch, alternatives: Sequence[str]) -> bool:
        """Whether a zone the sentence named before chose between places alike (see _in_context)."""
        return bool(alternatives) and match.zone in self.context_zones

    def _owned(self, lemmas: Sequence[str], match: PlaceMatch | None, owner: str) -> Decided | None:
        """"her office", "their room", "the kids' bed": of the places named like the phrase, the one that belongs
        to the kind of person whose clause it is ("the director ... her office": the director's office), or a
        thing of that kind in a room of theirs ("mum ... her bed": the bed of the parents' bedroom)."""
        if not (content := [t for t in lemmas if t not in lx.PLACE_MODIFIERS]):
            return None
        head = content[-1]
        # their room called so, else a thing in a room of theirs ("the parents' bed"), else any of theirs
        owned = owned_places(self.s.index.entries, self.s.index.owned_by(owner) if owner else [], head)
        owned = own_rooms(self.s.index.entries, owned, lemmas) or owned  # "her room": a bedroom, not the residents' lounge
        mine = [e for e in owned if match is not None and e.name == match.name]
        if len(owned) > 1 and not mine:
            owned = [e for e in owned if e.kind == "zone"] or owned  # "her office": the room, not its door
        if not owned or (len(owned) != 1 and not mine and not all(o.kind == "zone" for o in owned)):
            return None  # the words may name it: then the owner decides a tie; else one of their rooms, seeded
        e = mine[0] if mine else owned[self.s.choose(0, len(owned) - 1, f"owned|{owner}|{head}")]
        return (PlaceMatch(e.name, e.kind, e.zone, match.score if match is not None else 1.0, False), 0.8,
                f"'{' '.join(lemmas)}' of a {owner}: {e.name}", ())  # "a patient ... his room": a ward of theirs

    def _words(self, j: int) -> tuple[list[str], int]:
        """The words of a place phrase from j, and the index after them."""
        s, low = self.s, self.s.low
        phrase: list[str] = []
        joined = False  # the word follows a hyphen inside the phrase ("check-in")
        while j < s.n and len(phrase) < 6:
            w = low[j]
            if w == "-" and phrase and j + 1 < s.n and low[j + 1][:1].isalnum() and s.hyphen_inside(j):
                joined = True
                j += 1
                continue
            if phrase and not joined and self._extends_name(phrase, j):
                phrase.append(w)  # "check in counter a": a preposition inside a name the world has
                j += 1
                continue
            if w in ("'s", "’s") or (w in ("'", "’") and phrase and phrase[-1].endswith("s") and
                                     s.w[j].tag == "POS"):
                j += 1  # "the parents' bed": the owner, then the thing
                continue
            if s.is_punct(j) or w in (">", "|") or (w in lx.CLAUSE_STARTERS and not joined) or \
                    w in ("who", "which", "that", "where", "for", "of", "with", "then", "to"):
                break
            if phrase and not joined and (self._time_starts(j) or chat_ends_name(
                    s, j, phrase, self.whole_name(phrase))):
                break  # "the coat counter b4 closing", "the lobby asap", "in lobby waitin 4 taxis": no more place
            if w in lx.PLACE_PREPOSITIONS and not joined and not (phrase and s.index.knows(lemma(w))) and not hyphened_name_word(s, j):
                break  # "the under-twos room": a preposition hyphened to a word of a name is one of its words
            after_hyphen, joined = joined, False
            if phrase and not after_hyphen and (self._verb_ends_name(phrase, j) or verb_after_place(s, phrase, j, self.whole_name)):
                break  # "key-cutting kiosk": one name; "the knife-skills course sidles away": a verb
            if phrase and w in lx.DETERMINERS and j + 1 < s.n and s.w[j + 1].pos in ("NOUN", "PROPN", "ADJ", "NUM") \
                    and not self._extends_name(phrase, j) and not self.whole_name([*phrase, w]):
                break  # "on platform 2 a man sits": the place ends where a new noun phrase starts
            if w.isdigit() or w in lx.UNITS:
                if not phrase and w.isdigit() and j > 0 and low[j - 1] in lx.DETERMINERS and j + 1 < s.n and \
                        s.index.knows(lemma(low[j + 1])) and not self.people.is_person_noun(j + 1):
                    phrase.append(w)  # "the 2 platform", "the 1 exam room": the number of a name, said first
                    j += 1
                    continue
                if (not phrase and not bare_room_number(s, j, self.people.is_person_noun)) or (phrase and any(  # "to 103"
                        ch.isdigit() for ch in phrase[-1]) and j + 1 < s.n and self.people.is_person_noun(j + 1)):
                    break  # "at gate A1 two agents chat", "on platform 1 three commuters": a count starts
                phrase.append(w if w.isdigit() else str(lx.UNITS[w]))
                j += 1
                continue
            if s.w[j].pos in ("ADV", "PRON", "ADP", "CCONJ", "SCONJ", "PART") and not after_hyphen and (not s.index.knows(
                    lemma(w)) or heading_adverb(s, phrase, j)) and not hyphened_name_word(s, j):
                break  # "from the recital hall back to the foyer": "back" heads on (no "back row")
            phrase.append(w)
            j += 1
            if s.w[j - 1].text.endswith(".") and len(s.w[j - 1].text) > 1:
                break  # "room b." at a sentence end: the full stop closes the phrase
        return phrase, j

    def _said_before(self, k: int, at: int, lemmas: Sequence[str]) -> Decided | None:
        """"the same exit", "that door", "this room": the place of that kind said last before, when the
        phrase points back at one; None otherwise."""
        s = self.s
        back = (s.low[k] == "the" and k + 1 < s.n and s.low[k + 1] == "same") or (
            s.low[k] in ("that", "this") and k + 1 < s.n and not s.is_verb(k + 1))
        content = [t for t in lemmas if t not in lx.PLACE_MODIFIERS]
        if not back or not content:
            return None
        fits = {m.name for m in s.index.candidates(lemmas)}
        anywhere = content[-1] in lx.GENERIC_PLACE_HEADS | lx.BUILDING_WORDS | {"spot", "point", "one"}
        for p in reversed(self.history):
            m = p.match
            entry = s.index.entry(m.name) if m is not None else None
            if m is not None and p.index < at and entry is not None and \
                    (anywhere or m.name in fits or s.index.names_word(entry, content[-1])):
                return (m, 0.9, f"'{' '.join(s.low[k:k + 1 + len(lemmas)])}': {m.name}, said before", ())
        return None

    def _informal(self, start: int, phrase: Sequence[str], j: int) -> tuple[list[str], int, tuple[str, ...]] | None:
        """An informal name or idiom at the start of a place phrase ("the hole in the wall", "the loo",
        "the caff counter"): its words as written, the index after them, and the lemmas it is matched
        by, what it means followed by the phrase's words after it ("cafe counter"). None when none
        starts there, or when the world calls a place by the phrase's own words ("the gents", "the
        lift lobby")."""
        s = self.s
        found = informal_at(s.low, start)
        if found is None or (phrase and self.whole_name(phrase)):
            return None
        end, plain = found
        written = [w for w in s.low[start:end] if w not in ("-", "'", "’")]
        rest = [w for w in s.low[end:j] if w not in ("-", "'", "’")] if j > end else []
        return [*written, *rest], max(end, j), tuple(phrase_lemmas([*name_tokens(plain), *rest]))

    def _time_starts(self, j: int) -> bool:
        """Whether a time phrase or a chat word starts at j, after a place phrase: "b4 closing", "2nite",
        "asap", "til 5", "till closing" (but "the book till": a till the world has, with no time after it)."""
        s, w = self.s, self.s.low[j]
        if w in CHAT_TIME_WORDS or w in TIME_WORDS:
            return not s.index.knows(w)  # "b4" may be a room of a world ("room b4")
        after = s.low[j + 1] if j + 1 < s.n else ""
        return w in ("till", "til", "until", "by", "before", "after") and (
            after[:1].isdigit() or after in TIME_WORDS or after in TIME_NOUNS)

    def _verb_ends_name(self, phrase: Sequence[str], j: int) -> bool:
        s = self.s
        w = s.low[j]
        if s.w[j].pos in ("VERB", "AUX") and not s.index.knows(lemma(w)) and not kind_continues(phrase, w) and \
                not gerund_before_room(s, j):  # "the old changing rooms": a kind of room, no verb
            return True
        if verb_lemma(w) in lx.INTENT_VERBS and s.index.knows(lemma(w)) and \
                not w.endswith("ing") and self.whole_name(phrase) and \
                not any(self.whole_name([*phrase, *s.low[j:end]]) for end in range(j + 1, min(j + 3, s.n) + 1)) \
                and (j + 1 >= s.n or not self.people.is_person_noun(j + 1)) and not exit_of_room_said(s, phrase, j):
            # "at gate B2 boards the plane", "the check-in hall queue at": a whole name, then a verb
            # that only happens to be a place word too ("departures board", the tag "queue"); but
            # "the pharmacy waiting chairs" and "the boardroom meeting" are names and nouns
            return True
        # "in the cafeteria evacuate": the verb after the place or the building ("gift shop" is a noun)
        return verb_lemma(w) in lx.INTENT_VERBS and not s.index.knows(lemma(w)) and (
            s.w[j].tag.startswith("VB") or place_before_verb(s, phrase, j))

    def _confidence(self, phrase: Sequence[str], lemmas: Sequence[str],
                    match: PlaceMatch) -> tuple[float, str, tuple[str, ...]]:
        """How sure a place match is, why, and the places that fit the phrase as well: a whole name or
        alias found and no other place like it is sure; a place only sharing words with the phrase
        is less so; two places scoring alike are unsure, unless a zone the prompt named before
        decides between them."""
        said = " ".join(phrase)
        alike = [m for m in self.s.index.candidates(lemmas) if m.score >= match.score - 1e-9]
        zones = {m.name for m in alike if m.kind == "zone"}
        tied = [m for m in alike if m.name != match.name
                and not (m.kind != "zone" and m.zone in zones)  # a fixture of a room alike is that room
                and not (m.kind == "zone" and match.zone == m.name)]
        alternatives = tuple(dict.fromkeys(m.name for m in tied))[:4]
        if alternatives and match.zone in self.context_zones:  # (this phrase's zone is not in it yet)
            return (0.7, f"'{said}' fits {len(alternatives) + 1} places; {match.name} is in {match.zone}, "
                         f"named before", alternatives)
        if alternatives:
            return 0.4, f"'{said}' fits {match.name} and {', '.join(alternatives)} alike", alternatives
        if not match.exact:
            return 0.75, f"'{said}' shares words with {match.name} but is not its name", ()
        return 1.0, "", ()

    def whole_name(self, phrase: Sequence[str]) -> bool:
        """Whether the words are exactly a name or alias of a place (determiners aside)."""
        lemmas = tuple(t for t in phrase_lemmas(list(phrase)) if t not in lx.PLACE_MODIFIERS)
        return bool(lemmas) and any(lemmas == p for e in self.s.index.entries for p in e.phrases)

    def _identifiers_agree(self, lemmas: Sequence[str], match: PlaceMatch) -> bool:
        """Whether every identifier of a place phrase ("c4", "2", the "b" of "ward b") belongs to the
        place matched or to one of the places it ties with: a number or letter names one place of a
        series, so a place whose series lacks it is not that place."""
        index = self.s.index
        ids = [t for k, t in enumerate(lemmas) if IDENTIFIER.fullmatch(t) and (k > 0 or not t.isalpha())]
        if not ids:
            return True
        entry = index.entry(match.name)
        return entry is None or all(t in entry.tokens for t in ids) or any(
            all(t in (index.entry(m.name) or entry).tokens for t in ids) for m in index.candidates(lemmas)[:8])

    def _in_context(self, match: PlaceMatch | None, lemmas: Sequence[str], k: int) -> PlaceMatch | None:
        """Of places that tie for a phrase ("the desk", "the jet bridge"), the one in the zone the
        sentence opened in ("At gate B2, ... two agents chat behind the desk"), else in a zone the
        prompt has already named ("Gate A1: ... staff at the desk")."""
        index = self.s.index
        if match is None:
            return match
        frame = self.fronted.get(self.s.w[min(k, self.s.n - 1)].sentence)
        if frame is not None and match.zone != frame:
            inside = [m for m in index.candidates(lemmas) if m.score >= match.score - 1e-9 and m.zone == frame]
            if inside:
                return inside[0]
        if not self.context_zones or match.zone in self.context_zones:
            tied = [m for m in index.candidates(lemmas) if m.score >= match.score - 1e-9]
            exits = [m for m in tied if (e := index.entry(m.name)) is not None and e.exit]
            if match.kind == "door" and exits and match not in exits and "exit" in lemmas:
                return exits[0]  # "the exit" is an exit door, whichever named "..._exit" ties with it
            return match
        candidates = index.candidates(lemmas)
        tied = [m for m in candidates if m.score >= match.score - 1e-9]
        exits = [m for m in tied if (e := index.entry(m.name)) is not None and e.exit]
        if exits and (len(exits) == len(tied) or "exit" in lemmas):
            # "the exit": an exit door (not a door only named "..._exit" inside the building), the one
            # nearest the places the sentence is about
            return self._nearest_exit(exits)
        for zone in reversed(self.context_zones):
            for m in tied:
                if m.zone == zone:
                    return m
        if match.kind != "entity":
            return match  # a room or door named outright is that one, wherever the sentence was before
        # "On platform 2 a man sits on the bench": a fixture of the zone named before, called by the
        # phrase's own words, though another zone's fixture has them as its whole name (only a zone
        # the people are in, "on platform 2", "in the pharmacy", not one they leave)
        content = [t for t in lemmas if t not in lx.PLACE_MODIFIERS]
        for zone in reversed(self.frame_zones):
            for m in candidates:
                entry = index.entry(m.name)
                if m.zone == zone and m.kind == "entity" and entry is not None and set(content) <= entry.tokens:
                    return m
        return match

    def _nearest_exit(self, exits: Sequence[PlaceMatch]) -> PlaceMatch:
        world = self.s.index.world
        centres = [world.zone(z).centroid for z in dict.fromkeys(self.context_zones)]
        cx = sum(c[0] for c in centres) / len(centres)
        cy = sum(c[1] for c in centres) / len(centres)
        def distance(m: PlaceMatch) -> float:
            door = world.find(m.name)
            x, y = getattr(door, "position", (cx, cy))
            return math.hypot(x - cx, y - cy)

        return min(exits, key=lambda m: (distance(m), m.name))

    def _extends_name(self, phrase: Sequence[str], j: int) -> bool:
        """Whether the words from j on continue `phrase` into a longer whole name or alias of the world."""
        s = self.s
        if s.low[j] not in ("in", "of", "and", "on", "up", "out"):
            return False  # "to", "from", "through" ... always mark a new place: never inside a name
        here = s.index.match(phrase_lemmas(list(phrase)))
        for end in range(j + 2, min(j + 4, s.n) + 1):
            extended = phrase_lemmas(list(phrase) + s.low[j:end])
            longer = s.index.match(extended)
            if longer is None or not longer.exact or (here is not None and here.exact and longer.name == here.name):
                continue
            # every word of the longer phrase must be the one place's: "check in counter a", not
            # "ward c to the nurses" (two places either side of a preposition)
            entry = s.index.entry(longer.name)
            if entry is not None and all(t in entry.tokens for t in extended) and \
                    (s.low[j] != "and" or any(" and " in said for said in entry.said)):  # not "the lifts and 2 cleaners"
                return True
        return False

    def past_part(self, k: int) -> int:
        """Past "the corner of", "the far end of" at k: a part of a place is the place."""
        s = self.s
        j = k
        while j < s.n and j < k + 3 and (s.low[j] in lx.PLACE_MODIFIERS or lemma(s.low[j]) in lx.PLACE_PARTS):
            j += 1
        if j > k and j < s.n and s.low[j] == "of" and lemma(s.low[j - 1]) in lx.PLACE_PARTS or j < s.n - 2 and \
                lemma(s.low[j]) == "row" and s.low[j + 1] == "of" and self.names_place(j + 2):  # "the back row of screen 2"
            return s.skip(j + 1 if s.low[j] == "of" else j + 2, lx.DETERMINERS)
        return past_state(s, k)  # "the jammed pinsetter": the pinsetter, in a state

    def names_place(self, k: int) -> bool:
        """Whether the words at k name a place of the world by its whole name or an alias ("ward a")."""
        s = self.s
        k = self.past_part(k)
        words: list[str] = []
        for j in range(k, min(k + 4, s.n)):
            if s.is_punct(j) and not s.hyphen_inside(j) or (words and s.low[j] in lx.PLACE_PREPOSITIONS | {"to", "for"}):
                break  # "queue at the copier": the name ends where another place phrase starts
            words.append(s.low[j])
        for n in range(len(words), 0, -1):
            match = s.index.match(phrase_lemmas(words[:n]))
            if match is not None and match.exact:
                # the name starts here: "to pick up wheelchairs" is a purpose, though "wheelchairs" is a name
                entry = s.index.entry(match.name)
                first = first_lemma([w for w in words[:n] if w not in lx.DETERMINERS], lemma)  # "make-up": makeup
                lemmas = phrase_lemmas(words[:n])  # "the banqueting tables": the tables of the banqueting suite
                return entry is None or first in entry.tokens or zone_then_thing(s.index, lemmas, match) is not None
        return False

    def scan_names(self, skip: set[int]) -> None:
        """Places the sentence names in no place role ("a fire alarm empties the pharmacy", "the lobby is
        busy"): a whole name or alias starting a noun phrase, for the scenario; never an unknown place."""
        s = self.s
        k = 0
        while k < s.n:
            starts = k not in self.covered and k not in skip and (
                k == 0 or s.low[k - 1] in lx.DETERMINERS or s.is_punct(k - 1)) and not s.is_punct(k)
            if starts and self.names_place(k):
                place = self.phrase(k, "named", k, record_unknown=False)
                if place is not None:
                    k = max(place.end, k + 1)
                    continue
            k += 1

    def scan_unknown(self, tokens: Sequence[int]) -> None:
        """Read every place phrase of these words, for the unknown places among them."""
        for i in tokens:
            prep = self.s.preposition(i)
            if prep is not None:
                self.phrase(i + prep[1], prep[0], i)
