"""Pass 5, part 2: a group's count, settled once its places are known (everyone in a zone fills it
at a busy density; "the others" after "one of them" are the rest of the parent), a count said apart
("visitors, about twenty, wait"), and how sure the reader is of it."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.counts import Quantifier, count_of, quantifier
from grove_tui.language.mention import Mention
from grove_tui.language.model import Count, FieldConfidence, GroupReading
from grove_tui.language.sentence import Sentence


def settle_count(s: Sentence, m: Mention, span: tuple[int, int], zone: str | None, earlier: list[GroupReading],
                 notes: list[str]) -> Count:
    """The count of the group of mention m, whose words are `span` and whose place is `zone`."""
    count = m.count
    if count is not None and count.kind in ("implied", "vague") and m.relation is None:
        count = count_after_comma(s, m, span) or count
    if m.whole_zone:
        count = _whole_zone(s, m, zone)
        if zone is None:
            notes.append(f"'{m.who}': no place says where everyone is; the whole building is filled")
    if m.rest_of_parent:
        count = _rest_of_parent(s, m, earlier, notes)
    if count is None:  # every mention kind sets or settles its count; this is the documented default
        count = Count("vague", s.choose(*lx.BARE_PLURAL_RANGE, f"{m.first}:bare"), *lx.BARE_PLURAL_RANGE)
    if m.exclusive and count.kind != "exclusive":
        count = replace(count, kind="exclusive")
    return count


def _whole_zone(s: Sentence, m: Mention, zone: str | None) -> Count:
    area = s.index.zone_area(zone) if zone else sum(e.area for e in s.index.entries if e.kind == "zone")
    low = max(1, min(lx.WHOLE_ZONE_CAP, round(area * lx.WHOLE_ZONE_DENSITY[0])))
    high = max(low, min(lx.WHOLE_ZONE_CAP, round(area * lx.WHOLE_ZONE_DENSITY[1])))
    if m.fraction < 1.0:
        low, high = max(1, round(low * m.fraction)), max(1, round(high * m.fraction))
    return Count("whole_zone", s.choose(low, high, f"{m.first}:whole"), low, high)


def _rest_of_parent(s: Sentence, m: Mention, earlier: list[GroupReading], notes: list[str]) -> Count:
    parent = int((m.relation or "x:-1").split(":")[1]) if m.relation else -1
    if 0 <= parent < len(earlier):
        taken = sum(g.count.value for g in earlier if g.relation == f"subset_of:{parent}")
        rest = max(0, earlier[parent].count.value - taken)
        if rest == 0:
            notes.append(f"'{m.who}': nobody is left of '{earlier[parent].who}'")
        return Count("implied", rest, rest, rest)
    low, high = lx.OTHERS_RANGE
    return Count("vague", s.choose(low, high, f"{m.first}:rest"), low, high)


def count_after_comma(s: Sentence, m: Mention, span: tuple[int, int]) -> Count | None:
    """A count said on its own after the group's phrase, between a comma and the clause's end:
    "a long line of people at the counter, maybe a dozen", "visitors, about twenty, wait"."""
    for i in range(m.last + 2, span[1]):
        if s.low[i - 1] not in (",", "(", "-", "–"):
            continue  # "visitors, about twenty, wait", "students (around 30) study"
        q = quantifier(s, i)
        if q is None and s.low[i] in lx.APPROXIMATE_WORDS:
            q = quantifier(s, i + 1)
            q = Quantifier(q.value, "approximate", q.end, q.high, q.low) if q is not None and q.kind == "exact" else q
        if q is None or q.kind not in ("exact", "approximate", "range"):
            continue
        if q.end >= s.n or s.is_punct(q.end):
            return count_of(s, q, f"{m.first}:apposition")
    return None


def count_confidence(s: Sentence, m: Mention, count: Count) -> list[FieldConfidence]:
    """How sure a count is: said outright (not listed), approximate, a vague word's range, a
    collective's usual size, a share of a zone's floor, or no number at all (a guess)."""
    said = f"'{m.who}'"
    if count.kind == "structured" and count.low != count.high:
        return [FieldConfidence("count", 0.7, f"{said}: how many parties or how many in each is not said: "
                                              f"{count.value} chosen in {count.low}-{count.high}")]
    if count.kind in ("exact", "structured", "exclusive"):
        return []
    if count.kind == "approximate":
        return [FieldConfidence("count", 0.9, f"{said}: about {count.value} ({count.low}-{count.high})")]
    if count.kind == "whole_zone":
        return [FieldConfidence("count", 0.6, f"{said}: {count.value} people from the place's floor area "
                                              f"({count.low}-{count.high})")]
    if count.kind == "implied" and m.collective is not None:
        return [FieldConfidence("count", 0.65, f"the size of {said} is not said: {count.value} chosen in "
                                               f"{count.low}-{count.high}")]
    if count.kind == "implied":
        return [FieldConfidence("count", 0.8, f"{said}: {count.value}, from the rest of the sentence")]
    first = s.low[m.first]
    worded = quantifier(s, m.first) is not None or first in ("others", "other", "rest", "a", "an") or \
        (first == "the" and m.relation is not None)
    if worded:
        return [FieldConfidence("count", 0.7, f"{said} gives no number: {count.value} chosen in "
                                              f"{count.low}-{count.high}")]
    return [FieldConfidence("count", 0.5, f"no number is given for {said}: {count.value} guessed in "
                                          f"{count.low}-{count.high}", (str(count.low), str(count.high)))]
