"""Pass 2, part 4: people said as part of a group ("one of them", "two of the patients", "some of
them", "two of the six developers", "half of the 20 students", "one of the guards").

Part of a group said before is a subset of it (`subset_of`). Part of a group named only inside the
phrase ("two of the six developers at their desks follow it around") makes two mentions: the whole
group (six developers, who stay where the phrase puts them) and the part that does the clause's
verb, a subset of it, so the whole keeps only the rest (`model.effective_counts`). The whole may be
said first, before the part: "Of the thirty people watching the fountain, five wander off", "Out of
forty passengers on the platform, ten ...": the whole is what the words before the comma say they do,
and the first count after it is its part."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.apposed_counts import GROUP_VERBS
from grove_tui.language.collective_parts import collective_head, owned_whole, whole_unsaid
from grove_tui.language.counts import Quantifier, count_of, number_at, quantifier
from grove_tui.language.mention import Mention
from grove_tui.language.model import Count
from grove_tui.language.owner_partitives import named_owner_end
from grove_tui.language.lone_parts import lone_one_of
from grove_tui.language.owned_parts import owned_whole_unsaid
from grove_tui.language.people import People
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_GROUP_WORDS = ("the", "those", "these", "their", "our", "his", "her", "my")
# "half of the students", "a third of the passengers": the share of the group
_FRACTIONS = {("half",): 0.5, ("a", "third"): 1 / 3, ("a", "quarter"): 0.25, ("one", "third"): 1 / 3,
              ("one", "quarter"): 0.25, ("two", "thirds"): 2 / 3, ("three", "quarters"): 0.75}


class Partitives:
    def __init__(self, s: Sentence, people: People) -> None:
        self.s = s
        self.people = people

    def part_of(self, at: int, num: Quantifier | None, found: list[Mention],
                parent_index: int | None) -> Mention | None:
        """The part of a group the phrase at `at` names, or None; `parent_index` is the group a bare
        "of them" refers to. A subset of a group named only inside the phrase carries that group
        (`Mention.whole`), which the finder adds first."""
        s = self.s
        low = s.low
        bare = self._bare_share(at, found, parent_index)
        if bare is not None:
            return bare
        fraction, of_at = self._fraction(at)
        if fraction is None and low[at] in ("each", "most") and at + 1 < s.n and low[at + 1] == "of":
            fraction, of_at = (1.0 if low[at] == "each" else 0.75), at + 1  # "each of them": all of them
        elif fraction is None:
            if num is None:
                return None
            # "a few of" is read with its "of" by the quantifier; "two of" leaves it
            of_at = num.end if num.end < s.n and low[num.end] == "of" else (
                num.end - 1 if low[num.end - 1] == "of" else None)
        if of_at is None or of_at + 1 >= s.n:
            return None
        k = of_at + 1
        if low[k] in ("them", "us", "whom") or (low[k] in ("those", "these") and not self._noun_after(k + 1)):
            label = found[parent_index].label if parent_index is not None else s.lemma(k)
            count = self._share(found[parent_index].count if parent_index is not None else None, fraction) \
                if fraction is not None else count_of(s, num, f"{at}", lx.OTHERS_RANGE) if num is not None else None
            if count is not None and low[at] == "most":
                count = replace(count, kind="implied")  # "most of them": about three in four
            return Mention(at, k, s.span(at, k), label, count,
                           relation=f"subset_of:{parent_index}" if parent_index is not None else None)
        if low[k] not in _GROUP_WORDS:
            k = named_owner_end(s, k) or -1  # "both of Mrs Patel's granddaughters": her own, as "her"
            if k < 0:
                return None
        inner = quantifier(s, k + 1)
        start = inner.end if inner is not None and inner.kind == "exact" else k + 1
        head = self.people.person_head(start, counted=start > k + 1)
        if head is None:
            head = collective_head(s, start)  # "two of the cast walk off"
        if head is None:
            return None
        label = self.people.label(head)
        if low[at] == "most" and inner is not None and inner.kind == "exact" and fraction is not None:
            pass  # "most of the 20 students": a part of the twenty, about three in four
        elif low[at] in ("both", "each", "most"):
            # "both of the porters", "each of the nurses": the group itself, no part of it
            whole = self._whole(k, head, inner, label)
            count = Count("exact", 2, 2, 2) if low[at] == "both" else whole.count
            return Mention(at, head, s.span(at, head), label, count)
        elif at > 0 and low[at - 1] == "all" and num is not None and fraction is None and num.kind == "exact":
            # "all 7 of the sales reps", "all seven of the cleaners": the group itself, as many as said
            return Mention(at, head, s.span(at, head), label, count_of(s, num, f"{at}"))
        same = next((j for j in range(len(found) - 1, -1, -1) if found[j].label == label
                     and not (found[j].relation or "").startswith("subset_of")), None)
        if same is not None or (parent_index is not None and inner is None and label == "person"):
            # "Ten nurses ...; two of the nurses ...": the group said before
            parent = same if same is not None else parent_index
            assert parent is not None
            count = self._share(found[parent].count, fraction) if fraction is not None else \
                count_of(s, num, f"{at}", lx.OTHERS_RANGE) if num is not None else None
            return Mention(at, head, s.span(at, head), label, count, relation=f"subset_of:{parent}")
        if fraction is None and num is not None and (whole_unsaid(s, of_at, head, inner is not None)
                                                    or owned_whole(s, k, inner)
                                                    or owned_whole_unsaid(s, of_at, inner is not None)
                                                    or lone_one_of(s, at, num, fraction, inner)):
            return Mention(at, head, s.span(at, head), label, count_of(s, num, f"{at}", lx.OTHERS_RANGE))  # "two of the crew"
        if fraction is not None and (inner is None or inner.kind != "exact"):
            return None  # "half of the patients in the lobby": half of everyone there (a whole-zone share)
        whole = self._whole(k, head, inner, label)
        count = self._share(whole.count, fraction) if fraction is not None else \
            count_of(s, num, f"{at}", lx.OTHERS_RANGE) if num is not None else None
        if count is not None and whole.count is not None and whole.count.value <= count.value:
            # "five of the guards": more guards than the five
            more = count.value + 1
            whole.count = replace(whole.count, value=more, low=max(whole.count.low, more), high=max(whole.count.high, more))
        if count is not None and low[at] == "most":
            count = replace(count, kind="implied")
        return Mention(at, head, s.span(at, head), label, count, whole=whole)

    def fronted_whole(self, at: int) -> Mention | None:
        """The whole said before its part at a clause's start ("Of the 12 nurses on the ward, two go
        ...", "Out of forty passengers, ten ..."), when a comma and a count follow in its sentence."""
        s = self.s
        low = s.low
        k = at + 2 if tuple(low[at:at + 2]) == ("out", "of") else at + 1 if low[at] == "of" else None
        if k is None or k >= s.n or (at > 0 and not s.is_punct(at - 1) and low[at - 1] not in lx.CLAUSE_STARTERS):
            return None
        det = k
        k = s.skip(k, {"the", "those", "these", "all", "their", "our"})
        inner = quantifier(s, k)
        start = inner.end if inner is not None and inner.kind in ("exact", "approximate") else k
        head = self.people.person_head(start, counted=start > k)
        if head is None or (inner is not None and start == k):
            return None
        comma = next((j for j in range(head + 1, s.n) if s.is_punct(j) or s.w[j].sentence != s.w[at].sentence), None)
        if comma is None or low[comma] != "," or comma + 1 >= s.n or (
                quantifier(s, comma + 1) is None and bare_share_at(s, comma + 1) is None):
            return None
        whole = self._whole(det, head, inner if start > k else None, self.people.label(head))
        whole.first, whole.who, whole.fronted = at, s.span(det, head), True
        return whole

    def fronted_part(self, m: Mention, whole: Mention, index: int) -> None:
        """Makes m, the first count after a whole said first, its part: a subset, as many as said,
        and the whole more than that."""
        m.relation = f"subset_of:{index}"
        if m.label == "person":
            m.label = whole.label
        if m.count is not None and whole.count is not None and whole.count.value <= m.count.value:
            more = m.count.value + 1
            whole.count = replace(whole.count, value=more, low=max(whole.count.low, more),
                                  high=max(whole.count.high, more))

    def _bare_share(self, at: int, found: list[Mention], parent_index: int | None) -> Mention | None:
        """A share of the group before said with no "of them", as the subject of its own verb: "40
        people wait in the foyer; half go to the gym", "Of the 30 swimmers, two thirds leave", "...,
        20% head to the café", "most stay"."""
        if parent_index is None:
            return None
        share = bare_share_at(self.s, at)
        if share is None:
            return None
        fraction, end = share
        parent = found[parent_index]
        count = self._share(parent.count, fraction)
        if count is not None and self.s.low[at] == "most":
            count = replace(count, kind="implied")
        return Mention(at, end - 1, self.s.span(at, end - 1), parent.label, count,
                       relation=f"subset_of:{parent_index}")

    def _fraction(self, at: int) -> tuple[float | None, int | None]:
        low = self.s.low
        percent = percent_at(self.s, at)  # "20% of them", "ten per cent of the visitors"
        if percent is not None:
            return percent
        for words, share in _FRACTIONS.items():
            end = at + len(words)
            if tuple(low[at:end]) == words and end < self.s.n and low[end] == "of":
                return share, end
        if low[at] == "half" and at + 2 < self.s.n and low[at + 1] in ("the", "those", "these", "their", "our") and \
                (at == 0 or low[at - 1] not in ("a", "the", "other", "second", "first")):
            return 0.5, at  # "half the 60 students": "of" left out
        return None, None

    def _noun_after(self, k: int) -> bool:
        """"two of those nurses": "those" is a pronoun only when no person's noun follows it."""
        return k < self.s.n and self.s.w[k].pos in ("NOUN", "PROPN") and self.people.is_person_noun(k)

    def _whole(self, k: int, head: int, inner: Quantifier | None, label: str) -> Mention:
        """The group named inside the phrase ("the six developers", "the guards"), with its count."""
        s = self.s
        if inner is not None and inner.kind == "exact":
            count = Count("exact", inner.value, inner.value, inner.value)
        elif inner is not None:
            count = count_of(s, inner, f"{k}:whole")
        else:
            low_, high_ = lx.BARE_PLURAL_RANGE
            count = Count("vague", s.choose(low_, high_, f"{k}:whole"), low_, high_)
        return Mention(k, head, s.span(k, head), label, count, partitive=True)

    @staticmethod
    def _share(count: Count | None, fraction: float) -> Count | None:
        """A share of a group's count: "half of the 20 students" are 10."""
        if count is None:
            return None
        value = max(1, round(count.value * fraction))
        kind = "exact" if count.kind == "exact" else "implied"
        return Count(kind, value, max(1, round(count.low * fraction)), max(1, round(count.high * fraction)))


