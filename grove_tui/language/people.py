"""Pass 2, part 1: which words are people ("nurses", "a sommelier", "the au pair", "ten zombies"),
where a person phrase's head noun is, and the short label a group is known by."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.one_name import one_name
from grove_tui.language.plural_surnames import plural_surname
from grove_tui.language.joined_names import joined_first_name
from grove_tui.language.time_phrases import time_phrase_end
from grove_tui.language.timer_people import timer_person
from grove_tui.language.hazard_subjects import hazard_verb, hazard_word
from grove_tui.language.adverbed_participles import adverb_before_participle
from grove_tui.language.animal_idioms import animal_idiom_person
from grove_tui.language.hyphen_counts import count_ends_at
from grove_tui.language.compound_people import chain_end
from grove_tui.language.gathering_verbs import gathering_verb
from grove_tui.language.parser import known_word
from grove_tui.language.counted_pushers import pushes_after
from grove_tui.language.of_names import of_name_end, possessive_name_end
from grove_tui.language.person_modifiers import compound_head_person, head_person, kind_word, modifier_end
from grove_tui.language.adverb_subjects import past_adverbs
from grove_tui.language.held_things import a_load_of_things
from grove_tui.language.vehicle_words import coach_as_vehicle
from grove_tui.language.side_words import side_word
from grove_tui.language.adjective_people import PLURAL_WORDS, adjective_person
from grove_tui.language.agent_compounds import agent_compound, agent_of_a_verb
from grove_tui.language.place_modifiers import names_a_place
from grove_tui.language.counted_compounds import kind_before_counted, kind_before_hyphened
from grove_tui.language.placed_people import placed_person
from grove_tui.language.scene_doers import scene_doer
from grove_tui.language.thing_people import moves_as_a_person, person_of_a_thing
from grove_tui.language.trader_people import trader_subject
from grove_tui.language.role_words import abbreviated_role, abbreviation_label, family_member, plural_adjective_people, world_person_name
from grove_tui.language.second_verbs import second_verb
from grove_tui.language.aided_names import aided_name
from grove_tui.language.caused_motion import taken_name
from grove_tui.language.movers import fetched_then_taken, moved_person_noun, mover_subject
from grove_tui.language.moved_described import moved_described_person
from grove_tui.language.aid_things import aid_thing
from grove_tui.language.failing_things import failing_thing
from grove_tui.language.feeling_people import feels_about_the_robot
from grove_tui.language.chore_subjects import chore_subject
from grove_tui.language.chat_list_items import chat_list_doer, chat_list_item
from grove_tui.language.own_place_items import own_place_item
from grove_tui.language.listed_people import listed_person
from grove_tui.language.counted_kinds import counted_plural_subject
from grove_tui.language.verb_tagged_plurals import counted_compound_person, verb_tagged_plural
from grove_tui.language.owned_by_subject import subject_of_his_or_her
from grove_tui.language.life_adjectives import by_a_life_adjective
from grove_tui.language.lone_person import by_a_person_adjective, goes_along_a_route, told_as_he_or_she
from grove_tui.language.sentence import Sentence
from grove_tui.language.singular_verbs import subject_of_a_later_verb
from grove_tui.language.sequences import acting_as_verb
from grove_tui.language.spelling import near_person_noun
from grove_tui.language.thing_modifiers import modifies_a_thing
from grove_tui.language.role_things import role_thing
from grove_tui.language.tokens import verb_lemma
from grove_tui.language.where_people import describes_a_place
from grove_tui.language.coordinated_roles import coordinated_role
from grove_tui.language.role_suffixes import collective_modifies_role, suffix_role
from grove_tui.language.unlisted_people import (CHILD_NAME_WORDS, names_a_place_with_next, unlisted_escorted, unlisted_subject)
from grove_tui.language.youth_units import youth_unit
from grove_tui.language.apposed_names import apposed_name
from grove_tui.language.weather_nouns import weather_noun

_MULTIWORD_LAST = frozenset(p[-1] for p in lx.MULTIWORD_PEOPLE)


def compound_person(lem: str) -> bool:
    """Whether a word is a compound naming a person ("lifeguard", "groundsman", "goalkeeper"): a
    person's word after at least three letters, and no thing so named ("mudguard")."""
    return lem.isalpha() and lem not in lx.COMPOUND_THINGS and lem not in lx.NON_PEOPLE and any(
        lem.endswith(head) and len(lem) - len(head) >= 3 for head in lx.COMPOUND_PERSON_HEADS)


