"""Pass 3: what each clause says its people do, and where.

A clause is the words a group owns (from its mention to the next group's) or a sentence's words before its first
mention (its scene, read for every group of that sentence). Phrase by phrase: a preposition gives a place its role
(from: start; to/into: destination; at/in/on: location, or the start of movers; through/via/past: via), a verb's
object does too ("leave the ward", "cross the hall"), "to"/"in order to"/"for" open a purpose ("to catch the train at
platform 1" keeps its place as where they go), and durations are waits. Then the intent from the verbs (phrasal
first), the robot interaction (reactions.py), evacuation cues, whom a follower follows, pace and togetherness.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field, replace

from grove_tui.language import lexicon as lx
from grove_tui.language.clause_cues import ClauseCues
from grove_tui.language.settled_after_leaving import settled_after_leaving, settled_at
from grove_tui.language.coming_in import SWIPING_VERBS, lets_self_in, settled_after_coming
from grove_tui.language.counts import duration_at
from grove_tui.language.stay_particles import after_a_stay
from grove_tui.language.manner import pace, together
from grove_tui.language.event_causes import left_thing
from grove_tui.language.particle_ends import place_end
from grove_tui.language.handled_fixtures import CHECKING_VERBS, STUDYING_VERBS
from grove_tui.language.going_idioms import straight_for
from grove_tui.language.going_verbs import goes_to_after, named_thing, obliged_to, sets_off_for
from grove_tui.language.pronoun_places import searched_or_queued_for
from grove_tui.language.purpose_with import with_object_end
from grove_tui.language.made_things import made_thing_then_place
from grove_tui.language.readied_for import readied_for
from grove_tui.language.purpose_after_for import purpose_after_for_place
from grove_tui.language.purpose_after_place import purpose_after_destination
from grove_tui.language.purpose_verbs import particle_object, reason_end, verb_with_an_object
from grove_tui.language.sought_things import sought_object
from grove_tui.language.people import People
from grove_tui.language.ahead_of_events import ahead_of_event
from grove_tui.language.place_carried import bare_place_at, from_is_where_got, purpose_said
from grove_tui.language.place_contrast import avoided_places, left_for
from grove_tui.language.preferred_places import chosen_at, over_at
from grove_tui.language.place_ordinals import series_number_at
from grove_tui.language.refused_destinations import refused_destination_after
from grove_tui.language.place_phrases import Place, PlacePhrases
from grove_tui.language.place_topics import topic_mark_at
from grove_tui.language.reactions import clause_reaction
from grove_tui.language.ridden_stays import ridden_for_a_while
from grove_tui.language.numbered_names import numbered_kind, numbered_name
from grove_tui.language.moved_things import moved_along
from grove_tui.language.contents_of import contents_of_thing
from grove_tui.language.sentence import Sentence
from grove_tui.language.stays import stay_after_for, stay_in
from grove_tui.language.tokens import lemma, verb_lemma
from grove_tui.language.thing_clauses import a_things_verb
from grove_tui.language.verb_classes import around_after, phrasal_intent, takes_a_way, verb_intent
from grove_tui.language.wander_spots import (SPOT_KEEPING_VERBS, browsing_between_shops, chore_after_coming,
                                              thing_adjective, wandering_at_a_spot)
from grove_tui.language.gerund_loads import gerund_load
from grove_tui.language.purpose_places import place_after_purpose

# Prepositions of the place where a purpose is done ("to catch the train at platform 1").
_PURPOSE_PLACE_PREPOSITIONS = frozenset({"at", "in", "on", "inside", "by", "near", "from"})
# Words that keep a word inside a place phrase available as a verb ("wait in the waiting room").
_VERBS_INSIDE_NAMES = ("line", "wait", "stand", "sit", "queue", "walk", "mill", "hang")
# Possessives before a room that is someone's own ("locks her office").
_OWNERS = frozenset({"her", "his", "their", "my", "our"})
# Words that open a clause before its place subject ("While the boardroom gets vacuumed by a cleaner, ...").
_OPENING_LINKS = frozenset("while whilst as when once because since".split())


@dataclass
class Clause:
    intent: str | None = None
    verb: str | None = None
    verb_index: int | None = None
    robot: str | None = None
    unaimed: str | None = None  # "shrink back" once the robot was named: theirs unless the scene says how
    places: list[Place] = field(default_factory=list)
    purpose: str | None = None
    wait_seconds: float | None = None
    together: bool = False
    pace: str = "normal"
    follows: str | None = None
    evacuate: bool = False
    has_action: bool = False
    moves: bool = False  # a verb of walking is among the clause's verbs
    avoid: list[str] = field(default_factory=list)  # places said not to be used ("not the main doors")


# Prepositions of where someone settles or hides: after leaving, the place they go to.
_SETTLED_AT = frozenset({"at", "on", "in", "obj:at", "under", "behind", "beneath"})


@dataclass
class _Scan:
    """The state of one clause's phrase-by-phrase scan."""

    c: Clause
    own: list[int]
    used: set[int] = field(default_factory=set)
    pos: int = 0  # position in `own`