def whole_of_a_bare_part(s: Sentence, found: list[Mention], part: int | None) -> int | None:
    """The group a bare number that borrowed its noun is part of, when "the others" or "the rest"
    follow it: "fifteen students arrive; ten head to the reading room and the others go to the cafe"
    (the ten are fifteen's, and the others the five left). The group said just before, of the same
    kind, counted exactly and more than the part; the part is made its subset."""
    if part is None or part < 1:
        return None
    m, whole = found[part], found[part - 1]
    nxt = m.last + 1
    bare = m.first == m.last and quantifier(s, m.first) is not None and m.relation is None and nxt < s.n and (
        s.is_verb(nxt) or verb_lemma(s.low[nxt]) in lx.INTENT_VERBS)  # "ten head to ...", not "ten in the pharmacy"
    if not bare or whole.label != m.label or whole.relation is not None or m.count is None or whole.count is None \
            or whole.count.kind != "exact" or not 0 < m.count.value < whole.count.value:
        return None
    m.relation = f"subset_of:{part - 1}"
    return part - 1


def other_half(s: Sentence, at: int) -> int | None:
    """The index of "half" in "the other half" / "the second half" at `at` (the rest of a group half
    of which was named before: "half of the thirty students leave and the other half stay"), else None."""
    if at + 2 < s.n and s.low[at] == "the" and s.low[at + 1] in ("other", "second") and s.low[at + 2] == "half" and \
            (at + 3 == s.n or s.low[at + 3] != "of") and not _half_of_a_match(s, at):
        return at + 2
    return None


