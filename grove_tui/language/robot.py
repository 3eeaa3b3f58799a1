"""Pass 3, part 2: what the sentence asks of the robot itself (language/model.py `RobotReading`).

A clause whose subject is the robot ("a (delivery) robot crosses the hall to the lifts", "it" once
the robot is named: "as it passes the lobby") or that sends it ("send the robot to ward A", "have the
robot wait by the door") gives the robot a task from its verb (cross, wait, patrol, follow) and its
places by role. These clauses belong to no group: a group's places never come from them. A passive
("the robot is followed by two children") is the people's clause, and a reaction to the robot
("two children follow the robot") asks nothing of the robot itself.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from grove_tui.language import lexicon as lx
from grove_tui.language.clauses import Clause, Clauses
from grove_tui.language.counts import quantifier
from grove_tui.language.mention import Mention
from grove_tui.language.model import FieldConfidence, RobotReading
from grove_tui.language.people import People
from grove_tui.language.place_phrases import Place, place_confidences
from grove_tui.language.sentence import Sentence
from grove_tui.language.robot_asides import after_aside
from grove_tui.language.robot_avoided import fronted_avoiding
from grove_tui.language.robot_bound import bound_trip
from grove_tui.language.robot_escorts import escorts_to_a_place
from grove_tui.language.robot_habits import habit_task
from grove_tui.language.robot_keeps import keeps_post
from grove_tui.language.robot_modals import obligation_verb
from grove_tui.language.robot_motion import goes_after_robot
from grove_tui.language.robot_out import out_exit
from grove_tui.language.robot_passed_by import hands_back
from grove_tui.language.robot_purpose import fronted_purpose
from grove_tui.language.robot_owners import owner_word
from grove_tui.language.robot_rounds import to_and_fro
from grove_tui.language.robot_shows import shows_the_way
from grove_tui.language.robot_states import placing_robot, state_after_robot, stays_so
from grove_tui.language.sequences import robot_sequel
from grove_tui.language.tokens import verb_lemma

_TASK_VERBS = lx.ROBOT_WAIT_VERBS | lx.ROBOT_PATROL_VERBS | lx.ROBOT_FOLLOW_VERBS | lx.ROBOT_CROSS_VERBS
# The robot switched off where it is ("the robot powers down in the kitchen"): waiting there.
_OFF_PHRASES = frozenset({("power", "down"), ("shut", "down"), ("switch", "off"), ("turn", "off"), ("power", "off")})
# Words after a verb of motion that say the robot goes by ("rolls past", "glides by", "zips along").
_PASSING_WORDS = frozenset("past by through along across over".split())
# "waits at the desk until the robot leads her to check-in": the robot is the subject of the clause it opens
_UNTIL = frozenset({"until", "till", "til", "untill"})
# What the robot does for people where it stands ("hands out leaflets near the fountain", "greets
# visitors at the entrance", "serves drinks at the bar"): a wait at the place.
_SERVING_VERBS = frozenset("hand give greet welcome serve distribute offer dispense pour sell answer entertain "
                           "demonstrate display show sign register check".split())
_PEOPLE_PRONOUNS = ("they", "he", "she", "we", "people", "everyone", "everybody", "someone", "somebody",
                    "nobody", "visitors", "staff")


@dataclass
class RobotClause:
    """The words of one clause about the robot, and the index of its verb."""

    tokens: list[int]
    verb: int | None
    command: bool = False  # "send the robot to ...": the verb is the sender's
    sequel: bool = False  # "..., then leads passengers to the exit": a second task, with people, after the first


class RobotClauses:
    def __init__(self, s: Sentence, people: People, clauses: Clauses) -> None:
        self.s = s
        self.people = people
        self.clauses = clauses

    def find(self, mentions: Sequence[Mention]) -> list[RobotClause]:
        """The clauses whose subject is the robot, each running to the next group's mention, the
        next clause about someone else, or the end of its sentence."""
        s = self.s
        # the people the robot escorts or follows are inside its clause ("the robot escorts a lost child to ...")
        starts = {m.first for m in mentions if m.robot_object is None}
        taken = {i for m in mentions for i in range(m.first, m.last + 1)}
        out: list[RobotClause] = []
        i = 0
        while i < s.n:
            found = self._subject(i, taken)
            if found is None:
                i += 1
                continue
            first, verb, command = found
            first = fronted_purpose(s, first, taken)  # "To reach the toy store, the robot must ..."
            first = fronted_avoiding(s, first, taken)  # "Avoiding the cafeteria, the robot drives to ..."
            end = self._end(verb if verb is not None else i + 1, starts, first)
            second = robot_sequel(s, verb, end) if verb is not None else None
            if second is not None:
                joined, sequel = second
                out.append(RobotClause(list(range(first, joined)), verb, command))
                out.append(RobotClause(list(range(sequel, end)), sequel, sequel=True))
            else:
                out.append(RobotClause(list(range(first, end)), verb, command))
            i = max(end, i + 1)
        return out

    def leads_into(self, a: int, b: int, found: Sequence[RobotClause]) -> int | None:
        """The first word of a robot clause that a group's clause (words a..b) leads into with a
        word of time ("two patients step aside as it passes"): the group reacts to the robot there."""
        for rc in found:
            r = rc.tokens[0]
            if a < r <= b and r > 0 and self.s.low[r - 1] in ("as", "when", "whenever", "while", "once", "until"):
                return r
        return None

    # ---- finding them ----------------------------------------------------------------------------

    def _subject(self, i: int, taken: set[int]) -> tuple[int, int | None, bool] | None:
        """(first word, verb index, command) when the robot (or "it" for it) is the subject at i."""
        s = self.s
        low = s.low
        is_robot = low[i] in lx.ROBOT_WORDS
        is_it = low[i] == "it" and any(x in lx.ROBOT_WORDS for x in low[:i]) and s.w[i].dep in ("nsubj", "")
        if not (is_robot or is_it) or i in taken:
            return None
        first = self._phrase_start(i, taken) if is_robot else i
        if is_robot and (placer := placing_robot(s, first)) is not None:
            return placer, placer, False  # "park the robot by the back door": it waits there
        before = first - 1
        command = before >= 0 and verb_lemma(low[before]) in lx.ROBOT_COMMAND_VERBS and (
            before == 0 or s.is_punct(before - 1) or low[before - 1] in lx.CLAUSE_STARTERS | {"please"})
        subject = (first == 0 or s.is_punct(before) or low[before] in lx.CLAUSE_STARTERS | _UNTIL
                   or s.w[before].sentence != s.w[first].sentence
                   or (s.w[before].pos == "NUM" and before > 0 and low[before - 1] == "at")  # "At 9 the robot ..."
                   or self._after_fronted_adverbial(i, first))
        if command:
            first = before
        elif not subject or goes_after_robot(s, first):
            return None  # "two kids trot after the robot round the shop": the robot is what they go after
        if not command and (state := state_after_robot(s, i)) is not None:
            return first, state, False  # "bot idle nr pulpit", "the robot is stationary by gate B1"
        j = i + 1
        while j < s.n and (s.w[j].pos == "ADV" or s.w[j].tag == "MD" or low[j] in ("then", "also", "now", "first")) \
                and not s.is_punct(j):
            j += 1
        j = after_aside(s, j)  # "the robot, meanwhile, keeps patrolling"
        if j >= s.n or s.is_punct(j):
            return None
        if command:
            if low[j] == "to" and j + 1 < s.n and s.verb_follows(j + 1):
                return first, j + 1, True  # "tell the robot to wait by the door"
            if s.w[j].pos == "VERB" or s.w[j].tag == "VB" or verb_lemma(low[j]) in _TASK_VERBS:
                return first, j, True  # "have the robot patrol the lobby", "have the robot park by ..." (a noun to the tagger)
            return first, None, True  # "send the robot to ward A": the sender's verb moves it
        if (task_verb := obligation_verb(s, j)) is not None:
            return first, task_verb, False  # "the robot needs to wait by the door", "is meant to follow them"
        if verb_lemma(low[j]) == "be":
            return self._after_be(first, j)
        if s.w[j].pos in ("VERB", "AUX") or s.w[j].tag.startswith("VB") or self._verb_tagged_noun(j):
            return first, j, False
        return None

    def _after_fronted_adverbial(self, i: int, first: int) -> bool:
        """Whether only a phrase with no verb (a time, a manner) stands between the start of the robot's
        sentence or clause and it, its parser's subject ("Overnight the robot patrols ...", "At night the
        robot ...")."""
        s = self.s
        if s.w[i].dep != "nsubj" or s.w[s.w[i].head].dep not in ("ROOT", "ccomp", "conj"):
            return False  # the subject of its sentence's main verb, not of "every time the robot passes"
        k = first - 1
        while k >= 0 and not s.is_punct(k) and s.w[k].sentence == s.w[first].sentence:
            if s.w[k].pos in ("VERB", "AUX") or s.w[k].dep in ("nsubj", "nsubjpass") or first - k > 3 or \
                    s.low[k] in lx.ROBOT_WORDS or s.low[k] in lx.CLAUSE_STARTERS:
                return False  # a short phrase only: "A nervous intern steps aside every time the robot ..." has a subject
            k -= 1
        return k < first - 1

    def _phrase_start(self, i: int, taken: set[int]) -> int:
        """The first word of the robot's noun phrase: "a delivery robot", "the small cleaning robot" (the
        parser may tag "cleaning" a verb modifying the robot)."""
        s = self.s
        first = i
        while first > 0 and not s.is_punct(first - 1) and (
                s.w[first - 1].pos in ("DET", "ADJ", "NOUN", "PROPN", "NUM") or s.low[first - 1] in lx.NP_MODIFIERS
                or owner_word(s, first - 1)  # "our robot", "the hotel's robot"
                or (s.low[first - 1] == "-" and first > 1)
                or (s.w[first - 1].tag == "VBG" and s.w[first - 1].dep in ("amod", "compound"))) and s.low[first - 1] not in lx.CLAUSE_STARTERS \
                and s.low[first - 1] not in lx.PLACE_PREPOSITIONS and (first - 1) not in taken:
            first -= 1
        return first

    def _after_be(self, first: int, j: int) -> tuple[int, int | None, bool] | None:
        s = self.s
        k = j + 1
        while k < s.n and s.w[k].pos == "ADV":
            k += 1
        if k < s.n and s.w[k].tag == "VBN" and verb_lemma(s.low[k]) in lx.ROBOT_PLACED_VERBS and \
                not (k + 1 < s.n and s.low[k + 1] == "by" and s.w[k + 1].dep == "agent"):
            return first, k, False  # "the robot is parked by the lifts": it stays there
        if k < s.n and s.w[k].tag == "VBN":
            return None  # "the robot is followed by two children": the people's clause
        if k < s.n and s.w[k].tag == "VBG":
            return first, k, False  # "the robot is crossing the hall"
        if k < s.n and s.preposition(k) is not None:
            return first, j, False  # "the robot is in the lobby": it stays there
        return None

    def _verb_tagged_noun(self, j: int) -> bool:
        """The small parser may tag the robot's verb a plural noun ("the robot rolls", "the robot
        patrols"): an "-s" word the lexicon knows as a verb, right after the robot, or any "-s" word right
        after the robot with a place phrase after it ("the robot hums along the corridor")."""
        s = self.s
        word = s.low[j]
        base = verb_lemma(word)
        if not word.endswith("s") or word.endswith("ss"):
            return False
        if base != word and (base in lx.INTENT_VERBS or base in _TASK_VERBS):
            return True
        return s.low[j - 1] in lx.ROBOT_WORDS and j + 1 < s.n and s.preposition(j + 1) is not None

    def _end(self, k: int, starts: set[int], first: int = -1) -> int:
        """Where a robot clause from k ends: the next group's mention (less the words joining it),
        a new subject after a clause word ("... as a family buys tickets"), a semicolon or colon, or
        the end of the sentence."""
        s = self.s
        sentence = s.w[k].sentence if k < s.n else -1
        j = k
        while j < s.n and s.w[j].sentence == sentence and s.low[j] not in (";", ":"):
            if j in starts or (j > k and hands_back(s, first, j)):  # "... rolls past and hops out of its way"
                break
            if s.low[j] in lx.CLAUSE_STARTERS - {"and", "then", "with"} and j > k and self._new_subject_after(j + 1):
                break
            if s.low[j] in ("and", ",") and j > k and self._new_subject_after(j + 1) and \
                    not (j + 1 < s.n and s.low[j + 1] in lx.ROBOT_WORDS):
                break
            j += 1
        while j > k and (s.low[j - 1] in lx.CLAUSE_STARTERS | {"where"} or s.is_punct(j - 1)
                         or verb_lemma(s.low[j - 1]) in lx.SCENE_VERBS):
            j -= 1  # "send the robot to the kitchen and have ...": not the robot's words
        return j

    def _new_subject_after(self, k: int) -> bool:
        """Whether a new subject starts at k: a person phrase, a pronoun for people, or a starter."""
        s = self.s
        k = s.skip(k, {","} | (lx.CLAUSE_STARTERS - {"with"}))
        if k >= s.n:
            return False
        if s.low[k] in _PEOPLE_PRONOUNS:
            return True
        q = quantifier(s, k)
        start = q.end if q is not None else s.skip(k, lx.DETERMINERS | lx.NP_MODIFIERS)
        if q is not None and start < s.n and s.low[start] == "of":
            start = s.skip(start + 1, lx.DETERMINERS)  # "as dozens of shoppers stream in"
        return start < s.n and self.people.person_head(start, counted=q is not None) is not None

    # ---- reading them ----------------------------------------------------------------------------

    def reading(self, found: Sequence[RobotClause]) -> RobotReading | None:
        """What the robot's clauses ask of it: a task from their verbs and the places by role."""
        s = self.s
        task: str | None = None
        task_confidence: FieldConfidence | None = None
        roles: dict[str, str | None] = {"start": None, "destination": None, "location": None}
        via: list[str] = []
        follows: str | None = None
        wait_seconds: float | None = None
        guides: str | None = None
        read_from: dict[str, Place] = {}
        texts: list[str] = []
        avoid: list[str] = []  # "..., avoiding the cafeteria", "without going through the lobby" (kept_away.py)
        for rc in found:
            # "needs to wait by the door", "tell it to wait by the door": the task verb's "to" is no purpose
            told = {rc.verb - 1} if rc.verb is not None and rc.verb > 0 and s.low[rc.verb - 1] in ("to", "ta") else set()
            clause = self.clauses.read(rc.tokens, told)
            verb = s.verb(rc.verb) if rc.verb is not None else ""
            placed = rc.verb is not None and (s.w[rc.verb].tag == "VBN" and verb in lx.ROBOT_PLACED_VERBS or (
                verb, s.low[rc.verb + 1] if rc.verb + 1 < s.n else "") in _OFF_PHRASES)
            placed = placed or keeps_post(s, rc.verb) or stays_so(s, rc.verb)  # "holds (its) position by the stairs"
            kind = "wait" if placed else self._task(verb, clause, rc.command)  # "is left in the hallway"
            kind = "cross" if kind == "wait" and shows_the_way(s, rc.verb, rc.tokens) else kind  # "shows them to gate 2"
            kind = "cross" if kind == "follow" and escorts_to_a_place(s, rc.verb) else kind  # "accompanies her back to"
            if kind in ("cross", "wait", None) and (habit := habit_task(s, rc.verb)) is not None:
                kind = habit  # "keeps circling the showroom floor": the habit of going round there
            if kind in ("cross", None) and to_and_fro(s, rc.verb, rc.tokens):
                kind = "patrol"  # "goes up and down the west mall": it keeps going round there
            if kind is None:
                if not any(p.match is not None for p in clause.places) and not self._passes_by(rc.verb):
                    continue
                kind = "cross"
                task_confidence = FieldConfidence("task", 0.6, f"'{verb}' is read as the robot going somewhere")
            if rc.sequel and task in ("wait", "patrol", "cross") and kind in ("follow", "cross"):
                # "waits on platform 1, then leads passengers to the exit": the task with the people is
                # the robot's; where it waited, or got to, is where it sets off from
                roles["start"] = roles["start"] or (roles["destination"] if task == "cross" else roles["location"])
                roles["destination"] = roles["location"] = None
                task = kind
            task = task or kind
            if kind == "wait" and wait_seconds is None:
                # the clause reader's stay ("for two minutes", "for a while"): how long the robot waits there
                wait_seconds = clause.wait_seconds
            if kind == "cross" and rc.verb is not None and guides is None and (verb in lx.LEADING_VERBS or
                                                                         escorts_to_a_place(s, rc.verb)):
                guides = self._followed(rc.verb)  # "guides them to the exit": whom it takes along
            if kind == "follow" and rc.verb is not None and follows is None:
                follows = self._followed(rc.verb)
            avoid += [a for a in clause.avoid if a not in avoid]
            for place in clause.places:
                if place.match is None or place.match.name in avoid:
                    continue
                name = place.match.name
                read_from.setdefault(name, place)
                role = self._role(place, rc.verb, kind in ("wait", "patrol"))
                if role == "via" and kind == "cross" and (self._stops_at(rc, place) or self._after_a_thing_gone_to(place, clause)):
                    role = "destination"  # "leaves the kitchen and is parked in the hallway", "goes to its dock in the hallway"
                if role == "location" and kind == "patrol" and roles["location"] not in (None, name):
                    role = "via"  # "patrols between the pharmacy and the cafeteria": its round keeps both
                if role == "via":
                    via += [] if name in via else [name]
                elif role == "destination" or roles[role] is None:
                    roles[role] = name  # the last destination said, the first start and location
            texts.append(s.span(rc.tokens[0], rc.tokens[-1]))
        start, destination, location = roles["start"], roles["destination"], roles["location"]
        if task in ("patrol", "cross") and (bound := bound_trip(s, found, read_from)) is not None:
            # "weaves through the kids milling by the skeleton, bound for the café": its trip there
            via = [v for v in [*via, *([location] if location else []), *([destination] if destination else [])]
                   if v not in (bound, start)]
            task, destination, location = "cross", bound, None
        if task in ("cross", "wait") and destination is None:
            # "the robot guides the visitors in the cafeteria out": from there to the nearest exit
            exit_ = next((e for rc in found if (e := out_exit(s, rc.tokens[0], [start, *via, location])) is not None),
                         None)
            if exit_ is not None:
                task, start = "cross", start or (via[0] if via else location)
                destination, location, via = exit_, None, [v for v in via if v != start]
        if task is None or (task == "cross" and not (start or destination or via)
                            and not any(self._passes_by(rc.verb) for rc in found)):
            if task == "cross" and guides is not None:  # "... walk to the exit while the robot guides them"
                return RobotReading("cross", text=" ... ".join(texts), guides=guides)  # route: guided_route.py
            return None  # "when the robot comes near": it moves, but the sentence sets no route
        if task in ("wait", "patrol") and location is None:
            location = destination or (via[0] if via and task == "patrol" else None)
            destination = None if location == destination else destination
            via = [v for v in via if v != location]
        confidence = place_confidences({"start": start, "destination": destination, "location": location}, via,
                                       read_from)
        if task_confidence is not None:
            confidence.insert(0, task_confidence)
        return RobotReading(task, start, destination, location, tuple(via), " ... ".join(texts), tuple(confidence),
                            follows, wait_seconds if task == "wait" else None, guides if task == "cross" else None,
                            avoid=tuple(avoid))

    def _passes_by(self, verb: int | None) -> bool:
        """Whether the robot's verb says it goes by, though no place is named ("as it rolls past",
        "glides by", "trundles through", "zips along", "as it passes"): crossing the scene."""
        s = self.s
        if verb is None or s.verb(verb) in lx.ROBOT_WAIT_VERBS | lx.ROBOT_FOLLOW_VERBS:
            return False
        nxt = s.low[verb + 1] if verb + 1 < s.n else ""
        return nxt in _PASSING_WORDS or (s.verb(verb) in lx.VIA_OBJECT_VERBS and (not nxt or s.is_punct(verb + 1)
                                                                                  or nxt in lx.CLAUSE_STARTERS))

    def _after_a_thing_gone_to(self, place: Place, clause: Clause) -> bool:
        """Whether the place says where a thing the robot goes to is ("goes to its dock in the
        hallway"), not where it goes by after a place ("to the kitchen through the hallway")."""
        s = self.s
        k = place.index - 1
        while k > 0 and (s.w[k].pos in ("NOUN", "ADJ", "DET", "PRON") or s.w[k].tag == "VBG") and not s.is_punct(k):
            k -= 1
        return k < place.index - 1 and s.low[k] in lx.DESTINATION_PREPOSITIONS and \
            not any(p.index == k and p.match is not None for p in clause.places)

    def _stops_at(self, rc: RobotClause, place: Place) -> bool:
        """Whether the verb that governs a place of the robot's route is one of staying ("... and
        charges in the hallway", "... and is parked by the lifts")."""
        s = self.s
        verbs = [i for i in rc.tokens if i < place.index and i != rc.verb and not s.after_determiner(i) and (
            s.is_verb(i) or s.w[i].tag == "VBN" or (s.low[i - 1] in ("and", "then") and verb_lemma(s.low[i]) != s.low[i]))]
        return bool(verbs) and (s.verb(verbs[-1]) in lx.ROBOT_WAIT_VERBS - {"be"} or (
            s.w[verbs[-1]].tag == "VBN" and s.verb(verbs[-1]) in lx.ROBOT_PLACED_VERBS))

    def _followed(self, verb: int) -> str | None:
        s = self.s
        k = s.skip(verb + 1, {"close", "closely", "right", "just", "along", "behind", "after"})
        j = s.skip(k, lx.DETERMINERS)
        counted = j + 1 < s.n and s.w[j].pos == "NUM"  # "follows two teenagers"
        head = self.people.person_head(j + 1 if counted else j, counted=counted) if j < s.n else None
        if head is not None:
            return s.span(k, head)  # "the security guard", "the ticket inspector"
        if k < s.n and s.low[k] in ("him", "her", "them", "us") and (k + 1 == s.n or s.w[k + 1].pos not in ("NOUN", "PROPN", "ADJ")):
            return s.low[k]  # "leads her to check-in": the pronoun, not "her" as a determiner
        end = s.skip(k, lx.DETERMINERS | lx.NP_MODIFIERS)
        if end < s.n and (self.people.is_person_noun(end) or s.low[end] in ("him", "her", "them", "us")):
            return s.span(k, end)
        return None

    @staticmethod
    def _task(verb: str, clause: Clause, command: bool) -> str | None:
        if verb in lx.ROBOT_FOLLOW_VERBS:
            return "follow"
        if verb in lx.ROBOT_PATROL_VERBS or lx.INTENT_VERBS.get(verb) == "wander" or clause.intent == "wander":
            return "patrol"
        if verb in lx.ROBOT_WAIT_VERBS or verb in _SERVING_VERBS or (verb and lx.INTENT_VERBS.get(verb) == "wait"):
            return "wait"
        if verb in lx.ROBOT_CROSS_VERBS or verb in lx.LEADING_VERBS or lx.INTENT_VERBS.get(verb) in ("walk", "evacuate") or (command and not verb):
            return "cross"
        return None

    @staticmethod
    def _role(p: Place, verb_index: int | None, stationary: bool) -> str:
        prep = p.prep
        if prep in ("from", "obj:start", "out", "off"):
            return "start"  # "brings the towels in off the balcony to the bathroom": from the balcony
        if stationary:
            return "location"
        if prep in lx.DESTINATION_PREPOSITIONS or prep in ("obj:dest", "for", "purpose"):
            return "destination"
        if prep in lx.VIA_PREPOSITIONS or prep in ("obj:via", "obj:at"):
            return "via"
        if verb_index is not None and p.index < verb_index:
            return "start"  # "the robot in the lobby drives to ward A"
        return "via"  # "drives to ward A, stopping at the nurse station"
