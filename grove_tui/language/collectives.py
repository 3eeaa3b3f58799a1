"""Pass 2, part 3: counted phrases and the collectives people are counted in ("ten patients", "a
family", "two families of three", "a queue of about thirty passengers", "groups of three or four",
"pairs of tourists", "a crowd of visitors"), with the count each gives (ranges in language/lexicon.py)."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.held_collectives import held_not_people
from grove_tui.language.count_alone import people_by_place
from grove_tui.language.plural_surnames import plural_surname
from grove_tui.language.counts import Quantifier, count_of, number_at, quantifier
from grove_tui.language.mention import Mention
from grove_tui.language.model import Count
from grove_tui.language.people import People
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma


class Collectives:
    def __init__(self, s: Sentence, people: People) -> None:
        self.s = s
        self.people = people

    def counted(self, at: int, q: Quantifier, found: list[Mention], exclusive: bool) -> Mention | None:
        """A phrase that starts with a count: "ten patients", "about 20 people", "two families of three"."""
        s = self.s
        after = q.end
        if after < s.n and s.low[after] == "of":
            after = s.skip(after + 1, {"the", "their", "our"})
        head = self.people.person_head(after, counted=True)
        if head is None:
            # "twenty people in the cafeteria and ten in the pharmacy": the number borrows the noun
            if not found and q.value > 0 and people_by_place(s, at, after):  # "all 9 in the lounge head to ..."
                return Mention(at, after - 1, s.span(at, after - 1), "person", count_of(s, q, f"{at}:count"))
            if (found and q.value > 0 and after < s.n and (s.low[after] in lx.PLACE_PREPOSITIONS
                                                           or verb_lemma(s.low[after]) in lx.INTENT_VERBS
                                                           or self._state_then_place(at, after))
                    and at > 0 and s.low[at - 1] not in ("at", "until", "till", "after", "before", "since")):
                return Mention(at, after - 1, s.span(at, after - 1), found[-1].label, count_of(s, q, f"{at}:ellipsis"))
            whole = next((k for k in range(len(found) - 1, -1, -1) if found[k].relation is None), None)
            if whole is not None and q.kind.startswith("vague") and after < s.n and at > 0 and (
                    s.is_punct(at - 1) or s.low[at - 1] in lx.CLAUSE_STARTERS) and (
                    s.is_verb(after) or verb_lemma(s.low[after]) in lx.INTENT_VERBS):
                # "twenty commuters wait; a few leave through the exit": a few of them
                return Mention(at, after - 1, s.span(at, after - 1), found[whole].label,
                               count_of(s, q, f"{at}:part"), relation=f"subset_of:{whole}")
            return None
        collective = self.collective(head, q, at)
        if collective is not None:
            return collective
        count = count_of(s, q, f"{at}:count")
        if exclusive:
            count = replace(count, kind="exclusive")
        return Mention(at, head, s.span(at, head), self.people.label(head), count, exclusive=exclusive)

    def _state_then_place(self, at: int, after: int) -> bool:
        """A state after a number set off by a comma, then a place: "3 lads by the board, 1 asleep on
        the benches", "two sitting on the wall": the number borrows the last group's noun."""
        s = self.s
        return (at > 0 and (s.is_punct(at - 1) or s.low[at - 1] == "and") and after + 1 < s.n
                and (s.w[after].pos == "ADJ" or s.w[after].tag in ("VBG", "VBN"))
                and s.low[after + 1] in lx.PLACE_PREPOSITIONS)

    def held(self, head: int) -> bool:
        """Whether the collective at `head` is a thing held ("with hired clubs"): language/held_collectives.py."""
        return held_not_people(self.s, head)

    def collective(self, head: int, number: Quantifier | None = None, first: int | None = None) -> Mention | None:
        """Mentions built on a collective noun: "a family", "two families of three", "a group of nurses"."""
        s = self.s
        if number is None and first is None and plural_surname(s, head):  # "the Smiths": one family, said by its name
            return Mention(head - 1, head, s.span(head - 1, head), "family",
                           self._collective_count("family", "family", None, 1, True, True, head), together=True,
                           collective="family")
        noun = s.lemma(head)
        if noun not in lx.IMPLIED_RANGES or (self.people.multiword_end(head) and noun not in lx.MULTIWORD_COLLECTIVES):
            return None  # "the au pair" is no pair; "the cabin crew" is a crew
        if held_not_people(s, head):
            return None  # "with hired clubs", "carry their clubs": things held
        if noun in lx.MULTIWORD_COLLECTIVES and (number is not None and s.low[head] == noun or (
                head + 1 < s.n and s.lemma(head + 1) == "member")):
            return None  # "three cabin crew", "2 crew", "a crew member": its members counted
        low = s.low
        at = first if first is not None else head
        while at > 0 and first is None and (low[at - 1] in ("a", "an", "the") or low[at - 1] in lx.NP_MODIFIERS
                                            or (s.w[at - 1].pos in ("ADJ", "NOUN") and at > 1 and s.w[at - 2].pos == "DET"
                                                and (s.w[at - 1].pos == "ADJ" or s.w[at - 1].dep == "compound"))):
            at -= 1  # "a long queue of ...", "a school class": the modifier is the collective's
        if noun in lx.MODIFYING_COLLECTIVES and head + 1 < s.n and s.lemma(head + 1) in lx.IMPLIED_RANGES \
                and s.lemma(head + 1) not in lx.MODIFYING_COLLECTIVES | lx.INTENT_VERBS.keys() \
                and s.w[head + 1].pos in ("NOUN", "PROPN"):  # "a family queues": the verb, however tagged
            head += 1  # "a tour group", "a family party": one group, as big as the first word says
        plural = s.low[head] != s.lemma(head)
        parties, exact_parties = 1, True
        if number is not None:
            if noun in lx.ONE_SET_PLURALS and number.kind == "exact" and number.value == lx.IMPLIED_RANGES[noun][0]:
                pass  # "both twins", "the two twins": the one pair (round 52), not two pairs
            elif number.kind in ("exact", "approximate") and number.value > 1:
                parties = number.value
            elif number.kind.startswith("vague") or number.kind == "range":
                parties, exact_parties = count_of(s, number, f"{head}:parties").value, False
        elif plural and first is None and noun not in lx.ONE_SET_PLURALS:
            # "groups of three or four", "pairs of tourists": several, however many is not said
            parties, exact_parties = s.choose(*lx.PLURAL_PARTIES_RANGE, f"{head}:groups"), False
        together = noun in lx.TOGETHER_COLLECTIVES
        size = number.value if number is not None and number.kind == "strong" else None  # "an 8-strong jury"
        last, label = head, self.people.label(head) if self.people.multiword_end(head) else noun
        loose: Quantifier | None = None
        if head + 2 < s.n and low[head + 1] == "of":
            loose = quantifier(s, head + 2)
            if loose is not None and loose.kind in ("approximate", "range") and parties == 1 and exact_parties:
                return self._loosely_counted(noun, at, head, loose, together)
            inner = number_at(s, head + 2)
            if loose is not None and loose.kind == "range" and loose.high is not None:
                # "groups of two or three": each party a size in the range
                size, inner = s.choose(loose.value, loose.high, f"{head}:party"), (loose.value, loose.end)
            if inner is not None:
                size = size or inner[0]
                last = inner[1] - 1
                member = self.people.person_head(inner[1], counted=True)
                if member is not None and self._verb_after_count(member):
                    member = None  # "a queue of 12 forms at the desk": no one "forms"; the verb
                if member is not None and member <= inner[1] + 2:
                    last = member
                    if noun in ("group", "crowd", "bunch", "party", "team", "queue", "line", "class", "tour") or \
                            noun in lx.MEMBERS_NAME_COLLECTIVES | lx.QUANTIFYING_COLLECTIVES:
                        label = self.people.label(member)
            else:
                member = self.people.person_head(s.skip(head + 2, {"the", "their", "our"}), counted=False)
                if member is not None:
                    last = member
                    if noun in ("group", "crowd", "bunch", "party", "team", "class", "tour", "delegation", "gang",
                                "couple", "pair", "handful", "trio", "duo", "quartet", "foursome", "twosome") or \
                            noun in lx.MEMBERS_NAME_COLLECTIVES | lx.QUANTIFYING_COLLECTIVES:
                        label = self.people.label(member)
        if label == noun and head > 0 and self.people.is_person_noun(head - 1) and self.people.collective_after(head - 1):
            at = min(at, head - 1)
            while at > 0 and (low[at - 1] in ("a", "an", "the", "their", "our", "his", "her") or low[at - 1] in lx.NP_MODIFIERS):
                at -= 1
            label = self.people.label(head - 1)  # "the security team": security staff, as many as a team
        count = self._collective_count(noun, label, size, parties, exact_parties, together, head)
        if not exact_parties and count.parties:
            # the number of parties is a seeded guess: the range runs over every number it could be
            low_size, high_size = (loose.value, loose.high) if loose is not None and loose.kind == "range" and \
                loose.high is not None else (count.low // max(1, count.parties), count.high // max(1, count.parties))
            parties_range = lx.PLURAL_PARTIES_RANGE if number is None else (count_of(s, number, "").low,
                                                                            count_of(s, number, "").high)
            count = replace(count, low=parties_range[0] * low_size, high=parties_range[1] * high_size)
        return Mention(at, last, s.span(at, last), label, count, together=together, collective=noun)

    def _verb_after_count(self, k: int) -> bool:
        """Whether a plural word no list names, right after "a queue of 12", is the sentence's verb:
        the parser found no verb in the sentence, or a particle follows ("a film crew of four sets up")."""
        s = self.s
        if k < 1 or s.w[k - 1].pos != "NUM" or self.people.is_person_noun(k) or not s.low[k].endswith("s"):
            return False
        if k + 1 < s.n and s.w[k + 1].pos in ("NOUN", "VERB", "AUX"):
            return False  # "a group of 6 zombies shambles": the next word is the verb
        word = s.low[k]
        verb = verb_lemma(word) != word or word[:-1] in lx.GATHERING_VERBS or word[:-2] in lx.GATHERING_VERBS
        return verb and (s.verbless(k) or (k + 1 < s.n and s.w[k + 1].tag == "RP"))

    def _loosely_counted(self, noun: str, at: int, head: int, loose: Quantifier, together: bool) -> Mention:
        """"a queue of about thirty passengers", "a crowd of 80 to 100 fans": the people inside the
        collective, counted loosely."""
        s = self.s
        member = self.people.person_head(loose.end, counted=True)
        if member is not None and self._verb_after_count(member):
            member = None  # "a queue of about 8 forms at ..."
        last = member if member is not None and member <= loose.end + 2 else loose.end - 1
        label = noun
        if member is not None and (noun not in lx.TOGETHER_COLLECTIVES | lx.QUEUE_COLLECTIVES or
                                   noun in ("group", "crowd", "bunch", "party", "team", "queue", "line")):
            label = self.people.label(member)
        return Mention(at, last, s.span(at, last), label, count_of(s, loose, f"{head}:inside"), together=together,
                       collective=noun)

    def _collective_count(self, noun: str, label: str, size: int | None, parties: int, exact_parties: bool,
                          together: bool, head: int) -> Count:
        s = self.s
        if size is None and noun in lx.QUANTIFYING_COLLECTIVES and label != noun:
            # "a crowd of visitors": the collective only says how many, vaguely
            low_, high_ = lx.IMPLIED_RANGES[noun]
            return Count("vague", s.choose(low_, high_, f"{head}:{noun}"), low_, high_)
        if size is None:
            low_, high_ = lx.IMPLIED_RANGES[noun]
            party = s.choose(low_, high_, f"{head}:{noun}")
            if parties == 1 and noun in lx.VEHICLE_LOADS and label != noun:
                # "a coachload of cyclists": as many as a coach holds, a number nobody said
                return Count("vague", party, low_, high_, *((1, party) if together else (None, None)))
            if parties == 1:
                return Count("implied", party, low_, high_, *((1, party) if together else (None, None)))
            return Count("structured", parties * party, parties * low_, parties * high_, parties, party)
        if parties == 1 and exact_parties:
            return Count("exact", size, size, size, 1, size)
        value = parties * size
        return Count("structured", value, value, value, parties, size)


def members_named(before: Mention) -> bool:
    """Whether a mention is a collective said with no count of its own ("the school party", "the 2 pm
    tour", "the night shift"), whose members a count set off by commas may name ("the school party, 25 children, ...")."""
    return (before.collective is not None and before.count is not None and before.count.kind == "implied"
            and (before.label == before.collective or before.label.endswith(" " + before.collective)))  # "the night shift"