def _half_of_a_match(s: Sentence, at: int) -> bool:
    """Whether "the second half" at `at` is a time, the part of a game or show ("when the second half
    starts", "in the second half", "the second half kicks off"), not the rest of a group."""
    after = verb_lemma(s.low[at + 3]) if at + 3 < s.n else ""
    return s.low[at + 1] == "second" and (
        (at > 0 and s.low[at - 1] in _TIME_WORDS) or after in lx.EVENT_VERBS | {"kick", "get", "resume", "restart"})


_TIME_WORDS = frozenset("when until till before after as once in during for by since whenever".split())


_PERCENT_WORDS = (("%",), ("percent",), ("per", "cent"), ("pc",), ("pct",))


def percent_at(s: Sentence, at: int) -> tuple[float, int] | None:
    """(share, index of "of") of a percentage of a group at `at`: "20% of them", "ten percent of the
    passengers", "30 per cent of the 50 visitors"; else None."""
    num = number_at(s, at)
    if num is None or not 0 < num[0] <= 100:
        return None
    for words in _PERCENT_WORDS:
        end = num[1] + len(words)
        if tuple(s.low[num[1]:end]) == words and end < s.n and s.low[end] == "of":
            return num[0] / 100, end
    return None


def bare_share_at(s: Sentence, at: int) -> tuple[float, int] | None:
    """(share, index after) of a share said alone before its verb: "half go", "two thirds leave",
    "a quarter head off", "20% stay", "most wait"; else None ("half an hour", "half of them")."""
    low = s.low
    found: tuple[float, int] | None = None
    for words, share in (*_FRACTIONS.items(), (("most",), 0.75), (("one", "half"), 0.5)):
        if tuple(low[at:at + len(words)]) == words:
            found = share, at + len(words)
            break
    num = number_at(s, at) if found is None else None
    if num is not None and 0 < num[0] <= 100:
        for words in _PERCENT_WORDS:
            if tuple(low[num[1]:num[1] + len(words)]) == words:
                found = num[0] / 100, num[1] + len(words)
                break
    if found is None:
        return None
    v = found[1]
    while v < s.n and s.w[v].pos == "ADV" and low[v] not in ("of",):
        v += 1
    if v >= s.n or not (s.is_verb(v) or (s.w[v].pos != "DET" and verb_lemma(low[v]) in lx.INTENT_VERBS)) or \
            s.lemma(v) in lx.PERSON_NOUNS:
        return None
    return found


def verb_of_a_bare_count(s: Sentence, k: int) -> bool:
    """Whether the word at k, after a bare count, is its verb: a verb by the parser, or a verb of
    going or staying the parser took for the count's noun, before a place ("..., a handful stop at the
    customs desk", "..., five head to the café")."""
    if s.is_verb(k) or (s.w[k].tag in ("NN", "NNS") and verb_lemma(s.low[k]) in lx.INTENT_VERBS.keys() | {"stop", "halt"}
                        and k + 1 < s.n and s.preposition(k + 1) is not None):
        return True
    # "..., three rise and stroll through to ...": a noun the parser saw joined by "and" to a verb is one;
    # "..., five troop over to ...": a group's verb before its particle
    return s.w[k].tag == "NN" and k + 2 < s.n and s.lemma(k) not in lx.PERSON_NOUNS and (
        (s.low[k + 1] in ("and", "then") and s.w[k + 2].tag in ("VB", "VBP", "VBZ")) or
        (verb_lemma(s.low[k]) in GROUP_VERBS and s.w[k + 1].pos in ("ADP", "ADV")))
