"""Pass 2, part 5: people named as the object of someone else's verb, who are people of the scene
all the same: those a person takes along ("a guide leads twelve tourists", "an orderly wheels a
patient"), sends somewhere ("a guard sends the visitors out of the café"), or follows ("the pupils
follow their teacher"), and those inside the robot's own clause ("the robot escorts a lost child")."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.robot_escorts import escorts_to_a_place
from grove_tui.language.aside_movers import aside_leader
from grove_tui.language.carried_things import collective_of_things, counted_things
from grove_tui.language.caused_motion import moves_along, route_after, taking_verb
from grove_tui.language.moved_pronouns import moved_pronoun
from grove_tui.language.owned_rides import own_ride
from grove_tui.language.titled_couples import couple_end
from grove_tui.language.counts import Quantifier, quantifier
from grove_tui.language.movers import FETCHING_VERBS
from grove_tui.language.possessed_people import possessed_head
from grove_tui.language.people import People
from grove_tui.language.robot_crowds import its_way
from grove_tui.language.sequences import each_leader, shared_subject_is_person, shared_subject_is_robot
from grove_tui.language.robot_modals import before_obligation
from grove_tui.language.school_classes import named_class
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma


# Words after "until" that name someone who is there, when they take someone along or walk ("... until a
# guard takes her to the desk"), not "until someone collects them" nor "until a nurse calls them".
# Arriving with nowhere said after "until": the one waited for ("until her son turns up").
_ARRIVING = frozenset("arrive come turn show appear return emerge".split())
_ARRIVING_TAILS = frozenset("up back out along round over in".split())
_SOMEONE_NAMED = frozenset({"a", "an", "the", "her", "his", "their", "its", "two", "three", "four"})


def nobody_after_subordinator(s: Sentence, at: int) -> bool:
    """Whether the people at `at` come after a word that names nobody who is there ("... until someone
    collects them", "if anyone asks"); after "until", a person said with an article is somebody ("...
    cries near the toy store until a guard takes her to the information desk")."""
    p = at - 1
    if p >= 1 and s.low[p] in _SOMEONE_NAMED and s.low[p - 1] == "until" and _waited_for(s, at):
        return True  # "... until her son turns up"
    if s.w[p].pos != "SCONJ" or s.low[p] in lx.CLAUSE_STARTERS:
        return False
    if s.low[p] != "until" or s.low[at] not in _SOMEONE_NAMED:
        return True
    verb = next((k for k in range(at + 1, min(at + 5, s.n)) if s.w[k].pos in ("VERB", "AUX")), None)
    if _waited_for(s, at):
        return True
    return verb is None or not (verb_lemma(s.low[verb]) in lx.LEADING_VERBS  # not "until a nurse calls them"
                                or lx.INTENT_VERBS.get(verb_lemma(s.low[verb])) == "walk")


def _waited_for(s: Sentence, at: int) -> bool:
    """Whether the people at `at`, after "until", only arrive, nowhere said ("until her son turns
    up", "until their mum comes back"): whom the others wait for, no group of the scene."""
    verb = next((k for k in range(at + 1, min(at + 5, s.n)) if s.w[k].pos in ("VERB", "AUX")), None)
    if verb is None or verb_lemma(s.low[verb]) not in _ARRIVING:
        return False
    end = s.skip(verb + 1, _ARRIVING_TAILS)
    return end >= s.n or s.is_punct(end) or (s.low[end] in lx.CLAUSE_STARTERS and s.low[end] not in ("and", "then"))


# What one named person rides in: "pushes Alastair's wheelchair" takes Alastair along.
_RIDDEN_BY_ONE = frozenset("wheelchair pram buggy pushchair stroller bed stretcher gurney".split())


_OWNERS = frozenset({"his", "her", "their", "my", "our", "your"})


def _counted_at(s: Sentence, at: int) -> Quantifier | None:
    """The count of the phrase at `at`, after a possessive too ("leads her twelve pupils", "follow their
    two teachers", round 71)."""
    return quantifier(s, at) or (quantifier(s, at + 1) if s.low[at] in _OWNERS else None)


class PeopleObjects:
    def __init__(self, s: Sentence, people: People) -> None:
        self.s = s
        self.people = people

    def led_by(self, at: int) -> bool:
        """Whether the phrase at `at` names people a person right before takes along: the object of a
        verb of leading, escorting, pushing or helping ("a tour guide leads twelve tourists", "an
        orderly wheels a patient", "a nurse helps an old man"): they go where the leader goes."""
        s = self.s
        p = at - 1
        if p >= 2 and s.low[p] in _OWNERS and verb_lemma(s.low[p - 1]) in lx.LEADING_VERBS:
            p -= 1  # "leads her class", "takes his party of pensioners": the group's mention starts after "her"
        leading = p >= 1 and verb_lemma(s.low[p]) in lx.LEADING_VERBS | FETCHING_VERBS
        if p < 1 or not (leading or s.w[p].pos == "VERB") or not (
                self.people.is_person_noun(p - 1) or shared_subject_is_person(s, self.people, p - 1)
                or each_leader(s, self.people, p - 1) is not None  # "two porters, each pushing a patient"
                or aside_leader(s, self.people, p - 1) is not None):  # "a porter, pushing a woman in a wheelchair"
            return False  # "a guard waits on platform 1, then leads four passengers": the guard's too
        q = _counted_at(s, at)
        start = q.end if q is not None else s.skip(at, lx.DETERMINERS | lx.NP_MODIFIERS)
        start = s.skip(start, {"of", "the"})
        head = self.people.person_head(start, counted=q is not None)
        if head is None and q is None:
            head = possessed_head(s, self.people, start)  # "pushes the bride's nan": the nan
        if moved_pronoun(s, at) or own_ride(s, at) is not None or ((couple := couple_end(s, at)) is not None and (leading or route_after(s, couple))):
            return True  # "Mr Ahmed's son wheels him from ...", "escorts Mr and Mrs Obi from ...": taken along
        if not leading:  # "a nurse trundles a patient out of X-ray": taken along a route
            if head is not None and moves_along(s, p, head):
                return True
            ridden = self.carried_owner(at)  # "trundles Mr Lee's wheelchair out of ward A": Mr Lee moved
            return ridden is not None and taking_verb(s, p) and route_after(s, ridden[1])
        if counted_things(s, self.people, p, q, head) or collective_of_things(s, self.people, p, head):
            return False  # "takes a handful of used mirrors to ...", "brings a bunch of flowers": things carried
        return head is not None or self.carried_owner(at) is not None \
            or named_class(s, start) is not None  # "a teacher takes year 3 to the hall"

    def carried_owner(self, at: int) -> tuple[int, int] | None:
        """(the person, the thing) when the phrase at `at` names what someone is carried or pushed in,
        by its owner: "his father's wheelchair", "the toddler's buggy", "their gran's wheelchair"."""
        s = self.s
        k = s.skip(at, lx.DETERMINERS | lx.NP_MODIFIERS | {"his", "her", "their", "my", "our"})
        while k < s.n and s.w[k].pos == "ADJ" and not self.people.is_person_noun(k):
            k += 1
        if k >= s.n:
            return None  # "... and ten tourists follow her": nothing after
        named = s.w[k].pos == "PROPN" and s.w[k].text[:1].isupper()  # "Alastair's wheelchair"
        while named and k + 1 < s.n and s.w[k + 1].pos == "PROPN" and s.w[k + 1].text[:1].isupper():
            k += 1  # "Mr Lee's bed", "Edith Baxter's wheelchair": the name's last word owns it
        if k + 2 >= s.n or not (self.people.is_person_noun(k) or named) or s.low[k + 1] not in ("'s", "’s", "'", "s'"):
            return None
        thing = k + 2
        while thing < s.n and s.w[thing].pos == "ADJ":
            thing += 1
        if named and not self.people.is_person_noun(k) and thing < s.n and s.lemma(thing) not in _RIDDEN_BY_ONE:
            return None  # "Boots's trolley", "Tesco's chair": a shop's, no one in it
        return (k, thing) if thing < s.n and s.lemma(thing) in lx.CARRYING_THINGS else None

    def sent_by(self, at: int) -> bool:
        """Whether the phrase at `at` names people a person right before sends somewhere ("a guard
        sends the visitors out of the café", "the manager tells two interns to go to the boardroom")."""
        s = self.s
        p = at - 1
        if p < 1 or s.verb(p) not in lx.SENT_VERBS or not self.people.is_person_noun(p - 1):
            return False
        q = _counted_at(s, at)
        start = q.end if q is not None else s.skip(at, lx.DETERMINERS | lx.NP_MODIFIERS)
        return self.people.person_head(start, counted=q is not None) is not None

    def followed(self, at: int) -> bool:
        """Whether the phrase at `at` names a person people follow, brought in by the phrase: someone
        of theirs, someone new or someone by name ("the pupils follow their teacher to the hall",
        "trail behind a guide", "follow Dr Jones"); not the robot, signs, or one said as known
        already ("follow the consultant": whom they follow, no group of its own)."""
        s = self.s
        p = at - 1
        if p >= 1 and s.low[p] in ("behind", "after"):
            p -= 1
        if p < 1 or s.verb(p) not in lx.FOLLOWING_VERBS or s.after_determiner(p):
            return False
        if s.low[at] in ("the", "this", "that", "these", "those"):
            return False  # "students follow the consultant": the one they go behind, said as known
        q = _counted_at(s, at)
        start = q.end if q is not None else s.skip(at, lx.DETERMINERS | lx.NP_MODIFIERS)
        return self.people.person_head(start, counted=q is not None) is not None

    def robot_object(self, at: int) -> str | None:
        """Whether the phrase at `at` names people inside the robot's own clause, after its verb:
        people it takes along ("the robot escorts a lost child to ...": "led"), follows ("the robot
        follows grandpa from ...": "followed") or meets on its way ("the robot passes two nurses
        chatting in the corridor", "delivers coffee to the manager": "met"). They are people of the
        scene all the same."""
        s = self.s
        noun = s.skip(at, lx.DETERMINERS | lx.NP_MODIFIERS)
        if noun >= s.n or (self.people.person_head(self._phrase_head(at), counted=_counted_at(s, at) is not None)
                           is None and not self.people.is_person_noun(noun)):
            return None
        p = at - 1
        while p > 1 and s.w[p].dep in ("amod", "det") and s.w[p].head >= at:
            p -= 1  # "guides an anxious first-time claimant": the mention's own words, still its object
        direct = True
        while p > 0 and p >= at - 6 and not s.is_punct(p) and s.low[p] not in lx.CLAUSE_STARTERS and \
                (s.w[p].pos in ("ADP", "ADV", "DET", "ADJ", "PART") or s.low[p] in lx.ROBOT_PREPOSITIONS or
                 its_way(s, p) or (
                    s.w[p].pos in ("NOUN", "NUM") and not self.people.is_person_noun(p)
                    and not s.index.knows(s.lemma(p)))):
            direct = False
            p -= 1  # "hands out leaflets to passengers", "drives past a group of visitors"
        if p < 1 or not (s.w[p].pos in ("VERB", "AUX") or s.w[p].tag.startswith("VB") or
                         verb_lemma(s.low[p]) in lx.LEADING_VERBS | lx.ROBOT_FOLLOW_VERBS | lx.ROBOT_CROSS_VERBS):
            by_parse = self._verb_through_prepositions(self._phrase_head(at))
            if by_parse is None:
                return None
            p, direct = by_parse, False  # "takes a chart from the nurse in ward B to the doctor": met on its way
        if s.w[p].tag == "VBN" and p > 0 and verb_lemma(s.low[p - 1]) in ("be", "get"):
            return None  # "the robot is followed by two children": a passive, the people's own clause
        k = before_obligation(s, p)  # "the robot is meant to follow", "the robot should follow"
        while k > 0 and s.w[k].pos == "ADV":
            k -= 1  # "the robot slowly escorts"
        robot = s.low[k] in lx.ROBOT_WORDS or (s.low[k] == "it" and any(w in lx.ROBOT_WORDS for w in s.low[:k])) \
            or (s.low[k] == "to" and k > 0 and s.low[k - 1] in lx.ROBOT_WORDS) \
            or shared_subject_is_robot(s, self.people, k)  # "ask the robot to escort ..."; "..., then leads ..."
        if not robot:
            return None
        word = verb_lemma(s.low[p])
        if direct and word in lx.ROBOT_FOLLOW_VERBS and word not in lx.LEADING_VERBS:
            return "followed"
        return "led" if direct and (word in lx.LEADING_VERBS or escorts_to_a_place(s, p)) else "met"

    def _verb_through_prepositions(self, head: int) -> int | None:
        """The verb a person's phrase hangs from by the parse, through a preposition of the robot's way
        and what else the verb took ("from the nurse in ward B to the doctor": "to" hangs from the
        verb, past the place and person before it the words alone cannot step over)."""
        s = self.s
        if head >= s.n or s.w[head].dep != "pobj" or s.low[s.w[head].head] not in lx.ROBOT_PREPOSITIONS | {"to", "from"}:
            return None
        k = s.w[head].head
        for _ in range(3):
            up = s.w[k].head
            if up == k or s.w[k].dep not in ("prep", "advmod", "dobj", "pobj") or s.w[up].sentence != s.w[head].sentence:
                return None
            k = up
            if s.w[k].pos == "VERB":
                return k
            if self.people.is_person_noun(k) or s.low[k] in lx.CLAUSE_STARTERS:
                return None  # "as the duo from the bike club natter": the phrase describes the duo
        return None

    def _phrase_head(self, at: int) -> int:
        s = self.s
        q = _counted_at(s, at)
        start = q.end if q is not None else s.skip(at, lx.DETERMINERS | lx.NP_MODIFIERS)
        return s.skip(start, {"of", "the"})