class People:
    """Who is a person in one sentence (a noun of the lexicon's list, a misspelling of one that is no
    English word, the subject of a verb only people do, or a counted noun that does more than things
    do), and the head and label of person phrases."""

    def __init__(self, s: Sentence) -> None:
        self.s = s

    def titled_name(self, k: int) -> int | None:
        """The last word of a name after a title ("Dr Jones", "Mr Li Wei", "Mrs Patel"), else None."""
        s = self.s
        if s.low[k].rstrip(".") not in lx.TITLES:
            return None
        j = k + 1 if k + 1 < s.n and s.low[k + 1] != "." else k + 2  # "Dr. Jones"
        end = None
        while j < s.n and j <= k + 3 and s.w[j].text[:1].isupper() and s.w[j].text.replace("'", "").replace("’", "").isalpha() and \
                s.w[j].pos == "PROPN" and (not s.index.knows(s.lemma(j)) or world_person_name(s, k, j)) and s.low[j] not in lx.ROBOT_WORDS and \
                s.low[j] not in lx.STOPWORDS | lx.PLACE_PREPOSITIONS | lx.CLAUSE_STARTERS and \
                verb_lemma(s.low[j]) not in lx.INTENT_VERBS:  # not "A Doctor Walks To Ward B"
            end, j = j, j + 1
        return end

    def is_person_noun(self, i: int) -> bool:
        s = self.s
        if self.titled_name(i) is not None or any(self.titled_name(k) == i for k in range(max(0, i - 3), i)):
            return True  # "Dr Jones", "Mrs Patel"
        lem = s.lemma(i)
        if acting_as_verb(s, i) or a_load_of_things(s, i) or coach_as_vehicle(s, i) or failing_thing(s, i) or \
                aid_thing(s, i) or time_phrase_end(s, i):  # "inches her walker": a walking frame; "the instant the robot ...": a time
            return False  # "..., then guides 5 passengers": a verb, no guide; "a sack of pellets", "the Glasgow coach": things
        if role_thing(s, i):
            return True  # "the keynote speaker walks", "a session chair heads to ...": a role
        if goes_along_a_route(s, i) or by_a_person_adjective(s, i):
            return True  # "the dispenser nips out of the pharmacy into the kitchen", "an elderly gent lingers"
        if (lem in lx.NON_PEOPLE or weather_noun(lem)) and lem not in lx.PERSON_NOUNS:
            return timer_person(s, i) or animal_idiom_person(s, i) or chat_list_doer(s, i)  # "a first-timer": a person, though a timer is a thing
        if lem in ("guard", "watch", "sentry") and i > 0 and s.verb(i - 1) in ("stand", "keep", "mount"):
            return False  # "the robot stands guard at the door": a duty, nobody
        if lem in lx.PERSON_NOUNS or s.low[i] in lx.PERSON_NOUNS or self.multiword_end(i) or adjective_person(s, i):
            return True  # "a drunk kicks the robot": an adjective standing for a person
        if abbreviated_role(s, i) or family_member(s, i) or plural_adjective_people(s, i) or plural_surname(s, i):
            return True  # "the GP waits", "our youngest edges away"
        if compound_head_person(s, i) or head_person(s, i) or agent_compound(s, i):
            return True  # "two team leaders", "the head goes back to her office", "three shelf stackers"
        if trader_subject(s, i) or listed_person(s, i) or feels_about_the_robot(s, i) or youth_unit(s, i):
            return True  # "the hairdresser goes to ...": a trade, though the world has its salon
        if counted_plural_subject(s, i) or verb_tagged_plural(s, i) or subject_of_his_or_her(s, i) or by_a_life_adjective(s, i):
            return True  # "thirty top-year juniors troop into ...", "the Dean leaves his vestry"
        if moves_as_a_person(s, i) or chat_list_item(s, i) or counted_compound_person(s, i) or own_place_item(s, i):  # "..., 1 sysadmin in comms room"
            return True  # "two wheelchairs roll to ...": a wheelchair user each, though the world has wheelchairs
        if s.w[i].pos in ("NOUN", "PROPN", "ADJ") and compound_person(lem):
            return True  # "the lifeguard", though the world names a lifeguard's chair
        if suffix_role(s, i) or coordinated_role(s, i) or apposed_name(s, i) or joined_first_name(s, i):  # "our guide Priya strolls": Priya
            return True  # "both quiz contestants leave", "a greeter by the leaflet stand", "the drummer and bassist haul"
        if self._subject_of_a_human_verb(i) or chore_subject(s, i) or self._agent_subject(i) or self._agent_going(i) or \
                self._reflexive_agent(i) or unlisted_subject(s, i) or unlisted_escorted(s, i) or \
                told_as_he_or_she(s, i) or placed_person(s, i) or scene_doer(s, i):  # "an old dear shrieks when she spots the robot"
            return True
        if mover_subject(s, i) or moved_person_noun(s, i) or fetched_then_taken(s, i) or moved_described_person(s, i) or \
                ((taken_name(s, i) or aided_name(s, i)) and self.is_person_noun(i - 2)):  # "a carer guides Doris from ..."
            return True  # "a keeper wheels a lady ...", "pushes an elderly gent on a gurney"
        # A misspelt word for people ("childern", "passangers"): one edit from a person noun, long
        # enough that the edit cannot turn one real word into another, no name of the world, and no
        # word of the parser's English vocabulary ("posters" is one edit from "porters", but a word).
        # The parser may call such a word a verb after a number ("Five colleages stroll"): a count
        # is followed by what it counts.
        counted = i > 0 and s.w[i - 1].pos == "NUM"
        if i > 0 and s.low[i - 1] in lx.ROBOT_WORDS:
            return False  # "the robot glides": the robot's verb, however close to "guides"
        return (len(s.low[i]) >= 6 and (s.w[i].pos in ("NOUN", "PROPN") or counted) and not s.index.knows(lem)
                and not known_word(s.low[i]) and not (lem != s.low[i] and known_word(lem))  # "scones": no "sons"
                and not second_verb(s, i) and near_person_noun(s.low[i]) is not None)

    def placed(self, k: int) -> bool:
        return placed_person(self.s, k) or scene_doer(self.s, k)  # "Put Mum on the settee": one person, placed; "Have ... and Grandpa doing ..."

    def plural_word(self, k: int) -> bool:
        """Whether a person word that looks singular names some people ("staff", "police", "the injured")."""
        return self.s.low[k] in PLURAL_WORDS

    def kind_word(self, k: int) -> bool:
        """Whether word k is inside a modifier naming a person's kind ("temp", "night-shift", "year 6")."""
        return kind_word(self.s, k)

    def describing_a_place(self, at: int) -> bool:
        """Whether the phrase at `at` only describes a place ("the room where poorly children wait")."""
        return describes_a_place(self.s, at)

    def multiword_end(self, i: int) -> bool:
        """Whether word i ends a person named by two words ("au pair", "station master")."""
        low = self.s.low
        if low[i] not in _MULTIWORD_LAST and self.s.lemma(i) not in _MULTIWORD_LAST:
            return False  # asked for every word the reader looks at: the common answer first
        return any(self._multiword_at(i - len(p) + 1, p) for p in lx.MULTIWORD_PEOPLE)

    def _multiword_at(self, i: int, p: tuple[str, ...]) -> bool:
        """Whether the words from i are p, the last one in the plural too ("two dinner ladies")."""
        last = i + len(p) - 1
        return (i >= 0 and last < self.s.n and tuple(self.s.low[i:last]) == p[:-1]
                and p[-1] in (self.s.low[last], self.s.lemma(last)))

    def multiword_start(self, i: int) -> int | None:
        """The last word of a person named by two words starting at i, else None."""
        for p in lx.MULTIWORD_PEOPLE:
            if self._multiword_at(i, p):
                return i + len(p) - 1
        return None

    def _agent_subject(self, i: int) -> bool:
        """A noun for someone who does something ("a busker strums", "the florist arranges"), in no
        list: the parser's subject of a verb that things do not do, ending like an agent noun, and
        no place, robot, thing or time word."""
        s = self.s
        word = s.w[i]
        if word.pos not in ("NOUN", "PROPN") or word.dep != "nsubj" or word.head == i:
            return False
        lem = s.lemma(i)
        head = s.w[word.head]
        verb = s.verb(word.head)
        # Not after a verb things do as well ("the sprinklers go off", "the heater stays on").
        return (lem.endswith(lx.AGENT_SUFFIXES) and len(lem) >= 5 and head.pos == "VERB"
                and verb not in lx.THING_VERBS and verb not in lx.INTENT_VERBS and verb not in ("be", "go", "start")
                and not hazard_verb(s, word.head)  # "butter catches fire", "paper ignites": a thing
                and not hazard_word(lem)  # "wiring smoulders", parsed a plural noun: a verb
                and verb_lemma(s.low[i]) not in lx.INTENT_VERBS  # "a cleaner wanders round": its verb
                and not s.index.knows(lem)
                and lem not in lx.ROBOT_WORDS and lem not in lx.NON_PLACES and lem not in lx.NON_PEOPLE
                and lem not in lx.BUILDING_WORDS and lem not in lx.DURATION_UNITS and lem not in lx.HAZARD_NOUNS)

    def _reflexive_agent(self, i: int) -> bool:
        """A noun in no list, ending like an agent's, that does something to itself ("a prankster
        parks himself in front of ...", "the juggler plants herself by ...", "two hecklers position
        themselves"): a person, however the parser tagged its verb."""
        s = self.s
        if i + 2 >= s.n or s.low[i + 2] not in ("himself", "herself", "themselves") or \
                s.w[i].pos not in ("NOUN", "PROPN") or not s.low[i + 1].isalpha():
            return False
        lem = s.lemma(i)
        return len(lem) >= 5 and lem.endswith(lx.WEAK_AGENT_SUFFIXES) and not self._a_thing(lem)

    def _agent_going(self, i: int) -> bool:
        """A noun for someone no list names, the subject of a verb of going or staying that things
        do as well ("the locksmith waits at reception", "after her shift the radiographer leaves
        her department"): an ending only people's nouns have, or an agent's ending and a pronoun
        for a person that refers to it ("her", "his"; "their" for a plural)."""
        s = self.s
        word = s.w[i]
        if word.pos not in ("NOUN", "PROPN"):
            return False
        # The parser may take the verb for a plural noun the word modifies ("an interpreter waits at"):
        # a determiner, the word, then a verb's "-s" form the lexicon knows.
        nxt = i + 1
        mistagged = (word.dep == "compound" and 0 < i and nxt < s.n and s.w[i - 1].pos == "DET"
                     and s.low[nxt].endswith("s") and verb_lemma(s.low[nxt]) != s.low[nxt]
                     and verb_lemma(s.low[nxt]) in lx.INTENT_VERBS)
        if mistagged:
            head = nxt
        elif word.dep != "nsubj" or word.head == i or s.w[word.head].pos not in ("VERB", "AUX"):
            return False
        else:
            head = word.head
        lem = s.lemma(i)
        verb = verb_lemma(s.low[head]) if mistagged else s.verb(head)
        if not lem.isalpha() or len(lem) < 5 or verb in lx.THING_VERBS or verb == "start" or self._a_thing(lem):
            return False
        if verb == "be" and not (head + 1 < s.n and s.preposition(head + 1) is not None):
            return False  # "the glazier is in the lobby", not "the bookseller is closed"
        singular = word.tag in ("NN", "NNP")
        if lem.endswith(lx.STRONG_AGENT_SUFFIXES) and (singular or verb != "go"):
            return True
        pronouns = lx.PERSONAL_PRONOUNS if singular else lx.PLURAL_PERSONAL_PRONOUNS
        owned = any(w.head == i and w.dep == "poss" for w in s.w)  # "the guard's torch": someone's thing
        if (singular and not owned or lem.endswith(lx.WEAK_AGENT_SUFFIXES)) and any(
                s.low[k] in pronouns and self._in_clause_of(k, head) for k in range(s.n)
                if s.w[k].sentence == word.sentence):
            return True  # "the chaplain leaves his office": "his" is someone's
        first = i
        while first > 0 and s.w[first - 1].dep == "compound" and s.w[first - 1].head == i and \
                s.w[first - 1].pos in ("NOUN", "PROPN"):
            first -= 1  # "the station announcer": a noun saying which kind, after the determiner
        if not (singular and lem.endswith(lx.WEAK_AGENT_SUFFIXES) and s.after_determiner(first)):
            return False
        # One of a kind who waits, arrives or leaves somewhere ("an interpreter waits at the
        # information desk while ..."), or the one subject of a sentence that names nobody else ("the
        # sommelier goes to the cellar"): a person, rather than a crowd nobody named.
        placed = verb in lx.PEOPLE_GOING_VERBS and head + 1 < s.n and (
            s.preposition(head + 1) is not None or s.low[head + 1] in lx.DETERMINERS)
        # Other people named only as its object do not make it one of a crowd ("the phrenologist sits
        # with a patient"); another subject does ("the developer and two interns go ...").
        return placed or not any((s.lemma(k) in lx.PERSON_NOUNS or s.low[k] in lx.PERSON_NOUNS)
                                 and s.w[k].dep not in ("pobj", "dobj", "obj")
                                 for k in range(s.n) if k != i)

    def _a_thing(self, lem: str) -> bool:
        """A word of a place, the robot, an animal or thing, a building, a time or a hazard."""
        return (names_a_place(self.s.index, lem) or lem in lx.ROBOT_WORDS or lem in lx.NON_PLACES or lem in lx.NON_PEOPLE
                or lem in lx.BUILDING_WORDS or lem in lx.DURATION_UNITS or lem in lx.HAZARD_NOUNS
                or lem in lx.IMPLIED_RANGES)

    def _in_clause_of(self, k: int, verb: int) -> bool:
        """Whether the word at k hangs, through the parse, under the verb at `verb` with no other
        subject on the way ("after her shift the radiographer leaves", not "she watches as ...")."""
        s = self.s
        seen = 0
        while seen < s.n:
            if k == verb:
                return True
            head = s.w[k].head
            if head == k:
                return False
            if head != verb and any(w.head == head and w.dep in ("nsubj", "nsubjpass") for w in s.w):
                return False  # "the torch flickers as he walks": "he" is the subject of a clause of its own
            k, seen = head, seen + 1
        return False

    def _subject_of_a_human_verb(self, i: int) -> bool:
        """A noun no list names, the parser's subject of a verb only people do ("a sommelier
        chats", "two botanists stroll"): a person, unless it names a place, the robot, a group
        word, a time or a hazard."""
        s = self.s
        word = s.w[i]
        if i > 0 and s.low[i - 1] in lx.ROBOT_WORDS:
            return False  # "the robot hums while ...": the robot's verb, tagged a noun
        parsed = word.pos in ("NOUN", "PROPN") and word.dep == "nsubj" and word.head != i and \
            s.w[word.head].pos == "VERB" and s.verb(word.head) in lx.HUMAN_SUBJECT_VERBS
        # The parser may also take the noun for an adjective and the verb for a plural noun ("a
        # sommelier chats"): a determiner or number, the word, then a human verb's "-s" form.
        nxt = i + 1
        mistagged = (0 < i and nxt < s.n and word.pos in ("NOUN", "PROPN", "ADJ")
                     and s.w[i - 1].pos in ("DET", "NUM") and verb_lemma(s.low[nxt]) in lx.HUMAN_SUBJECT_VERBS
                     and s.low[nxt] != verb_lemma(s.low[nxt]) and s.low[nxt].endswith("s")
                     and not (i >= 2 and s.w[i - 2].pos == "ADP"))  # "a family with a pram hurries": its object
        if not (parsed or mistagged):
            return False
        lem = s.lemma(i)
        return (lem.isalpha() and not s.index.knows(lem) and lem not in lx.ROBOT_WORDS
                and lem not in lx.NON_PLACES and lem not in lx.IMPLIED_RANGES and lem not in lx.HAZARD_NOUNS
                and lem not in lx.BUILDING_WORDS and lem not in lx.DURATION_UNITS)

    def person_head(self, j: int, *, counted: bool) -> int | None:
        """Index of the person noun of a phrase starting at j ("tired old patients"), or None.

        With a count before it, any plural noun counts ("ten zombies"), unless it names a place,
        a time or a thing of the world."""
        s = self.s
        k = j
        while k < s.n and k < j + 6 + 2 * sum(s.joins(h) for h in range(j, k)):  # "first-year": one word
            if s.low[k] in lx.ROBOT_WORDS:
                return None  # "the robot glides": whatever follows, the robot is nobody's kind
            named = self.titled_name(k)
            if named is not None:
                return named  # "Dr Jones": one person
            end = self.multiword_start(k)
            if end is not None:
                return end  # "the au pair": one person
            after = modifier_end(s, k) or of_name_end(s, k) or possessive_name_end(s, k)  # "Duke of Edinburgh hikers"
            if after is not None and after < s.n and (self.is_person_noun(after) or (
                    after + 1 < s.n and s.w[after].pos == "NOUN" and self.is_person_noun(after + 1)) or (
                    counted and k > j and s.w[after].tag == "NNS" and self.person_head(after, counted=True) == after)):
                k = after  # "night-shift workers", "year 6 pupils", "off-duty bus drivers": what kind, no count
                continue
            if k + 2 < s.n and s.joins(k + 1) and s.w[k].pos in ("NOUN", "ADJ", "ADV") and self.is_person_noun(k + 2) \
                    and s.lemma(k + 2) not in lx.IMPLIED_RANGES and not (k + 3 < s.n and self.is_person_noun(k + 3)):
                k += 2  # "some 25 well-wishers", "two day-trippers": one word, hyphenated
                continue
            if k + 2 < s.n and s.joins(k + 1) and (s.w[k].pos in ("NOUN", "ADJ", "PROPN") or s.w[k + 2].dep == "amod") \
                    and not self.is_person_noun(k) \
                    and s.lemma(k + 2) not in lx.IMPLIED_RANGES:  # not "a first-class patient"
                k += 2  # "bleary-eyed exam-season students": a hyphenated modifier, its last word then read
                continue
            if k > j and s.joins(k - 1) and k + 1 < s.n and s.w[k + 1].pos == "ADJ" and not self.is_person_noun(k):
                k += 1  # "six third-year medical students": the tail of a hyphenated modifier, then a describing word
                continue
            person = self.is_person_noun(k) and not gathering_verb(s.w, k)  # "twenty crowds about the robot"
            if person and self._does_only_what_things_do(k):
                return None  # "two fans whir in the server room"
            if person and s.w[k].pos == "ADJ" and k + 1 < s.n and \
                    s.w[k + 1].pos in ("NOUN", "PROPN") and s.w[k + 1].dep != "ROOT" and \
                    (self.is_person_noun(k + 1) or s.lemma(k + 1) in lx.IMPLIED_RANGES) and \
                    not self.third_person_verb(k + 1) and not self._verb_of_joined(k):
                k += 1  # "an elderly couple", "a young nurse": the word is an adjective here
                continue
            if person and self.collective_after(k):
                return k + 1  # "the security team", "a student group": the collective heads the phrase
            last = chain_end(s, k) if person else None
            if last is not None and self.is_person_noun(last):
                k = last  # "two coach company reps": the reps, of a coach company
                continue
            if person and not scene_doer(s, k) and (self._modifies_next_noun(k) or modifies_a_thing(s, k, person_next=k + 1 < s.n and self.is_person_noun(k + 1))):
                return None  # "the outpatient clinic", "security alert": a thing named after people
            if person or (s.lemma(k) in lx.IMPLIED_RANGES and k + 1 < s.n and s.low[k + 1] == "of"):
                # ("a queue of eight people": the collective heads the phrase)
                while k + 1 < s.n and self.is_person_noun(k + 1) and s.lemma(k + 1) not in lx.IMPLIED_RANGES \
                        and not s.w[k + 1].tag.startswith("VB") and not (
                            not counted and k + 2 < s.n and s.w[k + 2].pos in ("ADP", "DET", "PUNCT")
                            and not self._compound_of_next(k) and not collective_modifies_role(s, k)):
                    # "staff members", "security guards": the last noun heads the phrase; but in "Mum
                    # cooks in the kitchen" the second word is the verb
                    k += 1
                return k
            if s.w[k].pos == "ADV" and k + 1 < s.n and (
                    s.w[k + 1].pos == "ADJ" or s.w[k + 1].dep == "amod" or side_word(s, k)
                    or adverb_before_participle(s, k, self.is_person_noun)):  # "away fans", "freshly jabbed"
                k += 1  # "a partially sighted woman", "a very frail man": the adverb says how, no one
                continue
            if s.low[k] in lx.NP_MODIFIERS or s.w[k].pos == "ADJ" or (s.w[k].tag in ("VBN", "VBG") and (s.w[k].dep == "amod" or (  # "two whining toddlers"
                    k + 1 < s.n and s.w[k + 1].tag == "NNS" and self.is_person_noun(k + 1) and s.w[k].dep != "prep"))) \
                    or (k > j and adverb_before_participle(s, k - 1, self.is_person_noun)) \
                    or (s.w[k].pos == "PROPN" and s.w[k].text.islower() and k + 1 < s.n and s.w[k + 1].pos == "ADJ"):
                k += 1  # "tired old patients", "two lost children", "waiting visitors"; "a tipsy first-year": no name
                continue
            if kind_before_counted(s, k, j, counted, self.is_person_noun, lambda x: self.person_head(x, counted=True)):
                return k + 1  # "nine cub scouts": the kind, then the counted plural
            if kind_before_hyphened(s, k, j, counted, lambda x: self.person_head(x, counted=True)):
                k += 1  # "fifty Saturday bargain-hunters": when or what kind, then a hyphened plural
                continue
            if s.w[k].pos in ("NOUN", "PROPN") and k + 1 < s.n and (self.is_person_noun(k + 1) or (
                    counted and k >= 3 and s.joins(k - 1) and count_ends_at(s, k - 3) and self.person_head(k + 1, counted=True) == k + 1)):
                k += 1  # "flight attendants", "dog walker", "twenty season-ticket holders": the kind of person
                continue
            if s.w[k].pos in ("NOUN", "PROPN") and k + 2 < s.n and s.w[k + 1].pos in ("NOUN", "PROPN") and \
                    s.w[k + 1].tag not in ("NNS", "NNPS") and (self.is_person_noun(k + 2) or (
                        k + 3 < s.n and s.w[k + 2].pos in ("NOUN", "PROPN") and self.is_person_noun(k + 3))):
                k += 1  # "revenue protection officers", "car park attendants": a compound naming the kind
                continue
            if (counted and s.w[k].tag in ("NNS", "NNPS") and s.lemma(k) not in lx.NON_PLACES
                    and s.lemma(k) not in lx.NON_PEOPLE
                    and s.lemma(k) not in lx.DURATION_UNITS and not names_a_place(s.index, s.lemma(k))
                    and (verb_lemma(s.low[k]) not in lx.INTENT_VERBS or self._noun_before_its_verb(k))
                    and self._does_what_people_do(k)):
                return k
            return None
        return None

    def _noun_before_its_verb(self, k: int) -> bool:
        """Whether a counted plural that is a verb's form too ("potters", "ramblers") is the parser's subject of
        a verb after it ("nine potters throw", "the five potters in there get out") or a noun a participle
        describes ("of nine potters throwing at the wheels"): a noun, not the verb of a bare count."""
        w, s = self.s.w[k], self.s
        if w.tag != "NNS":
            return False
        if w.dep == "pobj":
            return k + 1 < s.n and s.w[k + 1].tag in ("VBG", "VBN") and s.w[k + 1].head == k
        return w.dep in ("nsubj", "nsubjpass") and k < w.head <= k + 4 and s.is_verb(w.head)

    def _compound_of_next(self, k: int) -> bool:
        """Whether the parser makes the person word at k a modifier of the next, itself no verb's
        subject ("follows the security guard around ...", not "Mum cooks in the kitchen")."""
        s = self.s
        nxt = s.w[k + 1]
        return s.w[k].dep == "compound" and s.w[k].head == k + 1 and nxt.dep in ("dobj", "pobj", "obj", "nsubj") \
            and not self.third_person_verb(k + 1)

    def _does_what_people_do(self, k: int) -> bool:
        """Whether a counted noun no list names is the subject of something people do ("ten zombies
        shamble to the exit", "five volunteers hand out leaflets"), not a thing that only is or
        hangs somewhere ("two posters hang in the lobby", "three clocks tick")."""
        s = self.s
        head = s.w[k].head
        if s.w[k].dep not in ("nsubj", "nsubjpass") or head == k:
            return True  # the parser gives no verb to judge by: keep the count's reading
        return s.verb(head) not in lx.THING_VERBS

    def _does_only_what_things_do(self, k: int) -> bool:
        """Whether a person word is the parser's subject of a verb only things do, with no object
        ("two fans whir", not "two nurses hang the posters")."""
        s = self.s
        word = s.w[k]
        if word.dep not in ("nsubj", "nsubjpass") or word.head == k or s.w[word.head].pos != "VERB":
            return False
        has_object = any(w.head == word.head and w.dep in ("dobj", "obj") for w in s.w)
        verb = s.verb(word.head)
        if s.lemma(k) not in lx.PERSON_THINGS and verb not in lx.SOUND_LIGHT_VERBS:
            return False  # "the porter leans against the wall": a person, whatever things do too
        if verb in lx.EVENT_VERBS and s.lemma(k) in lx.PERSON_THINGS and not has_object and (
                word.head + 1 == s.n or s.is_punct(word.head + 1)):
            return True  # "Once the class ends, ...": the lesson, no people
        return (verb in lx.THING_VERBS and verb not in lx.INTENT_VERBS and not has_object  # "line up" is people
                and not self._phrasal_after(word.head))

    def _phrasal_after(self, v: int) -> bool:
        """Whether a verb begins a phrase only people do ("hang around", "hang out", "line up")."""
        s = self.s
        return any(tuple([s.verb(v), *s.low[v + 1:v + len(phrase)]]) == phrase
                   for phrase in lx.PHRASAL_INTENTS if phrase[0] == s.verb(v))

    def _modifies_next_noun(self, k: int) -> bool:
        """Whether a person noun only modifies the noun after it ("outpatient clinic", "staff room"):
        that noun is no person, no collective and no verb the lexicon knows, and the parser does not
        make it the sentence's verb ("Mum cooks dinner")."""
        s = self.s
        if k + 1 >= s.n:
            return False
        nxt, word = s.w[k + 1], s.low[k + 1]
        if word in ("'s", "’s", "'") or nxt.tag == "POS":
            return True  # "the manager's office"
        if names_a_place_with_next(s, k):
            return True  # "by the host stand"
        if word in lx.LOCATION_ADVERBS:
            return False  # "the pupils downstairs", "the guests inside": where they are, no noun
        if self._verb_of_joined(k):
            return False  # "three kids and their mum queue": the last of joined people, then their verb
        plural = s.lemma(k) in lx.IMPLIED_RANGES or s.lemma(k) != s.low[k]
        if plural and word == verb_lemma(word) and (
                verb_lemma(word) in lx.INTENT_VERBS or word in lx.HUMAN_SUBJECT_VERBS or word in lx.SLOW_WORDS) \
                and (k + 2 >= s.n or s.w[k + 2].pos in ("ADP", "PUNCT", "ADV")):
            return False  # "a retired couple dawdle through", "a dozen shoppers dawdle past": plural verb
        if pushes_after(s, k):
            return False  # "a couple of mums wheel prams": their verb, though parsed as a noun
        if k > 0 and s.w[k - 1].pos == "NUM" and s.lemma(k) != s.low[k] and \
                not s.index.knows(s.lemma(k + 1)) and k + 2 < s.n and \
                s.w[k + 2].pos in ("NOUN", "DET", "ADP", "PRON"):
            return False  # "two interns lug boxes from ...": after a count, the next word is the verb
        # The parser may make the noun after a singular person word the sentence's verb: "Mum cooks"
        # is one, "Security alert:" is not.
        verb_like = (nxt.dep == "ROOT" and (word.endswith("s") or s.lemma(k) != s.low[k])) or \
            self.third_person_verb(k + 1)
        gerund_noun = nxt.tag == "NN" and word.endswith("ing")  # "the team meeting", not "nurses meeting"
        return (nxt.pos == "NOUN" and not verb_like and not nxt.tag.startswith("VB")
                and not self.is_person_noun(k + 1) and s.lemma(k + 1) not in lx.IMPLIED_RANGES
                and (gerund_noun or (verb_lemma(word) not in lx.INTENT_VERBS and verb_lemma(word) not in lx.ROBOT_VERBS))
                and s.lemma(k + 1) not in lx.DURATION_UNITS)

    def collective_after(self, k: int) -> bool:
        """Whether the person word at k names the members of a collective noun right after it ("the
        security team", "a staff party"), not a verb ("the nurses group together")."""
        s = self.s
        if k + 1 >= s.n or s.w[k + 1].pos not in ("NOUN", "PROPN") or s.w[k + 1].tag.startswith("VB"):
            return False
        noun = s.lemma(k + 1)
        if s.lemma(k) != s.low[k] and s.low[k] not in ("staff", "police"):
            return False  # "the porters group together": a plural subject, then its verb
        return noun in lx.IMPLIED_RANGES and noun not in lx.QUEUE_COLLECTIVES and s.lemma(k) not in lx.IMPLIED_RANGES \
            and verb_lemma(s.low[k + 1]) not in lx.INTENT_VERBS and not self.multiword_end(k + 1)

    def _verb_of_joined(self, k: int) -> bool:
        """Whether the word after the person word at k is the plural verb of people joined by "and"
        ("three kids and their mum queue", "two porters and a nurse wait")."""
        s = self.s
        if k + 1 >= s.n:
            return False
        word = s.low[k + 1]
        # a verb no list names, in its plural form, then where or how ("the kids and their nan bake in
        # the kitchen"): the small model makes it a noun the person word modifies
        unlisted = s.w[k + 1].pos == "NOUN" and word.isalpha() and not word.endswith("s") and \
            not s.index.knows(s.lemma(k + 1)) and (k + 2 >= s.n or s.w[k + 2].pos in ("ADP", "ADV", "PUNCT", "DET"))
        return word == verb_lemma(word) and (verb_lemma(word) in lx.INTENT_VERBS or word in lx.HUMAN_SUBJECT_VERBS
                                             or unlisted) and self._joined_subject(k)

    def _joined_subject(self, k: int) -> bool:
        """Whether the person word at k ends a phrase joined by "and" to people before it ("three
        kids and their mum", "the nurses and a porter")."""
        s = self.s
        j = k - 1
        while j >= 0 and (s.low[j] in lx.DETERMINERS or s.low[j] in lx.NP_MODIFIERS or s.w[j].pos in ("ADJ", "NUM")):
            j -= 1
        return j >= 1 and s.low[j] == "and" and self.is_person_noun(j - 1)

    def third_person_verb(self, i: int) -> bool:
        """Whether the word at i, which the parser may tag a plural noun, is the verb of the singular
        person noun before it: "a cleaner mops the corridor", "a cleaner mops near the toilets"
        (an "-s" word between a singular person and a determiner, preposition or the end)."""
        s = self.s
        if i < 1 or i >= s.n or not s.low[i].endswith("s") or s.low[i].endswith("ss"):
            return False
        before = i - 1
        named_kin = s.low[before] in lx.KIN_NAMES and (before == 0 or s.low[before - 1] not in lx.DETERMINERS)
        if not self.is_person_noun(before) or s.lemma(before) != s.low[before] or \
                s.index.knows(s.lemma(i)) or (self.is_person_noun(i) and not named_kin):
            return False  # "mum cooks": a name, then its verb, though "cooks" are people too
        after = s.w[i + 1] if i + 1 < s.n else None
        return after is None or after.pos in ("DET", "ADP", "ADV", "PUNCT") or s.low[i + 1] in lx.DETERMINERS or (
            after.pos in ("NOUN", "PRON", "ADJ", "NUM") and s.verbless(i))  # "a visitor sips coffee"

    def verb_after(self, k: int) -> bool:
        """Whether the word after k is a verb (so the word at k is the subject of a clause)."""
        s = self.s
        k = past_adverbs(s, k)  # "Mum quickly walks": the verb past the adverb
        if k + 1 >= s.n:
            return False
        nxt = s.low[k + 1]
        # the small model tags "cooks" in "Mum cooks in the kitchen" as a plural noun, but as the root
        known_verb = verb_lemma(nxt) in lx.INTENT_VERBS or verb_lemma(nxt) in lx.HUMAN_SUBJECT_VERBS
        return (s.w[k + 1].tag in ("VBZ", "VBP", "VBD") or s.w[k + 1].dep == "ROOT" or self.third_person_verb(k + 1)
                or (known_verb and (nxt != verb_lemma(nxt) or s.verbless(k)))  # "Mum and Dad nap"
                or nxt in ("is", "are", "was", "were") or subject_of_a_later_verb(s, k))

    def label(self, head: int | None) -> str:
        """The short label of the people a phrase names ("nurse", "au pair"); "person" for words that
        name nobody in particular ("people", "someone", "three of them")."""
        s = self.s
        if head is None:
            return "person"
        if (moved := person_of_a_thing(s.lemma(head))) is not None:
            return moved  # "three prams are pushed": three parents
        title = next((lx.TITLES[s.low[k].rstrip(".")] for k in range(max(0, head - 3), head)
                      if self.titled_name(k) == head), None)
        if title is not None:
            return title  # "Dr Jones": a doctor
        if head > 0 and s.low[head - 1] in CHILD_NAME_WORDS and s.w[head].tag == "NNP" and \
                s.lemma(head) not in lx.PERSON_NOUNS:
            return "child"  # "Little Tom": a child, by name
        noun = abbreviation_label(s, head) or (s.low[head] if one_name(s, head) else s.lemma(head))  # "two TAs": ta; "Agnes"
        if head >= 2 and s.low[head - 1] == "-" and modifier_end(s, head - 2) == head and s.w[head - 2].pos != "ADJ":
            return f"{s.low[head - 2]}-{noun}"  # "the co-pilot": another person than "the pilot"
        if noun not in lx.PERSON_NOUNS and len(s.low[head]) >= 6 and not known_word(s.low[head]):
            near = near_person_noun(s.low[head]) or noun  # "nurzes" -> nurse, but "posters" and "pickers" stay
            noun = noun if agent_of_a_verb(s.low[head], near) else near
        if self.multiword_end(head):
            return next(" ".join(p) for p in lx.MULTIWORD_PEOPLE if self._multiword_at(head - len(p) + 1, p))
        if noun in ("member", "person") and head > 0 and self.is_person_noun(head - 1):
            noun = s.lemma(head - 1)  # "staff members", "family members"
        if noun in lx.GENERIC_PEOPLE or noun in lx.NUMBER_WORDS or noun in lx.PRONOUN_PEOPLE:
            return "person"
        return noun

    def is_person_phrase(self, lemmas: Sequence[str]) -> bool:
        """Whether a place-role phrase names people, not a place ("to the nurses")."""
        content = [t for t in lemmas if t not in lx.PLACE_MODIFIERS]
        return bool(content) and (content[-1] in lx.PERSON_NOUNS or content[-1] in lx.PRONOUN_PEOPLE) and \
            not self.s.index.knows(content[-1])

