"""Place phrases read by meaning, a mixin of language/place_phrases.py: a phrase no word of which
names a place ("the eating area"), a phrase whose words do not decide between places alike ("the main
meeting room"), and a place described by what happens there ("the counter where you hire a car").
Meaning is the sentence-embedding model of language/meaning.py, through the world's one place index.
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.activity_rooms import room_saying_it
from grove_tui.language.activity_verbs import room_saying_words
from grove_tui.language.bare_alias_kinds import other_kind_of_room
from grove_tui.language.boarding import boarding_place
from grove_tui.language.clause_objects import joins_listed_things, room_of_listed
from grove_tui.language.from_where import from_where_ends
from grove_tui.language.done_there import gerund_room as gerund_room, room_doing_it, zone_saying
from grove_tui.language.rescue_heads import only_modifier_shared
from grove_tui.language.related_words import to_another_where
from grove_tui.language.done_to_people import done_to_people
from grove_tui.language.model import UNSURE_BELOW
from grove_tui.language.participle_places import participle_said, participle_starts
from grove_tui.language.phrasal_after import particle_after
from grove_tui.language.people import People
from grove_tui.language.place_described import (DESCRIBED_ACCEPT, plain_activity, purpose_by_use, rank_described,
                                                room_with, vehicle_stop)
from grove_tui.language.place_compounds import KIND_HEADS, modified_otherwise, noun_like_adjective
from grove_tui.language.place_doers import named_doers
from grove_tui.language.place_of_zone import served_at
from grove_tui.language.place_first_words import names_its_zone
from grove_tui.language.place_head_clauses import fixture_named_by_head, head_described, room_named_by_head
from grove_tui.language.place_other_kinds import kind_agrees
from grove_tui.language.places import MeaningMatch, PlaceMatch, owner_kinds
from grove_tui.language.place_where_things import where_things_are
from grove_tui.language.where_served import room_of_used_fixture
from grove_tui.language.where_rooms import other_room_saying_it, room_doing_where
from grove_tui.language.user_kinds import USER_KINDS
from grove_tui.language.sentence import IDENTIFIER, Sentence
from grove_tui.language.service_purposes import served_point, service_done
from grove_tui.language.tokens import lemma, verb_lemma
from grove_tui.language.building_modifiers import of_no_building

# A place matched by meaning alone: at least this similar to one of its names, and this much nearer
# than any place of another zone (measured on synonyms and absent places of every shipped world,
# none of them from the understanding sets: tests/language/test_meaning.py).
MEANING_ACCEPT = 0.75
MEANING_MARGIN = 0.03
# A word match that only shares some words with the phrase gives way to a place of another name
# nearer in meaning: at least this similar, and this much nearer than the word match itself.
# A phrase about to be refused as a place the world lacks: accepted by meaning when less near
# ("the stockroom" is 0.64 from "supply room"), but then far ahead of any other zone; the absent places
# of the shipped worlds' tests and sets come no nearer than 0.59 ("bowling alley" to "dining area").
MEANING_RESCUE = 0.62
MEANING_RESCUE_MARGIN = 0.08
# A place described by what happens there ("the counter where you leave your bags"): the phrase and
# its clause together, this near one of the place's names.
MEANING_DESCRIBED = 0.65
# The clause alone ("where you hire a car") against the names of the places its head can be: the
# activities of places the worlds have come at 0.45-0.89, those of places they lack ("where you do yoga",
# "where you hire a car" in a station) no nearer than 0.43.
MEANING_ACTIVITY = 0.5
# ... but when the head names a kind ("the counter", "the room"), the words read one of those places
# anyway, and the clause only chooses which: it may when this near and clearly ahead ("where books are
# borrowed and returned" is 0.48 from "lending desk", 0.38 from the next desk).
MEANING_ACTIVITY_CHOOSES = 0.35
# A place of the people whose clause it is wins when this near the nearest ("the room they sleep in").
MEANING_OWNED = 0.06
# A word before the head that names a kind of place ("ice-cream" stand, "stock" room, "cash" machine)
# and no word of the place matched must be this near one of its names, or it rules the place out:
# "ice cream" is 0.26 from the phone stand, "stock" 0.27 from the boardroom, "cash" 0.23 from the
# x-ray machine; "stock" is 0.34 from the supply room, "drug" 0.63 from the pharmacy.
MODIFIER_AGREES = 0.3
# ... unless it is a word for what the whole building is about ("train" 0.47 from "station", "flight" 0.64
# from "airport"; "maternity" is 0.40 from "hospital", "stock" 0.28 from "office").
MODIFIER_OF_BUILDING = 0.45
# A modifier only this near (0.3-0.45) leaves it to the whole phrase, when the words matched the place
# by its head alone: the phrase must be this near one of the place's names ("chek in hall" 0.72 from the
# check-in hall, "stock room" 0.64 from the supply room; "vending machines" 0.55 from self-checkout machines).
MODIFIER_SURE = 0.45
PHRASE_AGREES = 0.58
# A purpose that names no place ("to get a cup of water", "to sketch the sarcophagus"), against the
# places' names, when the sentence gives no place to go to: the places of the purposes people write
# come at 0.50-0.82, those of purposes no place serves ("to get some fresh air", "to meet a friend")
# no nearer than 0.35.
MEANING_PURPOSE = 0.5
MEANING_STRONG = 0.8
MEANING_CLEARER = 0.05
Decided = tuple[PlaceMatch, float, str, tuple[str, ...]]

class PlaceMeaning:
    """The meaning half of the place phrases: a mixin of PlacePhrases, which owns the sentence."""

    s: Sentence
    people: People
    owner: str | None

    def noun_modifiers(self, first: int, end: int, gerunds: bool = False) -> tuple[str, ...]:
        """The words before a place phrase's head that say what kind of place it is ("ice cream" of "the
        ice-cream stand", "stock" of "the stockroom"), not how it looks ("the vast hall"), whose it is
        ("the nurses' post"), which of a series ("gate 2") or the building ("the station café")."""
        s = self.s
        index = s.index
        at = [x for x in range(first, end) if not s.is_punct(x) and s.low[x] not in lx.DETERMINERS
              and s.low[x] not in ("'s", "’s", "'", "’") and s.lemma(x) not in lx.PLACE_MODIFIERS
              and not IDENTIFIER.fullmatch(s.low[x])]
        if len(at) == 1:
            word = s.lemma(at[0])
            if word in index.vocabulary or len(word) < 7:
                return ()
            # "stockroom", "mailroom": a word the world lacks, made of a kind and a word for places it has
            return next(((word[:n],) for n in range(3, len(word) - 3) if word[n:] in index.zone_words), ())
        return tuple(s.low[x] if s.w[x].tag == "VBG" else s.lemma(x) for x in at[:-1]
                     if (s.w[x].pos in ("NOUN", "PROPN", "X") or (gerunds and s.w[x].tag == "VBG")  # "vending"
                         or (gerunds and noun_like_adjective(s, x)))  # "the pet shop": tagged an adjective
                     and s.lemma(x) not in index.building_words and (
                         not self.people.is_person_noun(x) or s.lemma(x) in USER_KINDS))  # "the staff entrance"

    def modifiers_agree(self, modifiers: Sequence[str], name: str, phrase: Sequence[str] = (), head: str = "") -> bool:
        """Whether the words that say what kind of place a phrase means fit the place `name`: each is
        one of its words (or a synonym), or together they are near one of its names or its room's. A
        phrase given (a place the words matched by its head alone) must then also be near the place as a
        whole, unless the modifiers are clearly near: "vending machines" shares "machines" with the
        self-checkout machines, and "vending" is 0.38 from them, but the phrase is only 0.55 from them."""
        index = self.s.index
        entry = index.entry(name)
        head = lemma(phrase[-1]) if phrase else head  # the head alone: a place read by meaning
        if entry is not None and other_kind_of_room(index, PlaceMatch(entry.name, entry.kind, entry.zone, 0.0, False),
                                                    (*modifiers, head), modifiers):
            return False  # "the bike shop" is no newsagent, though the newsagent is also "the shop"
        if entry is not None and entry.kind != "zone" and modifiers and head in lx.GENERIC_PLACE_HEADS and \
                head not in entry.tokens and not set(modifiers) & entry.tokens:
            return False  # "the tv room" is no boardroom screen, a "tv" only by a synonym: a room, not a fixture
        strange = [t for t in modifiers if entry is not None and (not index.names_word(entry, t) or (
            t not in entry.tokens and _synonym_of(t, head)))]  # "vending" is a synonym of the head "machine" only
        if not strange or entry is None:
            return True
        if any(t in USER_KINDS and t not in entry.tag_tokens for t in strange):
            return False  # "the staff entrance" of a mall with no entrance for staff (user_kinds.py)
        said = " ".join(strange)
        near = index.by_meaning(said, among={entry.name, entry.zone})
        if not near or index.near_building(said) >= MODIFIER_OF_BUILDING:  # "the train platform" of a station
            return True
        if head not in lx.GENERIC_PLACE_HEADS and modified_otherwise(entry, strange, head):
            # "the garden centre" is no "travel centre": the place's own modifier says what kind it is,
            # so the phrase's must be near the place itself (its room, "the concourse", says nothing of it)
            near = [r for r in near if r.entry.name == entry.name]
            if not near or (head in KIND_HEADS and near[0].similarity < MODIFIER_SURE) or \
                    not kind_agrees(entry, strange, head):  # "petrol" is no "coffee": "the petrol kiosk" no coffee kiosk
                return False  # a building word's modifier is all its kind: "conference" is 0.33 from "travel"
        closest = max(r.similarity for r in near)
        if closest < MODIFIER_AGREES:
            return False
        if closest >= MODIFIER_SURE or len(phrase) < 2:  # "stockroom": one word, a synonym of the place's
            return True
        whole = index.by_meaning(" ".join(phrase), among={entry.name})
        return not whole or whole[0].similarity >= PHRASE_AGREES

    def _by_meaning(self, phrase: Sequence[str], lemmas: Sequence[str], accept: float = MEANING_ACCEPT,
                    margin: float = MEANING_MARGIN) -> Decided | None:
        """The place a phrase no word of which names one means, when one is clearly nearest: similar
        enough to one of its names (`accept`), and clearly nearer than any place of another zone
        (`margin`)."""
        content = [t for t in lemmas if t not in lx.PLACE_MODIFIERS]
        speaks_of_door = bool(set(content) & lx.DOOR_WORDS)
        ranked = [r for r in self.s.index.by_meaning(" ".join(phrase)) if r.entry.kind != "door" or speaks_of_door]
        if not ranked or ranked[0].similarity < accept:
            return None
        best = ranked[0]
        other = next((r for r in ranked[1:] if r.entry.zone != best.entry.zone), None)
        ahead = best.similarity - (other.similarity if other is not None else 0.0)
        if ahead < margin:
            return None
        margin = ahead
        zone = next((r for r in ranked[1:] if r.entry.name == best.entry.zone), None)
        if best.entry.kind != "zone" and zone is not None and best.similarity - zone.similarity < MEANING_MARGIN:
            best = zone  # "the x-ray room": the room, though the machine's name is as near
        said = " ".join(phrase)
        # below MEANING_ACCEPT only to spare a refusal: unsure, so the app asks ("the stockroom: supply_room?")
        score = 0.7 if best.similarity >= 0.85 and margin >= 0.08 else 0.55 if best.similarity >= MEANING_ACCEPT \
            else 0.45
        alternatives = (other.entry.name,) if other is not None and score < UNSURE_BELOW else ()
        return (PlaceMatch(best.entry.name, best.entry.kind, best.entry.zone, best.similarity, False), score,
                f"'{said}' is read by meaning as {best.entry.name} (like '{best.nearest}')", alternatives)

    def rescued(self, phrase: Sequence[str], lemmas: Sequence[str]) -> Decided | None:
        """A phrase about to be refused, read by meaning less strictly (MEANING_RESCUE): as written, then
        in the singular ("the stores" comes nearer "drugstore" by its letters, 0.69, than "store room",
        0.61; "store" is 0.77 from the store room and far ahead of the pharmacy)."""
        phrase, lemmas = of_no_building(self.s.index, phrase, lemmas)  # "the hospital canteen": a canteen
        meant = self._by_meaning(phrase, lemmas, accept=MEANING_RESCUE, margin=MEANING_RESCUE_MARGIN)
        if meant is None and list(lemmas) != [w for w in phrase if w not in lx.DETERMINERS]:
            meant = self._by_meaning(lemmas, lemmas, accept=MEANING_RESCUE, margin=MEANING_RESCUE_MARGIN)
        return None if meant is not None and only_modifier_shared(self.s.index, lemmas, meant[0].name) else meant

    def _described(self, phrase: Sequence[str], lemmas: Sequence[str], j: int,
                   exact: bool = False) -> tuple[Decided, int] | None:
        """The place a phrase followed by a relative clause means ("the counter where you hire a car",
        "the place you buy tickets", "the room they take X-rays in"), and the index after the clause;
        None when no place is clearly it.

        The clause says what is done there: it alone is compared by meaning with the names of the
        places the phrase's head can be (a counter is a counter, desk or till; a room is a room; a
        "place" or "spot" is anything), and the nearest is taken when near enough and clearly ahead
        of any other zone's; failing that, the phrase and its clause together, as near as a name."""
        s = self.s
        content = [t for t in lemmas if t not in lx.PLACE_MODIFIERS]
        if exact and not head_described(s, content, j):
            return None  # a place's whole name: the clause after it says what is done there, not which
        if content and content[-1] in _ANY_PLACE | lx.GENERIC_PLACE_HEADS | {"hall"} and j < s.n and s.low[j] == "with":
            return room_with(s.index, s.low, j)  # "the room with the projector": the room that has it
        clause = self._relative_clause(j, bare=bool(content) and content[-1] in _ANY_PLACE | lx.BUILDING_WORDS |
                                        lx.GENERIC_PLACE_HEADS)
        if clause is None:
            return None
        first, end = clause
        said = participle_said(s, first, self._active(first, end))
        activity = plain_activity(("" if s.low[first] == "for" else "where ") + said)
        meant = self._by_clause(phrase, lemmas, content, activity, j, end)
        doers, named = named_doers(s, first, said)
        if doers != said and named and (theirs := self._by_clause(phrase, lemmas, content, plain_activity(
                ("" if s.low[first] == "for" else "where ") + doers), j, end)) is not None and \
                theirs[0].name in {e.name for e in s.index.owned_by(named)}:
            # "the room where they decide on their verdict", the jury's: said of the jury, it is their room
            meant = theirs
        if meant is not None and exact:  # "the pool where toddlers have lessons": the teaching pool, not its tank
            meant = (room_named_by_head(s.index, meant[0], content[-1]), *meant[1:])
        elif meant is not None and content:  # "the counter that does fried chicken": the chicken shop's counter
            meant = (fixture_named_by_head(s.index, meant[0], content[-1]), *meant[1:])
        return (meant, end) if meant is not None else None

    def _by_clause(self, phrase: Sequence[str], lemmas: Sequence[str], content: Sequence[str], activity: str,
                   j: int, end: int) -> Decided | None:
        """The place a head and the activity of its relative clause (words j to end) describe, or None."""
        s = self.s
        meant = None if vehicle_stop(activity) else self._by_activity(phrase, lemmas, activity)
        head = content[-1] if content else "place"
        kinds = None if head in _ANY_PLACE | lx.BUILDING_WORDS else \
            [e.name for e in s.index.entries if _head_fits(head, e.kind, e.tokens)]
        # by names and descriptions together, among the places the head can be: a head that names a kind
        # ("the office") is read anyway, so the clause may choose when less near; and a room whose
        # description says it ("students hand in coursework" at the school office) beats one only named
        # like the head ("head of department's office")
        both = rank_described(s.index, activity, kinds, accept=DESCRIBED_ACCEPT if kinds is None else
                              MEANING_ACTIVITY_CHOOSES) if meant is None or kinds is not None else None
        theirs = {e.name for e in s.index.entries if e.owners & owner_kinds(self.owner)} if self.owner else set()
        if both is not None and (meant is None or both[0].zone != meant[0].zone and both[0].score > meant[0].score
                                 and not (meant[0].name in theirs and self._alike(both[0].name, meant[0].name))):
            # "the room they sleep in": their own bedroom, though the parents' is as near
            meant = both
        if meant is None and s.low[j] == "where":
            meant = self._by_meaning([*phrase, *s.low[j:end]], lemmas, accept=MEANING_DESCRIBED, margin=MEANING_MARGIN)
        if meant is not None and meant[1] < 0.6 and meant[0].kind == "zone" and \
                (said := room_saying_words(s.index, activity, meant[0], kinds)) is not None:
            # "the room where film gets developed": the darkroom, whose "developing sinks" say it
            meant = (said, meant[1], f"'{activity}' is said in the words of {said.name}", ())
        return meant if meant is not None or head not in _ANY_PLACE else room_doing_it(s.index, activity)

    def _alike(self, one: str, other: str) -> bool:
        """Whether two places are of one kind (two bedrooms, two desks)."""
        a, b = self.s.index.entry(one), self.s.index.entry(other)
        return a is not None and b is not None and bool(a.types & b.types)

    def where_clause(self, k: int) -> tuple[Decided, int] | None:
        """A place said only by what is done there, a clause with no head ("walk to where you get your
        bags back", "wait where the trains come in"): the place, and the index after the clause."""
        if (things := where_things_are(self.s.index, self.s.low, k)) is not None:
            return things  # "to where the washers and dryers are": the room holding them
        clause = self._relative_clause(k, bare=False)
        if clause is None or self.s.low[k] not in ("where", "wherever"):
            return None
        first, end = clause
        activity = plain_activity("where " + self._active(first, end))
        meant = (None if vehicle_stop(activity) else self._by_activity(("place",), ("place",), activity)) or \
            rank_described(self.s.index, activity) or room_doing_it(self.s.index, activity)
        if meant is None:
            return None
        meant = room_doing_where(self.s.index, activity, room_of_listed(self.s, self.people, first, end, meant))
        return room_of_used_fixture(self.s.index, other_room_saying_it(self.s.index, activity, meant)), end

    def _active(self, first: int, end: int) -> str:
        """The clause's words, a passive said as what people do there: "the old maps are kept" is "you keep
        the old maps", "books are borrowed and returned" "you borrow and return books"; what is done
        to a thing is nearer in meaning to the names of the place where people do it."""
        s = self.s
        said = s.span(first, end - 1).lower()
        aux = next((x for x in range(first, end - 1) if s.low[x] in _PASSIVE_AUX and s.w[x + 1].tag == "VBN"), None)
        if aux is None or aux == first or done_to_people(s, first, aux):
            return said  # "where guests get powdered": what is done to them, said as it was
        verbs = [aux + 1]
        x = aux + 2
        while x + 1 < end and s.low[x] in ("and", "or", ",") and s.w[x + 1].tag == "VBN":
            verbs.append(x + 1)
            x += 2
        thing = " ".join(w for w in s.low[first:aux] if w not in ("where", "that", "which"))
        rest = " ".join(w for w in s.low[x:end] if w not in ("by",))
        done = " and ".join(s.w[v].lemma.lower() for v in verbs)
        return " ".join(part for part in ("you", done, thing, rest) if part)

    def _relative_clause(self, j: int, bare: bool) -> tuple[int, int] | None:
        """The words of the relative clause at j, after its marker ("where", "that", "which", or none
        after a word for any place, `bare`: "the place you buy tickets"), as (first, end); None when no
        clause starts at j ("in the hall people wait" is a new clause)."""
        s = self.s
        if j >= s.n:
            return None
        if s.low[j] in ("where", "wherever", "that", "which"):
            first = j + 1
            if s.low[j] not in ("where", "wherever") and not (first < s.n and (s.is_verb(first) or s.low[first] in _SUBJECTS)):
                return None  # "the desk that morning": no clause
        elif s.low[j] == "for" and j + 1 < s.n and not any(
                w[:1].isdigit() or w in lx.UNITS or w in ("a", "an", "while", "ages", "long", "now", "good")
                or lemma(w) in lx.DURATION_UNITS for w in s.low[j + 1:j + 4]):
            first = j  # "the desk for car hire", "the room for x-rays"; not "for ten minutes", "for a while"
        elif bare and s.low[j] in _SUBJECTS and j + 1 < s.n and (s.is_verb(j + 1) or s.w[j + 1].tag == "MD"):
            first = j  # "the place you buy tickets", "the spot people leave their bags"
        elif bare and participle_starts(s, j):
            first = j  # "the place serving tea and scones"
        else:
            return None
        end = first
        while end < s.n and end < first + 10 and (not s.is_punct(end) or s.hyphen_inside(end)) and \
                not (s.low[end] in lx.CLAUSE_STARTERS and end > first and not self._joins_inside(first, end)
                     and not particle_after(s, end)) \
                and not to_another_where(s.low, end) and not from_where_ends(s.low, first, end):  # "from where they rent skis to where ...": two places
            end += 1
        if end < first + 2:
            return None  # "the room where": no clause to read
        return first, end

    def _joins_inside(self, first: int, at: int) -> bool:
        """Whether the "and" or "or" at `at` joins words inside a relative clause rather than starting a
        new one: things before the clause's verb ("where the maps and rare books are kept"), or a verb
        like the one before it ("where books are borrowed and returned")."""
        s = self.s
        if s.low[at] not in ("and", "or") or at + 1 >= s.n:
            return False
        if joins_listed_things(s, self.people, first, at):
            return True  # "where they sell tropical fish and rabbits": both things the clause's verb has
        verbs = [x for x in range(first, at) if s.is_verb(x) and s.low[x] not in _PASSIVE_AUX]
        if not verbs:
            return not s.is_verb(at + 1) and not self.people.is_person_noun(at + 1)
        return s.w[at + 1].tag == s.w[verbs[-1]].tag and s.w[at + 1].tag in ("VBN", "VBD", "VBP", "VB")

    def _by_activity(self, phrase: Sequence[str], lemmas: Sequence[str], activity: str) -> Decided | None:
        """The place where an activity is done ("where you hire a car"), among the places the phrase's
        head can be, by the meaning of the activity alone."""
        index = self.s.index
        content = [t for t in lemmas if t not in lx.PLACE_MODIFIERS]
        head = content[-1] if content else "place"
        kinds = [e.name for e in index.entries if _head_fits(head, e.kind, e.tokens)]
        ranked = index.by_meaning(activity, among=kinds)
        named = head not in _ANY_PLACE and head not in lx.BUILDING_WORDS
        # A head that names a kind ("the counter", "the room") is read whatever the clause says: the
        # clause then only chooses among those places, so it may choose when less near
        if not ranked or ranked[0].similarity < (MEANING_ACTIVITY_CHOOSES if named else MEANING_ACTIVITY):
            return None
        best = ranked[0]
        theirs = {e.name for e in index.owned_by(self.owner)} if self.owner else set()
        own = next((r for r in ranked if r.entry.name in theirs), None)
        if own is not None and best.similarity - own.similarity < MEANING_OWNED:
            # "the kids run to the room they sleep in": their bedroom, though the parents' is as near
            ranked = [own, *(r for r in ranked if r is not own)]
            best = own
        other = next((r for r in ranked[1:] if r.entry.zone != best.entry.zone), None)
        margin = best.similarity - (other.similarity if other is not None else 0.0)
        if margin < MEANING_MARGIN and best is not own:
            return None
        zone = next((r for r in ranked[1:] if r.entry.name == best.entry.zone), None)
        if best.entry.kind != "zone" and zone is not None and best.similarity - zone.similarity < MEANING_MARGIN \
                and head in _ANY_PLACE | lx.BUILDING_WORDS:
            best = zone  # "the place where you leave your luggage": the room, though its lockers are as near
        if head in _ANY_PLACE | lx.BUILDING_WORDS and (room := room_saying_it(index, best, activity) or
                                                      zone_saying(index, activity, best)) is not None:
            best = room  # "to where their fingerprints get scanned": the room its description says it of
        fixture = next((r for r in ranked[1:] if r.entry.zone == best.entry.name and r.entry.kind == "entity"), None)
        if best.entry.kind == "zone" and fixture is not None and head not in _ANY_PLACE | lx.BUILDING_WORDS and \
                head not in ("room", "hall") and best.similarity - fixture.similarity < MEANING_MARGIN:
            best = fixture  # "the counter for prescriptions": the pharmacy's counter, not the pharmacy
        said = " ".join(phrase)
        score = 0.7 if best.similarity >= 0.6 and margin >= 0.08 else 0.55 if best.similarity >= MEANING_ACTIVITY \
            else 0.45
        alternatives = (other.entry.name,) if other is not None and score < UNSURE_BELOW else ()
        return (PlaceMatch(best.entry.name, best.entry.kind, best.entry.zone, best.similarity, False), score,
                f"'{said} {activity}' is read by what is done there as {best.entry.name} (like '{best.nearest}')",
                alternatives)

    def _words_do_not_decide(self, phrase: Sequence[str], lemmas: Sequence[str], match: PlaceMatch, score: float,
                             alternatives: Sequence[str]) -> Decided | None:
        """Meaning, where words do not decide: places alike ("the main meeting room": the boardroom
        and both meeting rooms share "meeting room"), a thing's name inside a phrase headed by a room
        word ("the mummy gallery" is no mummy), a phrase that shares only a word for rooms with its
        match ("the snack area": only "area"), or only some of its words ("the drug store" shares
        "store" with the store room, and means the drugstore)."""
        if (alternatives and score < UNSURE_BELOW) or self._headed_elsewhere(lemmas, match):
            return self._nearest_of(phrase, lemmas, match, alternatives)
        if match.exact:
            return None
        entry = self.s.index.entry(match.name)
        content = [t for t in lemmas if t not in lx.PLACE_MODIFIERS]
        shared = set(content) & (entry.tokens if entry is not None else set())
        meant = self._by_meaning(phrase, lemmas)
        if shared <= lx.GENERIC_PLACE_HEADS:
            # only "area" or "room" in common: the word match says nothing
            return meant or (match, 0.5, f"'{' '.join(phrase)}' shares only '{' '.join(sorted(shared))}' with "
                                         f"{match.name}", ())
        if meant is None or meant[0].name == match.name or meant[0].score < MEANING_STRONG or (
                entry is not None and meant[0].zone == match.name and len(content) == 1 and
                names_its_zone(self.s.index.entries, entry, content[0])):  # "into departures": the lounge
            return None
        own = self.s.index.by_meaning(" ".join(phrase), among={match.name})
        if own and meant[0].score - own[0].similarity < MEANING_CLEARER:
            return None
        return meant

    def _headed_elsewhere(self, lemmas: Sequence[str], match: PlaceMatch) -> bool:
        """Whether a fixture or door matched by its whole name sits inside a phrase whose head is a
        word for rooms it lacks ("the mummy gallery", "the coffee area")."""
        content = [t for t in lemmas if t not in lx.PLACE_MODIFIERS]
        entry = self.s.index.entry(match.name)
        return bool(content) and match.kind != "zone" and match.exact and entry is not None and \
            content[-1] not in entry.tokens and content[-1] in self.s.index.zone_words

    def _nearest_of(self, phrase: Sequence[str], lemmas: Sequence[str], match: PlaceMatch,
                    alternatives: Sequence[str]) -> Decided | None:
        """Of the places the phrase's words point at (the match, the places alike and any place
        sharing one of its words), the one nearest in meaning, when it is clearly nearer; a room
        when the phrase's head is a word for rooms."""
        index = self.s.index
        said = " ".join(phrase)
        content = [t for t in lemmas if t not in lx.PLACE_MODIFIERS]
        if (entry := index.entry(match.name)) is not None and entry.exit and "exit" in content:
            return None  # "the exit": any exit is one; the nearest to the scene was chosen, meaning adds nothing
        rooms_only = self._headed_elsewhere(lemmas, match)
        strong = [r.entry.name for r in index.by_meaning(said)[:3] if r.similarity >= MEANING_ACCEPT]
        among = {match.name, *alternatives, *index.sharing(content), *strong}
        ranked = [r for r in index.by_meaning(said, among=among) if r.entry.kind == "zone" or not rooms_only]
        if len(ranked) < 2:
            return None
        best, margin = ranked[0], ranked[0].similarity - ranked[1].similarity
        zone = next((r for r in ranked[1:] if r.entry.name == best.entry.zone), None)
        if best.entry.kind != "zone" and zone is not None and best.similarity - zone.similarity < MEANING_MARGIN:
            best = zone  # "the whale gallery": the room, though its whale is as near
            margin = best.similarity - max(r.similarity for r in ranked if r.entry.zone != best.entry.zone)
        elif margin < MEANING_MARGIN:
            return None
        score = 0.7 if margin >= 0.08 else 0.55
        rest = tuple(r.entry.name for r in ranked[:4] if r.entry.name != best.entry.name)
        return (PlaceMatch(best.entry.name, best.entry.kind, best.entry.zone, match.score, False), score,
                f"'{said}' fits {', '.join([best.entry.name, *rest])} by words; by meaning {best.entry.name} "
                f"(like '{best.nearest}')", rest if score < UNSURE_BELOW else ())


    def purpose_place(self, purpose: str) -> Decided | None:
        """The place a purpose is done at ("to get a cup of water": the water dispenser, "to grab a
        coffee": the café, "to print something": the printer), by meaning, when one is clearly
        nearest; less sure than a place said, so the app asks when it is not near."""
        words = purpose.lower().replace("-", " ").split()
        while words and words[0] in ("to", "in", "order", "so", "as", "for"):
            words = words[1:]
        if (boarded := boarding_place(self.s.index, words)) is not None:
            return boarded  # "run for the train": a platform (boarding.py)
        verb = verb_lemma(words[0]) if words else ""
        # "to board his plane" is no departures board: a verb that is only a word of a place's name
        # ("check in" still names the check-in hall)
        ranked = [r for r in self.s.index.by_meaning(purpose.lower()) if r.entry.kind != "door" and
                  (not _heads(verb, r.entry.phrases) or (words[1:2] in (["in"], ["out"], ["up"], ["off"], ["on"])
                                                   and any(p[:1] == (verb,) for p in r.entry.phrases)))]
        by_name = _clearly_nearest(ranked)
        # what the world says a place is for ("Queue-number ticket dispenser.") answers "to take a queue
        # number" where no name does: it decides when its place is clearly nearest and nearer than the
        # name match, or no name is clearly nearest; within the name match's own room the names decide
        by_use = _clearly_nearest([r for r in self.s.index.by_description(purpose.lower()) if
                                   not _heads(verb, r.entry.phrases) or words[1:2] in (["in"], ["out"], ["up"])])
        if by_use is not None and (by_name is None or (by_use[0].similarity > by_name[0].similarity and
                                                       by_use[0].entry.zone != by_name[0].entry.zone)):
            best, other = by_use
        elif by_name is not None:
            best = served_at(self.s.index, ranked, by_name[0])  # "to get a coffee": the café's coffee counter
            other = by_name[1] if best is by_name[0] else by_name[0]
        else:
            return purpose_by_use(self.s.index, purpose)  # "to buy aspirin and plasters": the pharmacy
        score = 0.65 if best.similarity >= 0.7 else 0.55
        alternatives = (other.entry.name,) if other is not None and score < UNSURE_BELOW else ()
        found = PlaceMatch(best.entry.name, best.entry.kind, best.entry.zone, best.similarity, False)
        found = served_point(self.s.index, found) if service_done(words) else found  # "to get his prescription filled"
        return (gerund_room(self.s.index, words, found), score,  # "to fingerprinting"
                f"'{purpose}' names no place; by meaning it is done at {best.entry.name} (like '{best.nearest}')",
                alternatives)

