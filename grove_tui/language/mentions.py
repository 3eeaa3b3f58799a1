"""Pass 2, part 2: the mentions of people, each with its count.

A group of people starts at a person phrase in subject position: at the start of a sentence or
clause ("..., while", "and", "as", "then", "except"), after "there are" or an imperative scene verb
("Simulate ten nurses"), or where the parser finds the subject ("At six the staff head out"). Its
count is read from the phrase: a number, approximate ("about twenty"), vague ("a few"), implied by a
collective ("a family" 3-4), structured ("two families of three"), whole-zone ("everyone in the
cafeteria", settled once places are known) or exclusive ("nobody ... except one guard").
Relations: "one of them" is part of the group before (subset_of), "the others" are other people
than that group (others_of; after a subset, the rest of its parent), "a few more" adds to it
(more_of). Counted phrases and collectives are read in collectives.py.
"""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.another_count import more_people, the_other_count
from grove_tui.language.apposed_counts import apposed_collective, collective_is_a_verb
from grove_tui.language.occasion_headings import without_heading
from grove_tui.language.count_tails import a_total, after_apposed_count
from grove_tui.language.collectives import Collectives, members_named
from grove_tui.language.couple_words import bare_couple
from grove_tui.language.cue_in_names import compound_place_refused, person_word_in_a_place_name
from grove_tui.language.counts import Quantifier, count_of, negative_at, number_at, quantifier
from grove_tui.language.events import after_a_clock_time, cause_of_a_clearing, event_after_time_word
from grove_tui.language.family_members import with_members
from grove_tui.language.family_surnames import members_said, surname_family
from grove_tui.language.mention import Mention
from grove_tui.language.one_name import one_name
from grove_tui.language.model import Count
from grove_tui.language.objects import PeopleObjects, nobody_after_subordinator
from grove_tui.language.only_people import only_people_before, the_only_mention
from grove_tui.language.passive_doers import participle
from grove_tui.language.partitives import Partitives, other_half, verb_of_a_bare_count, whole_of_a_bare_part
from grove_tui.language.people import People
from grove_tui.language.people_phrases import companions, coordinated_person, whole_zone_pronoun
from grove_tui.language.place_phrases import Place, PlacePhrases
from grove_tui.language.role_words import family_member, family_size, person_of_a_person, possessor_of_a_person
from grove_tui.language.sentence import Sentence
from grove_tui.language.school_classes import named_class
from grove_tui.language.taken_mentions import taken_mention
from grove_tui.language.tokens import phrase_lemmas, verb_lemma

_POSSESSIVES = ("their", "his", "her", "our", "my")
# A phrase of time before a clause's subject ("every few minutes a passenger ...", "now and then").
_WHEN_WORDS = frozenset("every often occasionally sometimes now then suddenly later soon eventually finally "
                        "meanwhile once regularly periodically".split())
_TIME_WORDS = _WHEN_WORDS | frozenset("few so and in a while from time to couple of".split())
# Words after a number that keep it a count ("twenty or so", "twenty-odd", "forty-plus").
_COUNT_TAILS = frozenset("- or so odd more plus ish +".split())