class Clauses(ClauseCues):
    """Reads clauses of one sentence."""

    def __init__(self, s: Sentence, people: People, places: PlacePhrases) -> None:
        self.s = s
        self.people = people
        self.places = places

    def read(self, toks: Sequence[int], excluded: set[int], scene: bool = False,
             robot_after: int | None = None, owner: str | None = None) -> Clause:
        """The clause of the words `toks` less `excluded` (mentions, the robot's own clauses), said of
        people of the kind `owner` ("their room" is a room of theirs)."""
        before, self.places.owner = self.places.owner, owner
        try:
            return self._read(toks, excluded, scene, robot_after)
        finally:
            self.places.owner = before

    def _read(self, toks: Sequence[int], excluded: set[int], scene: bool, robot_after: int | None) -> Clause:
        s = self.s
        own = [i for i in toks if i not in excluded]
        scan = _Scan(Clause(), own)
        c = scan.c
        c.robot, c.unaimed = clause_reaction(s, own, robot_after)
        c.has_action = c.robot is not None
        while scan.pos < len(own):
            if not self._phrase(scan):
                scan.pos += 1
        if scene:
            self._scene(scan)
        c.wait_seconds = c.wait_seconds or stay_in(s, own)  # "until closing", "all afternoon", even inside a phrase
        self._intent(scan)
        self._evacuation(c, own)
        if c.intent == "follow" and c.verb_index is not None:
            self._followed(c)
        c.pace, c.together = pace(s, own), together(s, own)
        return c

    # ---- phrases ---------------------------------------------------------------------------------

    def _phrase(self, scan: _Scan) -> bool:
        """Read the phrase at the scan's position; False when no phrase starts there."""
        s = self.s
        i = scan.own[scan.pos]
        w = s.low[i]
        nxt = s.low[i + 1] if i + 1 < s.n else ""
        searched = w == "of" and tuple(s.low[max(0, i - 2):i]) == ("in", "search")  # "in search of the gym"
        if (w == "for" or searched) and not (i > 0 and s.low[i - 1] in lx.EXCEPT_WORDS) and self._for(scan, i, nxt):
            return True
        dur: tuple[float | None, int] | None = duration_at(s, i) if i > 0 and after_a_stay(s, i) else None
        if dur is not None:  # "waits 15 minutes outside the room": a duration without "for"
            scan.c.wait_seconds = scan.c.wait_seconds or dur[0]
            self._take(scan, i, dur[1])
            return True
        negated = next((p for p in lx.NEGATED_PLACE_PHRASES if tuple(s.low[i:i + len(p)]) == p), None)
        if negated is not None:
            # "go to the imaging instead of the waiting room": a place nobody goes to
            k = i + len(negated)
            place = self.places.phrase(k, "at", i, record_unknown=False, mentioned=False)
            self._take(scan, i, place.end if place is not None else s.phrase_end(k))
            if place is not None and place.match is not None:
                scan.c.avoid.extend(avoided_places(s.index, scan.c.places, place))
            return True
        if w in lx.NOT_USING_WORDS:
            return self._not_using(scan, i)
        if w in ("evacuation", "evacuating", "clearing") and nxt == "of":
            scan.c.evacuate = scan.c.evacuate or w != "clearing"
            return self._add_place(scan, self.places.phrase(i + 2, "obj:start", i), i)
        if w == "to" and nxt == "be" and i + 2 < s.n and verb_lemma(s.low[i + 2]) in lx.ZONE_EMPTYING_VERBS:
            return False  # "the hall has to be emptied": the zone's evacuation, read by emptied_zones
        if w == "to" and i > 0 and (s.w[i - 1].tag == "VBN" and s.verb(i - 1) in lx.TELLING_VERBS
                                    or self._told_before(i) or obliged_to(s, i)) and s.verb_follows(i + 1):
            return False  # "the guests are asked to leave", "tells two interns to go to ...", "have to leave": no purpose
        if purpose_after_destination(s, scan.c.places, i):  # "hurries to MR2 to chair student council"
            return self._purpose(scan, i, i, i + 2)
        if w == "to" and (nxt == "" or s.verb_follows(i + 1)) and (not (self.places.names_place(i + 1) or series_number_at(
                s.index, s.low[i + 1:i + 6])) or verb_with_an_object(s, i + 1)):  # "to check tomorrow's rota", "to book a court"
            return self._purpose(scan, i, i, i + 2)
        if (event_end := ahead_of_event(s, i)) is not None:  # "ahead of the 3 pm star show": why they are there
            scan.c.purpose = scan.c.purpose or s.span(i, event_end - 1)
            self._take(scan, i, event_end)
            return True
        if (said := purpose_said(s, i)) is not None:  # "in order to catch the bus", "wanting flea spray"
            return self._purpose(scan, i, *said)
        if (reason := reason_end(s, i)) is not None:  # "because her provisional licence needs a picture"
            scan.c.purpose = scan.c.purpose or s.span(i, reason - 1)
            self._take(scan, i, reason)
            return True
        if w in lx.PLACE_SEQUELS and scan.c.places and place_end(s, scan.c.places[-1]) == i:  # "goods in and"
            sequel = self._sequel(scan, i)
            if sequel is not None:
                return self._add_place(scan, sequel, i)
            if i in scan.used:  # the rest of the one name, taken (_sequel)
                return True
            aim = purpose_after_for_place(s, scan.c.places, i, scan.own, self.people.is_person_noun, self.places.names_place)
            if aim is not None:  # "for the boardroom and the weekly call": why they go
                scan.c.purpose = scan.c.purpose or s.span(i + 1, aim - 1)
                self._take(scan, i, aim)
                return True
        prep = s.preposition(i) or bare_place_at(s, i)  # "sits backstage": a bare adverb of place
        if prep is not None:
            name, width = prep
            if name == "from" and from_is_where_got(s, i, scan.own):  # not "takes towels from A to B"
                name = "at"  # "buy tickets from the machines": where they stand, not where they start
            name = "at" if name == "out" and i > 0 and s.verb(i - 1) in lx.THING_OR_PLACE_VERBS else name  # "mops out the bar"
            # "pour off platform 2" names a place; "drop off a parcel" only a particle and a thing
            place = self._there(i, width, name) if i + width < s.n and s.low[i + width] == "there" else \
                self.places.phrase(i + width, name, i, record_unknown=name != "off")
            if place is not None and name in lx.VIA_PREPOSITIONS | {"by"} and i > 0 and (s.low[i - 1] == "in" or s.verb(i - 1) in SWIPING_VERBS) and \
                    place.match is not None and place.match.kind == "door":
                place = replace(place, prep="from")  # "pour in through the main doors": in from there
            elif place is not None and name == "by" and i > 0 and s.low[i - 1] == "out" and \
                    place.match is not None and place.match.kind == "door":
                place = replace(place, prep="out")  # "get out by the side door": out of the scene there
            if place is not None:
                # "check in counter a": the "in" inside a name is not a new phrase
                return self._add_place(scan, place, i)
            return False
        return self._verb_object(scan, i, nxt)

    def _there(self, i: int, width: int, prep: str) -> Place | None:
        """"in there", "out of there": the place named last before it ("a pipe bursts above the
        dinosaur gallery and everyone in there is sent out"), in this phrase's role."""
        s = self.s
        for k in range(i - 1, -1, -1):
            if s.low[k] in lx.DETERMINERS and self.places.names_place(k):
                found = self.places.phrase(k, prep, k, record_unknown=False)
                if found is not None and found.match is not None:
                    return replace(found, prep=prep, index=i, end=i + width + 1, written=s.low[i])
        return None

    def _sequel(self, scan: _Scan, i: int) -> Place | None:
        """A place said right after another with no preposition of its own, in the same role: the
        next stop of a route ("walk to the café and then the pharmacy", "from ward A, then ward B")."""
        s = self.s
        before = scan.c.places[-1]
        if before.prep in ("for", "purpose") or before.match is None:
            return None
        k = s.skip(i, lx.PLACE_SEQUELS)
        if k >= s.n or k not in scan.own or s.preposition(k) is not None or s.verb_follows(k) or s.low[k] == "where":
            return None  # (", where five managers meet": what happens at the place before, no next stop)
        place = self.places.phrase(k, before.prep, i, record_unknown=False)
        if place is None or place.match is None:
            if s.low[i] == "and" and s.low[k] not in lx.DETERMINERS and s.low[k] not in lx.NOT_USING_WORDS and \
                    self._same_head(before.match.name, s.phrase_end(k)):
                self._take(scan, i, s.phrase_end(k))  # "the residents' and visitors' lounge": one name
            return None
        if place.match.name == before.match.name:
            if s.low[i] == "and":  # "the owners' and trainers' lounge": the rest of the one name, no verb in it
                self._take(scan, i, place.end)
            return None
        return replace(place, sequel=True)

    def _same_head(self, name: str, end: int) -> bool:
        """Whether the phrase ending before `end` has a head that is a word of the place `name`, so words
        after "and" finish that place's name even when they alone name no place of the world."""
        entry = self.s.index.entry(name)
        return entry is not None and 0 < end <= self.s.n and self.s.lemma(end - 1) in entry.tokens

    def _not_using(self, scan: _Scan, i: int) -> bool:
        """ "..., not the main doors", "but not through the lobby", "avoiding the lifts": a place the group
        must not use, kept apart from where it goes (a place word must follow: "not moving" is none)."""
        s = self.s
        k = s.skip(i + 1, lx.NOT_USING_LINKS)
        if k >= s.n or (s.low[i] in ("not", "never") and s.verb_follows(k)):
            return False
        place = self.places.phrase(k, "at", i, record_unknown=False, mentioned=False)
        if place is None or place.match is None:
            return False
        scan.c.avoid.extend(avoided_places(s.index, scan.c.places, place))
        self._take(scan, i, place.end)
        return True

    def _take(self, scan: _Scan, first: int, end: int) -> None:
        scan.used.update(range(first, end))
        scan.pos = self.s.advance(scan.own, end)

    def _add_place(self, scan: _Scan, place: Place | None, first: int) -> bool:
        if place is None:
            return False
        scan.c.places.append(place)
        self._take(scan, first, place.end)
        return True

    def _for(self, scan: _Scan, i: int, nxt: str) -> bool:
        """"for five minutes" (a wait), "head for the exit" (a destination), "for coffee" (a purpose)."""
        s = self.s
        dur = stay_after_for(s, i + 1)  # "for a while", "for the rest of the run": a stay, never a purpose
        if dur is not None:
            scan.c.wait_seconds = dur[0]
            self._take(scan, i, dur[1])
            return True
        # "head for the exit", "leave the ward for the canteen", "queue for the coffee machine": a place by its whole
        # name after a determiner; "for coffee", "head out the back for a cigarette" are purposes, whatever they match.
        leaves_for = left_for(s, scan.c.places, i)
        right_after_verb = self._verb_just_before(i) in lx.FOR_DESTINATION_VERBS or leaves_for or \
            sets_off_for(s, i) or searched_or_queued_for(s, i)
        if right_after_verb or (nxt in ("the", "this", "that") and self.places.names_place(i + 2)) or \
                numbered_name(s, i + 1) and self.places.names_place(i + 1) or numbered_kind(s, i + 1):  # "for gate B1"
            refused = len(self.places.unknown)
            place = self.places.phrase(i + 1, "for", i, record_unknown=right_after_verb or numbered_kind(s, i + 1))
            if place is not None or len(self.places.unknown) > refused:  # a place it lacks: no purpose either
                scan.c.places.extend([place] if place is not None else [])
                if leaves_for and place is not None:  # "abandon their desks for the boardroom": they go there
                    scan.c.has_action, scan.c.intent = True, scan.c.intent or "walk"
                scan.used.update(range(i, place.end if place is not None else s.phrase_end(i + 1)))
                scan.pos += 1
                return True
        end = s.phrase_end(i + 1)
        if end > i + 1 and not any(s.low[x] in lx.ROBOT_WORDS for x in range(i + 1, end)) and \
                (not self.people.is_person_noun(i - 1) or self._ends_a_named_place(scan, i)) and not (nxt in ("their", "his", "her") and i + 2 < s.n and s.low[i + 2] == "turn"):
            scan.c.purpose = scan.c.purpose or s.span(i, end - 1)
            self._take(scan, i, end)
            if (at := place_after_purpose(s, i, end)) is not None and \
                    (place := self.places.phrase(at + 1, "purpose", at)) is not None:
                self._add_place(scan, place, at)  # "go for coffee in the café": where it is done
            return True
        return False

    def _ends_a_named_place(self, scan: _Scan, i: int) -> bool:
        """Whether the word before i ends the clause's last place, named by the world ("the kids' club for the
        pirate party": "club" is the place's, not a club of people the "for" could be about)."""
        return bool(scan.c.places) and scan.c.places[-1].match is not None and place_end(self.s, scan.c.places[-1]) == i

    def _purpose(self, scan: _Scan, first: int, said_from: int, verb_at: int) -> bool:
        """"to register", "in order to catch the bus": a purpose, not a place. A place right after it
        is where the purpose is done ("to catch the train at platform 1"): where they go, not where
        they start."""
        s = self.s
        end = s.phrase_end(verb_at, allow_objects=True)
        scan.c.purpose = scan.c.purpose or s.span(said_from, max(end - 1, said_from + 1))
        goal = self._purpose_object(verb_at - 1)
        if goal is not None:
            # "to reach the ICU", "to get to the pharmacy", "to use the toilets": the purpose's place is
            # where they go
            scan.c.places.append(goal)
            end = max(end, goal.end)
        with_end = with_object_end(s, end, self.people.is_person_noun, self.places.names_place)
        if with_end > end:  # "to help with boarding": what the purpose is done with (purpose_with.py)
            end = with_end
            scan.c.purpose = s.span(said_from, end - 1)
        if sought_object(s, end) or readied_for(s, said_from, end, self.places.names_place, self.people.is_person_noun):  # "to look for prom dresses", "to set up for dinner": sought_things.py, readied_for.py
            end = s.phrase_end(end + 1)
            scan.c.purpose = s.span(said_from, end - 1)
        prep = s.preposition(end) if end < s.n else None
        if particle_object(s, end):  # "to stock up on IPA": what the purpose is about, no place
            end = s.phrase_end(end + 1)
            scan.c.purpose = s.span(said_from, end - 1)
        elif prep is not None and prep[0] in _PURPOSE_PLACE_PREPOSITIONS:
            place = self.places.phrase(end + prep[1], "purpose", end)
            if place is not None:
                scan.c.places.append(place)
                end = place.end
        self._take(scan, first, end)
        return True

    def _purpose_object(self, verb: int) -> Place | None:
        """The place a purpose's verb names as where they are going: its object ("to reach the ICU",
        "to visit the gift shop") or the place after its "to" ("to get to the pharmacy", "to make
        it back to the ward"); None when the object is a thing ("to reach the top shelf")."""
        s = self.s
        if verb >= s.n or s.verb(verb) not in lx.PURPOSE_PLACE_VERBS:
            return None
        k = s.skip(verb + 1, {"it", "back", "over", "up", "down"})
        if k < s.n and s.low[k] in ("to", "into", "onto"):
            k += 1
        elif s.verb(verb) not in lx.DESTINATION_OBJECT_VERBS | lx.PURPOSE_OBJECT_VERBS:
            return None  # "to get a coffee": "get" sends somewhere only with "to"
        if k >= s.n or not (s.low[k] in lx.DETERMINERS or s.index.knows(lemma(s.low[k]))):
            return None
        return self.places.phrase(k, "purpose", verb, record_unknown=False)

    def _verb_object(self, scan: _Scan, i: int, nxt: str) -> bool:
        """A place as a verb's object: "leave the ward", "skip the ICU", "clear the platform", "mops
        the corridor" (a verb the lexicon lacks, with a whole place name for its object)."""
        s = self.s
        c = scan.c
        v = s.verb(i)
        if thing_adjective(s, i) or gerund_load(s, i):
            return False  # "clean towels": a thing's adjective; "a basket of washing off the balcony": a load
        if v in lx.NEGATING_VERBS and (nxt in lx.DETERMINERS or self.places.names_place(i + 1)):
            # "skip the critical care and go to ...": a place they do not go to
            place = self.places.phrase(i + 1, "obj:at", i, record_unknown=False, mentioned=False)
            self._take(scan, i, place.end if place is not None else i + 1)
            return True
        if (k := chosen_at(s, i)) is not None and (chosen := self.places.phrase(k, "obj:dest", i)) is not None:
            # "choose the library over the state dining room": where they go, and a place they do not
            c.places.append(chosen)
            c.has_action, c.intent, end = True, c.intent or "walk", chosen.end
            if (o := over_at(s, i, end)) is not None and (over := self.places.phrase(
                    o, "at", end, record_unknown=False, mentioned=False)) is not None:
                c.avoid.extend(avoided_places(s.index, c.places, over) if over.match is not None else [])
                end = over.end
            self._take(scan, i, end)
            return True
        if v in lx.ZONE_EMPTYING_VERBS and s.is_verb(i) and not s.after_determiner(i) and \
                nxt in lx.DETERMINERS | {"out"}:
            # "clear the platform", "empty out the ward": the zone everybody leaves
            place = self.places.phrase(s.skip(i + 1, {"out"}), "obj:start", i, record_unknown=False)
            if place is not None and place.match is not None and place.match.kind == "zone":
                c.places.append(place)
                c.evacuate = True
                scan.used.update(range(i + 1, place.end))
                scan.pos = s.advance(scan.own, place.end)
                return True
        if not s.after_determiner(i) and takes_a_way(s, i, v, s.phrase_end(i + 1)):
            # "take the stairs", "use the side entrance", "take the lifts", "ride the escalator": the way they go
            place = self.places.phrase(i + 1, "obj:via", i, record_unknown=False)
            c.has_action, c.intent = True, c.intent or "walk"  # a way the world lacks is still a way they go
            if place is not None and place.match is not None:
                c.places.append(place)
                scan.used.update(range(i, place.end))
                scan.pos = s.advance(scan.own, place.end)
                return True
        obj = i + 2 if nxt in ("up", "down", "off", "out") and i + 1 < s.n and s.w[i + 1].dep == "prt" else i + 1
        nxt = s.low[obj] if obj < s.n else ""
        if v in lx.LEADING_VERBS and any(s.lemma(x) in lx.CARRYING_THINGS for x in range(obj, s.phrase_end(obj))):
            return False  # "pushes a wheelchair", "wheels his father's bed": what someone is taken in, no place
        if moved_along(s, v, obj):
            return False  # "wheels a roll cage from ... to ...": the thing moved, no place of theirs
        if ((s.w[i].pos == "VERB" or self.people.third_person_verb(i)) and v not in lx.INTENT_VERBS
                and v not in lx.START_OBJECT_VERBS  # "abandon their desks", "desert the ward": the place left
                and (v not in lx.ROBOT_VERBS or v in CHECKING_VERBS or v in STUDYING_VERBS)  # "checks the drugs trolley": at it
                and v not in lx.HOLDING_VERBS  # "carrying coffees": no place
                and (nxt in lx.DETERMINERS or self.places.names_place(obj)) and not s.hyphen_inside(i - 1)
                and not (i > 0 and s.low[i - 1] == "with")  # "with hired clubs": a modifier of what they hold
                and not s.after_determiner(i) and (self.places.names_place(s.skip(obj, lx.DETERMINERS))
                                                   or nxt in _OWNERS) and not made_thing_then_place(s, obj)):
            # "a cleaner sweeps platform 2", "mops the corridor", "locks her office", "closes up
            # reception": the object of a verb the lexicon lacks (one's own room by its kind)
            place = self.places.phrase(obj, "obj:at", i, record_unknown=False)
            if place is not None:
                c.places.append(place)
                c.has_action = True  # a verb of its own, though no list names it: no sharing the next group's
                scan.used.update(range(i, place.end))
        elif not s.after_determiner(i) and (v in lx.OBJECT_VERBS or ridden_for_a_while(s, v, obj)) and nxt not in (
                "round", "around"):  # a preposition; "rides the street course for an hour": there (ridden_stays.py)
            if nxt in lx.DETERMINERS or (nxt and (s.index.knows(lemma(nxt)) or self.places.names_place(obj))):
                role = ("obj:start" if v in lx.START_OBJECT_VERBS else "obj:via" if v in lx.VIA_OBJECT_VERBS
                        else "obj:seen" if v in lx.SEEN_OBJECT_VERBS
                        else "obj:at" if v in lx.LOCATION_OBJECT_VERBS or v not in lx.OBJECT_VERBS else "obj:dest")
                # What people watch is mostly a thing ("the news"), and so is what they clean where a
                # place follows ("cleans the windows in the hallway"): a place only when the world has it.
                end = s.phrase_end(obj)
                thing = role == "obj:seen" or ((v in lx.THING_OR_PLACE_VERBS or left_thing(s, i)) and end < s.n
                                               and s.preposition(end) is not None)  # "left a bag by the door"
                part = end - 1 - (s.low[end - 1] in ("just", "right", "directly", "immediately") and end - 2 >= obj)
                if s.lemma(part) in lx.PLACE_PARTS and v in lx.THING_OR_PLACE_VERBS and end < s.n and s.preposition(end):
                    return False  # "mops the floor (just) outside the kitchen": the floor of the place said next
                place = self.places.phrase(obj, role, i, record_unknown=not thing)
                if place is not None and not any(x in lx.ROBOT_WORDS for x in place.words):
                    c.places.append(place)
        return False

    def _verb_just_before(self, i: int) -> str | None:
        """The verb (or "beeline") right before i, past adverbs ("head straight for the exit")."""
        s = self.s
        j = i - 1
        while j >= 0 and (s.w[j].pos == "ADV" or s.low[j] in ("straight", "directly", "off", "back")):
            j -= 1
        if j < 0:
            return None
        word = s.low[j]
        return word if word in lx.FOR_DESTINATION_VERBS else verb_lemma(word)

    # ---- a sentence's scene ----------------------------------------------------------------------

    def _scene(self, scan: _Scan) -> None:
        """What a sentence's words before its first group say for all of its groups."""
        s = self.s
        c, own = scan.c, scan.own
        if any(s.low[i] in lx.ROBOT_WORDS for i in own):
            first_robot = min(i for i in own if s.low[i] in lx.ROBOT_WORDS)
            c.places = [p for p in c.places if p.index < first_robot]  # the robot's places are not the people's
        # "Gate B1 clears out when the alarm sounds; its passengers ...": where they all leave
        for place in self.places.emptied_zones(own):
            c.places.insert(0, place)
            c.evacuate = True
        if not own:
            return
        # "The cafeteria is empty except for ...": a place as the subject of "to be" is where the
        # sentence's people are. So is a place that heads the sentence before a colon ("Gate A1: 25
        # people seated") or names the event the people come from ("the boardroom meeting of twelve
        # people"); the subject of a passive takes the role the verb gives its object ("Ward B is
        # visited by").
        first = own[1] if len(own) > 1 and s.low[own[0]] in _OPENING_LINKS and own[1] == own[0] + 1 else own[0]
        subject = self.places.phrase(first, "at", first, record_unknown=False)  # "While the boardroom gets ..."
        if subject is None:
            return
        after = s.low[subject.end] if subject.end < s.n else ""
        if subject.match is not None and self.places.passive_emptying(subject.end):
            # "Platform 1 must be cleared: ...", "the ward has to be emptied": where everybody leaves
            c.places.append(replace(subject, prep="obj:start"))
            c.evacuate = True
            scan.used.update(range(first, subject.end))
        elif verb_lemma(after) in ("be", "stay", "remain", "get", "have") or after in (":", "of") or \
                (subject.match is not None and topic_mark_at(s, subject.end)):  # "platform 2 rn: 20 people"
            passive = subject.end + 1 < s.n and s.w[subject.end + 1].tag == "VBN"
            verb = verb_lemma(s.low[subject.end + 1]) if passive else ""
            if verb in lx.START_OBJECT_VERBS:
                subject = replace(subject, prep="obj:start")
            elif verb in lx.DESTINATION_OBJECT_VERBS | lx.VIA_OBJECT_VERBS:  # "is crossed by": a way through
                subject = replace(subject, prep="obj:via" if verb in lx.VIA_OBJECT_VERBS else "obj:dest")
            c.places.append(subject)
            scan.used.update(range(first, subject.end))

    # ---- what they do ----------------------------------------------------------------------------

    def _intent(self, scan: _Scan) -> None:
        """The intent from the verbs: phrasal verbs first, then single verbs; a verb inside a place
        phrase or a relative clause ("who are waiting") is not one."""
        s = self.s
        c, own, used = scan.c, scan.own, scan.used
        candidates: list[tuple[int, str, str]] = []
        for i in own:
            if i in used and s.low[i] not in _VERBS_INSIDE_NAMES:
                continue
            if lets_self_in(s, i):
                candidates.append((i, "walk", "come"))  # "let themselves in": coming in
                continue
            phrasal = phrasal_intent(s, i)  # "line up", "do laps", "stretches her legs"
            if phrasal is not None:
                candidates.append((i, phrasal[1], phrasal[0][0]))
                continue
            if i in used or named_thing(s, i) or any(p.index < i < p.end for p in c.places) or \
                    (s.w[i].pos == "NOUN" and (s.w[i].dep == "compound" and s.w[i].head > i or s.w[i].dep == "dobj" and
                                               s.w[i - 1].dep == "compound" and s.verb(s.w[i].head) not in lx.SCENE_VERBS)):
                continue
            if thing_adjective(s, i) or contents_of_thing(s, i):
                continue  # "carries clean linen to ward B": a thing's adjective, no cleaning
            v, kind = s.verb(i), verb_intent(s, i)  # the lexicon's, or a verb of moving in or with something
            if kind is not None and not (v == "line" and s.w[i].pos != "VERB"):
                if v in ("make", "get") and not (i + 1 < s.n and s.low[i + 1] in ("their", "its", "his", "her",
                                                                                  "way", "to", "for")) and \
                        not (v == "make" and straight_for(s, i)):
                    continue
                candidates.append((i, kind, v))
        if any(s.w[i].pos == "VERB" and s.w[i].lemma not in ("be", "have") and i not in used for i in own):
            c.has_action = True  # "a nurse pushes a cart to ward b": a verb of its own, even one the lexicon lacks
        if any(i not in s.relative for i, _, _ in candidates):
            candidates = [c_ for c_ in candidates if c_[0] not in s.relative]
        if len(candidates) > 1 and any(a_things_verb(s, i) for i, _, _ in candidates):
            candidates = [c_ for c_ in candidates if not a_things_verb(s, c_[0])]  # "... before the bus leaves"
        elif len(candidates) > 1 and own and candidates[0][0] == own[0] and s.w[own[0]].tag == "VBG":
            candidates = candidates[1:]  # "the family sleeping in the bedrooms escape": who they are, not what they do
        if candidates:
            c.has_action = True
            c.moves = any(kind in ("walk", "evacuate") for _, kind, _ in candidates)
            c.intent, c.verb, c.verb_index = self._main_intent(candidates, c)

    def _main_intent(self, candidates: list[tuple[int, str, str]], c: Clause) -> tuple[str, str, int]:
        s = self.s
        kinds = [k for _, k, _ in candidates]
        has_destination = any(p.prep in lx.DESTINATION_PREPOSITIONS or p.prep in ("obj:dest", "purpose")
                              for p in c.places if p.match is not None)  # "stroll ... to reach gate A2" too
        has_destination = has_destination or refused_destination_after(s, candidates, self.places.unknown_towards)
        if (came := chore_after_coming(candidates)) is not None:  # "come in ... and mop the corridor"
            c.places = [replace(p, prep="obj:dest") if p.prep == "obj:at" and p.index > came[0] else p for p in c.places]
            return "walk", came[2], came[0]
        if (came := settled_after_coming(s, candidates)) is not None:  # "come in ... and sit down at the desks"
            return "walk", came[2], came[0]
        if (left := settled_after_leaving(s, candidates)) is not None:  # "head out of X and flop onto the couch"
            sat = settled_at(s, candidates)
            c.places = [replace(p, prep="to") if p.prep in _SETTLED_AT and p.index > sat else p for p in c.places]
            return "walk", left[2], left[0]
        for wanted in ("queue", "converse", "wait", "wander", "follow", "evacuate"):
            if wanted in kinds:
                i, _, verb = candidates[kinds.index(wanted)]
                if wanted == "wander" and has_destination and not around_after(s, i) and \
                        ("walk" not in kinds[:kinds.index(wanted)] or goes_to_after(s, i)) and \
                        not browsing_between_shops(s.index, c.places, c.purpose):
                    return "walk", verb, i  # "stroll to the cafe": a slow walk with a destination
                if wanted == "wander" and verb not in SPOT_KEEPING_VERBS and wandering_at_a_spot(s, c.places):
                    return "wait", verb, i  # "mill about near the ticket machines": at that spot
                return wanted, verb, i
        i, kind, verb = candidates[0]
        if kind == "walk" and around_after(s, i) and not has_destination:  # "walks slowly round the hall"
            return "wander", verb, i
        return kind, verb, i

    def _told_before(self, i: int) -> bool:
        """Whether people told what to do stand right before "to" at i ("tells two interns to go")."""
        s = self.s
        k = i - 1
        while k > 0 and s.w[k].pos in ("NOUN", "PROPN", "DET", "ADJ", "NUM") and not s.is_punct(k):
            k -= 1
        return k < i - 1 and s.verb(k) in lx.TELLING_VERBS | lx.ROBOT_COMMAND_VERBS and any(  # or the robot told
            self.people.is_person_noun(x) or s.low[x] in lx.ROBOT_WORDS for x in range(k + 1, i))
