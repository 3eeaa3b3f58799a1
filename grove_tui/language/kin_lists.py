"""Kin said as one list (round 18): "Mum, Dad and the three kids walk to ...", "Grandma, Grandpa and
two grandchildren wait ..." are one family, a group of everyone listed who keeps together. A couple
("Mum and Dad") and a possessive pair ("a mum and her toddler") stay one group per noun phrase, each of
one (the writers' convention); the list here has three kin or more ("Mum and two kids" stays two groups,
the set's convention).
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.counts import number_at
from grove_tui.language.mention import Mention
from grove_tui.language.model import Count
from grove_tui.language.sentence import Sentence

_KIN = lx.KIN_NAMES | frozenset(
    "mother father mummy mommy parent grandparent grandmother grandfather grandchild grandson granddaughter "
    "son daughter kid child baby toddler brother sister sibling cousin aunt auntie aunty uncle nephew niece "
    "wife husband twin stepmum stepdad stepson stepdaughter".split())
_BEFORE = frozenset({"the", "their", "his", "her", "our", "my", "its", "a", "an"})


def _item(s: Sentence, i: int) -> tuple[int, int] | None:
    """(people, last word) of one kin item starting at word i: "Mum", "the three kids", "a baby"."""
    j = i + 1 if i < s.n and s.low[i] in _BEFORE else i
    value = 1
    said = number_at(s, j)
    if said is not None:
        value, j = said
    if j >= s.n or s.lemma(j) not in _KIN or (j + 1 < s.n and s.w[j + 1].pos in ("NOUN", "PROPN")):
        return None
    if said is None and s.lemma(j) != s.low[j] and s.low[j] not in lx.KIN_NAMES:
        return None  # "the kids": how many is not said
    return value, j


def _list_at(s: Sentence, i: int) -> tuple[int, int] | None:
    """(people, last word) of a list of kin starting at word i, None when there is none."""
    items: list[tuple[int, int]] = []
    k, ended = i, False
    while not ended:
        item = _item(s, k)
        if item is None:
            return None
        items.append(item)
        after = item[1] + 1
        if after < s.n and s.low[after] == ",":
            after += 1
            if after < s.n and s.low[after] == "and":
                after, ended = after + 1, True
        elif after < s.n and s.low[after] == "and":
            after, ended = after + 1, True
        else:
            return None
        k = after
    last = _item(s, k)
    if last is None:
        return None
    items.append(last)
    if any(s.w[j].sentence != s.w[i].sentence for _, j in items):
        return None
    if len(items) < 3:
        return None  # "Mum and Dad", "Mum and two kids": one group per noun phrase (the writers' convention)
    return sum(v for v, _ in items), last[1]


def kin_families(s: Sentence, mentions: Sequence[Mention]) -> list[Mention]:
    """The mentions with each list of kin as one mention of a family who keep together."""
    out = list(mentions)
    i = 0
    while i < s.n:
        found = _list_at(s, i) if (i == 0 or s.low[i - 1] not in _BEFORE) else None
        if found is None:
            i += 1
            continue
        total, last = found
        inside = [k for k, m in enumerate(out) if m.first <= last and m.last >= i]
        if not inside or any(out[k].relation is not None or out[k].whole is not None for k in inside) or \
                any(m.relation is not None for m in out):
            i = last + 1
            continue
        family = Mention(i, last, s.span(i, last), "family", Count("exact", total, total, total), together=True)
        out = out[:inside[0]] + [family] + [m for k, m in enumerate(out) if k > inside[0] and k not in inside]
        i = last + 1
    return out