def _heads(verb: str, phrases: Sequence[Sequence[str]]) -> bool:
    """Whether a purpose's verb is the head noun of one of a place's names ("to board" and "departures
    board"), not a word before it ("to print" and "print station": where printing is done)."""
    return any(p and p[-1] == verb for p in phrases)


def _synonym_of(word: str, head: str) -> bool:
    """Whether `word` is listed as a synonym of `head` ("vending" of "machine")."""
    return bool(head) and any(word in group and head in group for group in lx.PLACE_SYNONYMS)


def _clearly_nearest(ranked: Sequence[MeaningMatch]) -> tuple[MeaningMatch, MeaningMatch | None] | None:
    """The nearest place of a ranking and the nearest of another zone, when it is near enough for a
    purpose and clearly ahead of that other one."""
    if not ranked or ranked[0].similarity < MEANING_PURPOSE:
        return None
    best = ranked[0]
    other = next((r for r in ranked[1:] if r.entry.zone != best.entry.zone), None)
    if best.similarity - (other.similarity if other is not None else 0.0) < MEANING_CLEARER:
        return None
    return best, other


# Who does what is done at a place, in a relative clause with no marker ("the place you buy tickets").
_SUBJECTS = frozenset("you they we people one i he she staff passengers visitors patients kids children "
                      "travellers customers shoppers".split())
# The auxiliaries of a passive ("the maps are kept", "parcels get collected").
_PASSIVE_AUX = frozenset("is are was were be been being get gets got".split())
# Heads that say only "a place": what is done there decides among every room and fixture.
_ANY_PLACE = frozenset("place spot area space zone section part region corner point bit location one".split())


def _head_fits(head: str, kind: str, tokens: frozenset[str]) -> bool:
    """Whether a place of this kind and these words can be what a phrase with this head calls it: "the
    room" a room, "the counter" a counter, desk, till or booth, "the place" anything but a door."""
    if kind == "door":
        return head in lx.DOOR_WORDS
    if head in _ANY_PLACE or head in lx.BUILDING_WORDS:
        return True
    if head in ("room", "hall"):
        return kind == "zone"
    return head in tokens or any(head in group and tokens & group for group in lx.PLACE_SYNONYMS)