class Mentions:
    """Finds the mentions of people of one sentence, in order."""

    def __init__(self, s: Sentence, people: People, places: PlacePhrases) -> None:
        self.s = s
        self.people = people
        self.places = places
        self.collectives = Collectives(s, people)
        self.partitives = Partitives(s, people)
        self.objects = PeopleObjects(s, people)
        self.problems: list[str] = []  # counts no scenario can have ("-5 people", "zero nurses")

    def find(self) -> list[Mention]:
        s = self.s
        found: list[Mention] = []
        fronted: int | None = None  # a whole said before its part ("Of the twelve nurses on the ward, two ...")
        i = 0
        while i < s.n:
            whole = self.partitives.fronted_whole(i) if fronted is None else None
            if whole is not None:
                fronted = len(found)
                found.append(whole)
                i = whole.last + 1
                continue
            if negative_at(s, i):
                end = next((k for k in range(i + 1, min(i + 5, s.n)) if self.people.is_person_noun(k)), i)
                self.problems.append(f"'{s.span(i, end)}' is a negative number of people; give a whole number of "
                                     f"at least 1")
            if i in s.together_phrases or not self.subject_position(i):
                i += 1
                continue
            m = self.mention_at(i, found)
            if m is not None and m.count is not None and m.count.kind == "exact" and m.first == i:
                m = self._approximated(m, found)
            if fronted is not None and (m is None or collective_is_a_verb(s, m)):
                m = self._bare_count(i, found[fronted])
            if m is not None and m.collective is not None and m.first == m.last and 0 < m.first and \
                    s.low[m.first - 1] == "-" and m.last + 1 < s.n and s.w[m.last + 1].pos in ("NOUN", "PROPN") and \
                    not self.people.third_person_verb(m.last + 1):
                m = None  # "the first-class lounge", "a first-team pitch": a collective inside a compound modifier
            if m is not None and found and collective_is_a_verb(s, m):
                m = None  # "4-5 kids w/ notebooks crowd round the t-rex", "..., 24 pupils, troop from": their verb
            if m is None:
                i += 1
                continue
            if found and self._members_of_collective(found[-1], m):
                # "the robot leads a tour ..., with about twelve tourists trailing behind it": the tour's people
                before = found[-1]
                before.count, before.label, before.apposition = *with_members(before, m), (m.first, m.last)
                i = m.last + 1
                continue
            if found and not found[-1].fronted and self._apposition(found[-1], m, len(found) - 1):
                # "All the diners in the canteen, some thirty of them, leave": how many the group before is
                count = m.count
                assert count is not None
                members = members_named(found[-1]) or surname_family(s, found[-1])  # "The school party, 25 children, ...": who the party is
                found[-1].count, found[-1].whole_zone, found[-1].apposition = count, False, (m.first, m.last)
                if found[-1].label == "person" or members:
                    found[-1].label = m.label
                i = m.last + 1
                continue
            found[:] = without_heading(s, found, m)  # "kids bday: 9 on the wall": the heading's kids are the 9
            if m.count is not None and m.count.value == 0 and m.count.kind == "exact":
                self.problems.append(f"'{m.who}' asks for nobody; give a number of people of at least 1 "
                                     f"(or leave that group out)")
            if found and found[-1].whole_zone and found[-1].relation is None and m.relation is None and \
                    self.after_except(m.first):
                m.exception_of = len(found) - 1  # "everyone in the hall leaves except two guards"
            m.robot_object = self.objects.robot_object(m.first)
            if m.zone_place is None and not m.whole_zone:
                m.zone_place = self.possessor_place(m.first)
            if fronted is not None and m.relation is None and m.whole is None and m.count is not None and \
                    m.label in ("person", found[fronted].label) and s.w[m.first].sentence == s.w[found[fronted].first].sentence:
                self.partitives.fronted_part(m, found[fronted], fronted)
            fronted = None
            if m.whole is not None:
                # "two of the six developers": the six first, the two a subset of them
                found.append(m.whole)
                m.relation = f"subset_of:{len(found) - 1}"
            found.append(m)
            i = m.last + 1
        return found

    def _approximated(self, m: Mention, found: list[Mention]) -> Mention:
        """The mention with the approximation said right before its number ("By nine about thirty
        developers", "at noon roughly 60 commuters"), when the phrase was found at the number, or said after
        it ("twenty developers, give or take,")."""
        s = self.s
        for j in range(m.first - 1, max(-1, m.first - 5), -1):
            if s.is_punct(j):
                break
            q = quantifier(s, j)
            if q is not None and q.kind == "approximate" and number_at(s, j) is None and \
                    any(number_at(s, k) is not None and k == m.first for k in range(j + 1, q.end)):
                wider = self.mention_at(j, found)
                if wider is not None and wider.last == m.last and wider.count is not None:
                    return wider
        after = tuple(s.low[m.last + 1:m.last + 5])
        count = m.count
        if count is not None and count.kind == "exact" and count.value > 1 and (
                after == (",", "give", "or", "take") or after[:3] in ((",", "or", "thereabouts"), ("give", "or", "take"))):
            spread = max(1, round(count.value * lx.APPROXIMATE_SPREAD))  # "twenty developers, give or take,"
            m.count = Count("approximate", count.value, count.value - spread, count.value + spread)
        return m

    def _bare_count(self, at: int, whole: Mention) -> Mention | None:
        """A bare count right after a whole said first, before any verb ("..., three get up and ...")."""
        s = self.s
        num = quantifier(s, at)
        if num is None or at == 0 or s.low[at - 1] != "," or num.end >= s.n or not verb_of_a_bare_count(s, num.end):
            return None
        return Mention(at, num.end - 1, s.span(at, num.end - 1), whole.label, count_of(s, num, f"{at}:part"))

    def _members_of_collective(self, before: Mention, m: Mention) -> bool:
        """Whether m, after "with" in the same sentence, counts the people of a collective said with no number and
        no kind of people ("leads a tour ..., with about twelve tourists trailing behind it", "a group ... with ten in tow")."""
        s = self.s
        return (m.first > 0 and s.low[m.first - 1] == "with" and before.collective is not None
                and before.label == before.collective and before.count is not None
                and before.count.kind == "implied" and m.count is not None and m.count.value > 1 and m.relation is None
                and m.collective is None and s.w[before.first].sentence == s.w[m.first].sentence)

    def _apposition(self, before: Mention, m: Mention, index: int) -> bool:
        """Whether m only says how many the mention before is, set off by commas ("the party, 25 children, ...")."""
        s = self.s
        if apposed_collective(s, before, m):
            return True  # "toddlers in ski suits, a gaggle of them, waddle": how many, said by a collective
        if m.first < 2 or s.low[m.first - 1] != "," or m.count is None or m.count.kind not in ("exact", "approximate"):
            return False
        if (m.last + 1 >= s.n or s.low[m.last + 1] in (".", "!", ";")) and m.relation == f"subset_of:{index}" and \
                before.count is not None and before.count.kind in ("vague", "implied") and not before.whole_zone:
            return True  # "Travellers queue at security, maybe forty of them.": how many, said last
        if m.last + 1 >= s.n:
            return False
        if m.relation not in (None, f"subset_of:{index}") or \
                m.label not in ("person", before.label) and not (before.whole_zone and before.label == "person") \
                and not members_named(before) and not members_said(s, before) and not a_total(s, m.last + 1):
            return False  # but "everyone on the balcony, three friends, ...": how many, and who
        if before.count is not None and before.count.kind not in ("vague", "implied") and not before.whole_zone:
            return False  # "Ten nurses, two of them students, ...": part of a group said in full
        between = range(before.last + 1, m.first - 1)
        if any(s.w[x].pos in ("VERB", "AUX") or s.low[x] in (",", ";", ":") for x in between):
            return False
        after = after_apposed_count(s, m.last + 1)  # "six in all, ...", "eleven lads in matching T-shirts, ..."
        if after >= s.n:
            return False
        return s.low[after] == "," or s.w[after].pos in ("VERB", "AUX") or self.people.third_person_verb(after)

    # ---- where a group can start -------------------------------------------------------------

    def subject_position(self, at: int) -> bool:
        s = self.s
        if at == 0:
            return True
        p = at - 1
        prev = s.low[p]
        if s.is_punct(p) or s.w[p].sentence != s.w[at].sentence:
            return True
        if event_after_time_word(s, p, at) or cause_of_a_clearing(s, p, at) or self.people.describing_a_place(at):
            return False  # "After the night shift, ...", "at the end of the class": a time, no people
        if prev == "with" and self._conversation_partner(p, at):
            return False
        if prev == "with" and s.low[at] in ("their", "his", "her", "its", "our", "my") and not companions(s, self.people, p):
            return False  # "families wait at the gate with their children": the families' own members
        if prev in lx.CLAUSE_STARTERS | lx.EXCEPT_WORDS | {"than"} and not compound_place_refused(s, at) or (s.low[p - 1], prev) == (",", "where"):
            return True
        if person_word_in_a_place_name(s, at):
            return False  # "the robot ferries soup from the kitchen diner to ...": a room, no diner
        if self.objects.led_by(at) or self.objects.robot_object(at) is not None or self.objects.followed(at) or \
                self.objects.sent_by(at):
            return True  # "a tour guide leads twelve tourists": a counted group the subject takes along
        if prev == "instead" and s.low[at] != "of":
            return True  # "nobody waits there; instead eight patients queue ..."
        if prev == "for" and p > 0 and s.low[p - 1] in lx.EXCEPT_WORDS:
            return True  # "empty except for two cleaners"
        if prev == "from" and p > 0 and s.low[p - 1] == "apart":
            return True  # "apart from one guard"
        if prev == "by" and p > 0 and s.low[p - 1] in ("followed", "trailed", "accompanied", "joined"):
            return True  # "the manager walks to the boardroom, followed by two assistants"
        if prev in ("are", "is") and self._only_people_before(p):
            return True  # "the only people in the ward are two men"
        if prev in ("are", "is", "were", "was", "be", "'s", "’s", "'re", "’re") and p > 0 and s.low[p - 1] == "there":
            return True
        if verb_lemma(prev) in lx.SCENE_VERBS and (p == 0 or s.is_punct(p - 1) or s.low[p - 1] in
                                                   lx.CLAUSE_STARTERS | {"please", "to", "let's", "lets"}):
            return True
        if prev == "by" and s.w[p].dep == "agent" and participle(s, s.w[p].head):
            return True  # "the balcony is used by a smoker": the passive's doer (not "hover by the concierge")
        if verb_lemma(prev) == "have" and self._place_before(p):
            return True  # "the pharmacy has a queue of eleven people", "ward B has two visitors"
        if prev == "of" and self._event_before(p):
            return True  # "the boardroom meeting of twelve people breaks up"
        if prev in ("'s", "’s") and (self.possessor_place(at) is not None or family_member(s, at) or person_of_a_person(s, self.people, at)):
            return True  # "ward A's patients", "the café's 8 customers": the people of a place; "the bride's youngest"
        if self._after_time_phrase(at) or after_a_clock_time(s, at):
            return True  # "..., and every so often a lost visitor wanders over"
        return self._parser_subject(at)

    def _after_time_phrase(self, at: int) -> bool:
        """Whether only a phrase of time stands between the start of a clause and `at` ("and every
        few minutes", "and now and then", "then suddenly"), so a subject may start there."""
        s = self.s
        j = at - 1
        timed = False
        while j >= 0 and not s.is_punct(j) and (s.low[j] in _TIME_WORDS or s.lemma(j) in lx.DURATION_UNITS
                                                or s.w[j].pos in ("ADV", "NUM")):
            timed = timed or s.low[j] in _WHEN_WORDS or s.lemma(j) in lx.DURATION_UNITS
            if s.low[j] in lx.CLAUSE_STARTERS and s.low[j] not in _WHEN_WORDS:
                break
            j -= 1
        return timed and j < at - 1 and (j < 0 or s.is_punct(j) or s.low[j] in lx.CLAUSE_STARTERS) and \
            s.low[at] in lx.DETERMINERS | {"someone", "somebody"}

    def possessor_place(self, at: int) -> Place | None:
        """The zone whose people the mention at `at` is ("ward A's patients": ward_a), or None."""
        s = self.s
        p = at - 1
        if p < 1 or s.low[p] not in ("'s", "’s"):
            return None
        k = p
        while k > 0 and not s.is_punct(k - 1) and s.low[k - 1] not in lx.CLAUSE_STARTERS and p - k < 4:
            k -= 1
        k = s.skip(k, lx.DETERMINERS)
        words = tuple(s.low[k:p])
        if not words or any(self.people.is_person_noun(x) for x in range(k, p)):
            return None
        match = s.index.match(phrase_lemmas(list(words)))
        if match is None or match.kind != "zone" or not match.exact:
            return None
        return Place("in", k, words, match, p)

    def _place_before(self, p: int) -> bool:
        """Whether the words of p's clause before it name a place and no person ("the café has")."""
        s = self.s
        k = p - 1
        words: list[int] = []
        while k >= 0 and not s.is_punct(k) and s.low[k] not in lx.CLAUSE_STARTERS and s.w[k].sentence == s.w[p].sentence:
            words.append(k)
            k -= 1
        return bool(words) and not any(self.people.is_person_noun(x) for x in words) and \
            any(s.index.knows(s.lemma(x)) for x in words)

    def _parser_subject(self, at: int) -> bool:
        """Whether the phrase at `at` is the subject the parser found ("At six the staff head out"):
        determiners, numbers and adjectives, then a person noun the parser calls the subject."""
        s = self.s
        if at > 0 and s.w[at - 1].pos in ("DET", "ADJ", "NUM") and not (
                s.w[at - 1].pos == "NUM" and s.w[at - 1].head < at - 1 and s.low[at] in lx.DETERMINERS | lx.APPROXIMATE_WORDS):
            return False  # inside a noun phrase that starts earlier ("the only people"); not "At 8:15 the ..."
        if at > 0 and nobody_after_subordinator(s, at):
            return False  # "... until someone collects them", "if anyone asks": nobody who is there
        q = quantifier(s, at)
        begin = at
        if q is not None and q.kind == "approximate" and number_at(s, at) is None:
            # "At rush hour about 200 commuters ...": the approximation first, its number and noun after
            begin = next((k for k in range(at + 1, q.end) if number_at(s, k) is not None), at)
        number = number_at(s, begin)
        count_end = number[1] if number is not None else begin  # "a dozen", "half a dozen": words of the count
        for k in range(begin, min(begin + 5, s.n)):
            if s.low[k] in lx.NOBODY_WORDS:
                return False
            if k < count_end or (k >= count_end > begin and s.low[k] in _COUNT_TAILS):
                continue  # "a dozen", "twenty or so", "twenty-odd": words of the count
            if self.people.is_person_noun(k):
                head = s.w[k].head
                # the small model may tag the verb a noun ("the commuters on platform 1 walk to ...")
                verb_noun = head > k and verb_lemma(s.low[head]) in lx.INTENT_VERBS and not s.index.knows(s.lemma(head))
                plural = s.lemma(k) != s.low[k] or count_end > begin  # "fifteen staff queue"
                if s.w[k].dep == "compound" and head == k + 1 and plural and \
                        s.lemma(head) == s.low[head] and verb_lemma(s.low[head]) in lx.INTENT_VERBS and (
                            not s.index.knows(s.lemma(head)) or head + 1 == s.n or s.is_punct(head + 1)
                            or s.low[head + 1] in lx.PLACE_PREPOSITIONS):
                    return True  # "After lunch twelve patients queue at ...": the verb tagged a noun they name
                return s.w[k].dep in ("nsubj", "nsubjpass") and (s.w[head].pos in ("VERB", "AUX") or verb_noun)
            if s.w[k].pos not in ("DET", "NUM", "ADJ") and s.low[k] not in lx.NP_MODIFIERS and not self.people.kind_word(k):
                return False
        return False

    def _event_before(self, of: int) -> bool:
        """Whether "of" closes a subject noun phrase of no people ("the boardroom meeting of ..."):
        nouns and adjectives back to a determiner at a subject position."""
        s = self.s
        k = of - 1
        if k < 0 or s.w[k].pos not in ("NOUN", "PROPN") or self.people.is_person_noun(k) or \
                s.lemma(k) in lx.IMPLIED_RANGES or number_at(s, k) is not None:
            return False
        while k > 0 and s.w[k - 1].pos in ("NOUN", "PROPN", "ADJ") and not s.is_punct(k - 1):
            k -= 1
        if k > 0 and s.low[k - 1] in ("the", "a", "an", "this", "that"):
            k -= 1
        return self.subject_position(k) if s.low[k - 1:k] != ["of"] else False

    def _conversation_partner(self, p: int, at: int) -> bool:
        """Whether the phrase at `at`, after "with" at p, is who a person talks or walks with, not a
        group of its own: one person with no number ("chats with the driver"); "with two friends"
        still names a group."""
        s = self.s
        if p < 1 or verb_lemma(s.low[p - 1]) not in lx.INTENT_VERBS | lx.ROBOT_VERBS.keys():
            return False
        k = s.skip(at, {"the", "a", "an", "his", "her", "their", "its", "my", "our", "your"})
        if k == at:
            return False
        while k < s.n and (s.w[k].pos == "ADJ" or s.low[k] in lx.NP_MODIFIERS) and not self.people.is_person_noun(k):
            k += 1
        if k + 1 < s.n and s.w[k].pos in ("NOUN", "PROPN") and self.people.is_person_noun(k + 1):
            k += 1  # "the train driver"
        return k < s.n and self.people.is_person_noun(k) and s.lemma(k) == s.low[k] and \
            s.lemma(k) not in lx.IMPLIED_RANGES

    def after_except(self, at: int) -> bool:
        """Whether the phrase at `at` follows a word of exception ("except", "apart from", "other than")."""
        low = self.s.low
        prev = low[at - 1] if at > 0 else ""
        before = low[at - 2] if at > 1 else ""
        return prev in lx.EXCEPT_WORDS - {"but"} or (prev, before) in (("from", "apart"), ("but", "everyone"), ("but", "everybody")) or \
            (prev == "than" and before == "other") or (prev == "for" and before in lx.EXCEPT_WORDS)

    def _only_people_before(self, p: int, other: bool = True) -> bool:  # "the only other person": one more, not all
        return only_people_before(self.s, self.people, p, other)  # "the only people/visitor in X are/is ..."

    def _exclusive_context(self, at: int) -> bool:
        """Whether the phrase at `at` is the exception to "nobody" in its sentence ("nobody ... except
        one guard", "apart from two pilots, nobody is ...", "the only people in X are two men")."""
        s = self.s
        sentence = s.w[at].sentence
        words = [k for k in range(s.n) if s.w[k].sentence == sentence]
        saw_nobody = any(s.low[k] in lx.NOBODY_WORDS or (s.low[k] == "no" and k + 1 < s.n and
                                                         s.low[k + 1] in ("one", "people", "person", "body"))
                         or s.low[k] in ("empty", "deserted") for k in words)
        near = [s.low[k] for k in words if k < at][-2:]
        if near[-1:] in (["are"], ["is"]) and self._only_people_before(at - 1, other=False):
            return True
        return saw_nobody and (any(x in lx.EXCEPT_WORDS for x in near) or near[-1:] == ["than"]
                               or near == ["apart", "from"])

    @staticmethod
    def parent(found: list[Mention], *, plain: bool = False) -> int | None:
        """The group a relation refers to: the last one that is not itself a subset ("one of them"),
        or with `plain` the last one with no relation at all ("the others", "a few more")."""
        for k in range(len(found) - 1, -1, -1):
            relation = found[k].relation or ""
            if not relation.startswith("subset_of") and not (plain and relation):
                return k
        return None

    # ---- one mention -------------------------------------------------------------------------

    def mention_at(self, at: int, found: list[Mention]) -> Mention | None:
        s = self.s
        low = s.low
        if low[at] in ("the", "these", "those", "all", "its", "their", "our", "his", "her", "my", "your") and \
                at + 1 < s.n and number_at(s, at + 1) is not None:
            inner = self.mention_at(at + 1, found)  # "the four people in the living room"
            if inner is not None:
                inner.first = at
                inner.who = s.span(at, inner.last)
            return inner
        carried = self.objects.carried_owner(at) if self.objects.led_by(at) else None
        if carried is not None:  # "pushes his father's wheelchair": the father, taken along
            person, thing = carried
            plural = s.lemma(person) != low[person] or low[person + 1] in ("'", "s'")
            return Mention(at, thing, s.span(at, thing), self.people.label(person),
                           Count("vague", s.choose(2, 3, f"{at}:carried"), 2, 3) if plural else Count("exact", 1, 1, 1))
        if (moved := taken_mention(s, at, self.objects)) is not None:  # "Mr Ahmed's son wheels him ...", "Mr and Mrs Obi"
            return moved
        num = quantifier(s, at)
        part = self.partitives.part_of(at, num, found, self.parent(found))
        if part is not None:
            return part
        rest = self._rest_of(at, num, found)
        if rest is not None:
            return rest
        if low[at] == "the" and at + 1 < s.n and low[at + 1] == "only":
            return the_only_mention(s, self.people, at)  # "the only people in the ward are two men": the men
        whole = self._whole_zone(at, num)
        if whole is not None:
            return whole
        if low[at] in ("everyone", "everybody", "all", "half", "every") and not (num and num.value > 0):
            return None
        exclusive = self._exclusive_context(at)
        if low[at] in ("someone", "somebody", "anyone", "anybody"):
            return Mention(at, at, s.w[at].text, "person", Count("exclusive" if exclusive else "exact", 1, 1, 1),
                           exclusive=exclusive)
        if low[at] == "another" or the_other_count(s, at):  # "another 5", "the other 6": more of them
            return self._another(at, found)
        if num is not None:
            return self._counted_or_more(at, num, found, exclusive)
        return self._bare(at, found, exclusive)

    def _rest_of(self, at: int, num: Quantifier | None, found: list[Mention]) -> Mention | None:
        """"the others", "the rest", "everyone else": other people than the group before."""
        s = self.s
        low = s.low
        half = other_half(s, at)  # "the other half": the rest of a group half of which was named
        j = half if half is not None else s.skip(at, {"the"})
        if j < s.n and (low[j] in ("others", "rest") or j == half) and (j == at or low[at] == "the"):
            last = j + 2 if j + 2 < s.n and low[j + 1] == "of" and low[j + 2] in ("them", "us", "the") else j
            last = (self.people.person_head(last + 1, counted=False) or last) if low[last] == "the" else last  # "of the class"
            parent = self.parent(found, plain=True)
            label = found[parent].label if parent is not None else "person"
            whole = whole_of_a_bare_part(s, found, parent) if low[at] == "the" else None  # "ten ...; the others"
            parent = parent if whole is None else whole
            if low[at] == "the" and parent is not None and any(m.relation == f"subset_of:{parent}" for m in found):
                return Mention(at, last, s.span(at, last), label, None, relation=f"others_of:{parent}",
                               rest_of_parent=True)
            low_, high_ = lx.OTHERS_RANGE
            count = Count("vague", s.choose(low_, high_, f"{at}:others"), low_, high_)
            return Mention(at, last, s.span(at, last), label, count,
                           relation=f"others_of:{parent}" if parent is not None else None)
        if low[at] in ("everyone", "everybody") and at + 1 < s.n and low[at + 1] == "else":
            parent = self.parent(found)
            parent = next((w for w in [whole_of_a_bare_part(s, found, parent)] if w is not None), parent)
            label = found[parent].label if parent is not None else "person"
            return Mention(at, at + 1, s.span(at, at + 1), label, None,
                           relation=f"others_of:{parent}" if parent is not None else None, rest_of_parent=True)
        return None

    def _whole_zone(self, at: int, num: Quantifier | None) -> Mention | None:
        """"everyone", "all the patients", "every visitor in the lounge", "half the open office":
        everyone in a zone (the zone settled once places are read)."""
        s = self.s
        low = s.low
        if low[at] in ("every", "each") and at + 1 < s.n:
            head = self.people.person_head(at + 1, counted=False)
            if head is not None:  # "every visitor in the lounge": everyone there
                return Mention(at, head, s.span(at, head), self.people.label(head), None, whole_zone=True)
        if low[at] == "half" and at + 1 < s.n:
            half = self._half_of(at)
            if half is not None:
                return half
        if not (whole_zone_pronoun(s, at) or (low[at] == "all" and not (num and num.value > 0))):
            return None
        last, label = at, "person"
        if low[at] == "all":
            k = s.skip(at + 1, {"the", "of"})
            n_after = number_at(s, k)
            if n_after is not None:  # "all ten patients": a plain count
                head = self.people.person_head(n_after[1], counted=True)
                if head is not None:
                    return Mention(at, head, s.span(at, head), self.people.label(head),
                                   Count("exact", n_after[0], n_after[0], n_after[0]))
            head = self.people.person_head(k, counted=False)
            if head is None:
                return None
            last, label = head, self.people.label(head)
        return Mention(at, last, s.span(at, last), label, None, whole_zone=True)

    def _half_of(self, at: int) -> Mention | None:
        """"half the open office", "half of the patients in the lobby": half of everyone in a zone
        (the zone named right there, or by the clause)."""
        s = self.s
        k = s.skip(at + 1, {"of"})
        k = s.skip(k, {"the", "all"})
        if k == at + 1 or k >= s.n:
            return None  # "half an hour", "half a dozen" are read elsewhere
        head = self.people.person_head(k, counted=False)
        if head is not None:
            return Mention(at, head, s.span(at, head), self.people.label(head), None, whole_zone=True, fraction=0.5)
        place = self.places.phrase(k, "in", at, record_unknown=False)
        if place is None or place.match is None or place.match.kind != "zone":
            return None
        return Mention(at, place.end - 1, s.span(at, place.end - 1), "person", None, whole_zone=True,
                       fraction=0.5, zone_place=place)

    def _another(self, at: int, found: list[Mention]) -> Mention:
        """"another nurse", "another group": one more, or a group's size more."""
        s = self.s
        head, last, count = more_people(s, self.people, at)  # "another nurse", "another 5"
        parent = self.parent(found, plain=True)
        relation = f"more_of:{parent}" if parent is not None else None
        if head is not None and s.lemma(head) in lx.IMPLIED_RANGES:
            collective = self.collectives.collective(head, None, at)  # "another group": a group's size, not one
            if collective is not None:
                collective.relation = relation
                return collective
        label = self.people.label(head) if head is not None else (found[parent].label if parent is not None
                                                                  else "person")
        return Mention(at, last, s.span(at, last), label, count, relation=relation)

    def _counted_or_more(self, at: int, num: Quantifier, found: list[Mention], exclusive: bool) -> Mention | None:
        """"a few more", "two more patients", "a few others", or a plain counted phrase."""
        s = self.s
        low = s.low
        after = num.end
        if after < s.n and low[after] == "more":
            parent = self.parent(found, plain=True)
            head = self.people.person_head(after + 1, counted=True)
            last = head if head is not None else after
            label = self.people.label(head) if head is not None else (found[parent].label if parent is not None
                                                                      else "person")
            return Mention(at, last, s.span(at, last), label, count_of(s, num, f"{at}:more"),
                           relation=f"more_of:{parent}" if parent is not None else None)
        if after < s.n and low[after] in ("others", "other"):
            parent = self.parent(found, plain=True)
            head = self.people.person_head(after + 1, counted=False) if low[after] == "other" else None
            if low[after] == "other" and head is None:
                return None
            last = head if head is not None else after
            label = self.people.label(head) if head is not None else (found[parent].label if parent is not None
                                                                      else "person")
            return Mention(at, last, s.span(at, last), label, count_of(s, num, f"{at}:others", lx.OTHERS_RANGE),
                           relation=f"others_of:{parent}" if parent is not None else None)
        return self.collectives.counted(at, num, found, exclusive)

    def _bare(self, at: int, found: list[Mention], exclusive: bool) -> Mention | None:
        """Phrases with no count: "visitors", "the nurses", "a nurse", "other visitors", "people"."""
        s = self.s
        low = s.low
        k = s.skip(at, {"the", "a", "an", "other", "their", "his", "her", "our", "its"})
        det = low[at] if k > at else ""
        other = "other" in low[at:k]
        head, named = self.people.person_head(k, counted=False), named_class(s, k)  # "Year 4 walks", "the Year 4 form"
        if head is None or (named is not None and head == named.last):
            return named  # or none: "ten in the pharmacy" borrows the last noun
        if possessor_of_a_person(s, self.people.is_person_noun, head):
            return None  # "Dr Patel's registrar", "the party host's mother": the person after "'s", the owner nobody
        if self.people.titled_name(k) == head:  # "Dr Jones", "Mr Li's wheelchair": one person
            return Mention(at, head, s.span(at, head), self.people.label(head),
                           Count("exclusive" if exclusive else "exact", 1, 1, 1), exclusive=exclusive)
        singular = (s.lemma(head) == low[head] or one_name(s, head)) and not self.people.plural_word(head)  # "Gladys"
        label = self.people.label(head)
        if det == "the" and any(m.label == label or s.lemma(head) == m.label != label.split("-")[-1] for m in found):
            return None  # "... one person; the person wanders around": the same people again
        noun = s.lemma(head)
        collective = self.collectives.collective(head)
        if collective is not None or self.collectives.held(head):  # "with hired clubs": things held, no one
            return collective
        if det in ("a", "an") or family_member(s, head) or (singular and (det == "the" or det in _POSSESSIVES and low[at - 1] == "and")):
            kind = "exclusive" if exclusive else "exact"
            return Mention(at, head, s.span(at, head), label, Count(kind, n := family_size(s, head), n, n), exclusive=exclusive)
        if singular and noun not in lx.GENERIC_PEOPLE and not other:
            if (self.people.verb_after(head) or self.after_except(at) or coordinated_person(self.s, self.people, head)
                    or self.objects.robot_object(at) is not None or self.objects.led_by(at) or self.objects.followed(at)
                    or self.objects.sent_by(at) or self.people.placed(head)) \
                    and noun not in lx.PRONOUN_PEOPLE \
                    and noun not in lx.NOBODY_WORDS:  # "everyone except grandma": the exception, named
                return Mention(at, head, s.span(at, head), label, Count("exclusive" if exclusive else "exact", 1, 1, 1),
                               exclusive=exclusive)  # "Mum cooks in the kitchen", "a carer helps grandpa": one person, by a role
            return None  # "staff" as a verb-less word, or a singular without determiner: not a subject
        low_, high_ = lx.OTHERS_RANGE if other else lx.BARE_PLURAL_RANGE
        parent = self.parent(found)
        relation = f"others_of:{parent}" if other and parent is not None else None
        if noun in lx.FAMILY_PLURALS and not other and (det == "the" or low[at] in _POSSESSIVES or bare_couple(s, at, noun)):
            low_, high_ = lx.FAMILY_PLURALS[noun]  # "the parents": the two of one family
            return Mention(at, head, s.span(at, head), label, Count(
                "implied", s.choose(low_, high_, f"{at}:family"), low_, high_), together=noun in lx.COUPLE_PLURALS)
        return Mention(at, head, s.span(at, head), label,
                       Count("vague", s.choose(low_, high_, f"{at}:bare"), low_, high_), relation=relation)
