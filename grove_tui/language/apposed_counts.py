"""Counts set off by commas after a group said without one, and the verb after them. "Year 1,
twenty-four pupils, troop from their classroom": the class is the 24 pupils (one group, whatever
noun the count uses: a school class or team is its members, school_classes.py), and "troop" is
their verb, though it is a collective's word too. A collective's word with no determiner, right
after a comma or a noun and before a preposition, is the verb of a group ("crowd round the
t-rex", "troop into the hall", "file out")."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.apposed_collectives import apposed_collective as apposed_collective
from grove_tui.language.mention import Mention
from grove_tui.language.school_classes import named_class
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Collectives' words that are verbs of a group moving or standing together.
GROUP_VERBS = frozenset("crowd cluster huddle swarm throng mob flock troop file queue gather group pack".split())
_AFTER_VERB = lx.PLACE_PREPOSITIONS | frozenset({"round", "around", "out", "off", "in", "along", "back", "up", "together"})


def collective_is_a_verb(s: Sentence, m: Mention) -> bool:
    """Whether the one-word collective mention m is the verb of the group before it ("..., 24
    pupils, troop from ...", "4-5 kids w/ notebooks crowd round the t-rex", "..., then troop back in to ...")."""
    if m.collective is None or m.first == 0 or m.last + 1 >= s.n:
        return False
    if m.first != m.last:  # "..., four troop over to ward A": a singular collective after a count of more is a verb
        return m.last == m.first + 1 and m.count is not None and s.w[m.first].pos == "NUM" and \
            s.low[m.last] == s.lemma(m.last) and s.low[m.last + 1] in _AFTER_VERB | {"over", "through", "across"} \
            and verb_lemma(s.low[m.last]) in GROUP_VERBS
    before = m.first - 1
    return (s.low[before] in (",", "then", "and") or s.w[before].pos in ("NOUN", "PROPN")) and s.low[m.last + 1] in _AFTER_VERB \
        and verb_lemma(s.low[m.first]) in GROUP_VERBS


def class_named(s: Sentence, before: Mention) -> bool:
    """Whether the mention is a school class or team said by its number ("Year 1", "Team 2"): a
    count in apposition names its members, by whatever noun ("Year 3, 28 children, ...")."""
    return before.collective is None and named_class(s, before.first) is not None
