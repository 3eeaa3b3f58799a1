"""Count edits of a follow-up: a group's head count changed, the group kept.

Factors ("twice as long", "double the nurses", "halve the queue", "three times as many visitors"),
comparatives ("make the queue longer": x1.5, "smaller": x2/3, said in a note), a new count ("make it
twenty patients", "only two nurses", "make the queue 15") and fewer ("two fewer visitors").
"""

from __future__ import annotations

import re

from grove_tui.language.edits import CountChange, GroupEdit
from grove_tui.language.followup_context import FollowupContext
from grove_tui.language.followup_phrases import NUMBER_PATTERN, number_of, states_action
from grove_tui.language.followup_references import resolve

FACTOR_WORDS: dict[str, float] = {
    "twice": 2.0, "double": 2.0, "doubled": 2.0, "two times": 2.0, "thrice": 3.0, "three times": 3.0,
    "triple": 3.0, "tripled": 3.0, "four times": 4.0, "quadruple": 4.0, "five times": 5.0, "ten times": 10.0,
    "half": 0.5, "halve": 0.5, "halved": 0.5, "a third": 1 / 3, "one third": 1 / 3, "a quarter": 0.25,
}
FACTOR_VERBS: dict[str, float] = {"double": 2.0, "triple": 3.0, "quadruple": 4.0, "halve": 0.5}
# "make the queue longer": a comparative with no number (the factor is said in a note).
COMPARATIVES: dict[str, float] = {"longer": 1.5, "bigger": 1.5, "larger": 1.5, "busier": 1.5, "fuller": 1.5,
                                  "more crowded": 1.5, "shorter": 2 / 3, "smaller": 2 / 3, "quieter": 2 / 3}
SIZE_WORDS = r"(?:long|many|big|large|numerous|crowded|busy|full|much)"

_FACTOR_WORD = "|".join(re.escape(w) for w in sorted(FACTOR_WORDS, key=len, reverse=True))
_MAKE_FACTOR = re.compile(rf"^(?:make|let|have)\s+(.+?)\s+({_FACTOR_WORD})\s+(?:as\s+)?{SIZE_WORDS}"
                          rf"(?:\s+(?:as\s+)?(?:before|now|it is|they are|as it was|as they were))?$")
_IS_FACTOR = re.compile(rf"^(.+?)\s+(?:is|are|should be|must be|becomes?|gets?|grows?|will be)\s+"
                        rf"({_FACTOR_WORD})\s+(?:as\s+)?{SIZE_WORDS}(?:\s+as\s+(?:before|now))?$")
_FACTOR_VERB = re.compile(r"^(" + "|".join(FACTOR_VERBS) + r")\s+(?:the\s+(?:size|number|length)\s+of\s+)?(.+)$")
_FACTOR_MANY = re.compile(rf"^({_FACTOR_WORD})\s+as\s+many\s+(.+?)(?:\s+as\s+(?:before|now))?$")
_COMPARATIVE = re.compile(r"^(?:make|let)\s+(.+?)\s+(" + "|".join(COMPARATIVES) + r")$")
_SET_COUNT = re.compile(rf"^(?:make (?:it|that|them|this)|let (?:it|there) be|use|we need|i want|there should be|"
                        rf"there are|there is|(?:it|that) should be|only|just|(?:i|we) want|have|make)\s+"
                        rf"({NUMBER_PATTERN}\s+.+)$")
_MAKE_NUMBER = re.compile(rf"^(?:make|set|change)\s+(.+?)\s+(?:to\s+|into\s+)?({NUMBER_PATTERN})"
                          rf"(?:\s+(?:people|persons|strong|long))?$")
_FEWER = re.compile(rf"^({NUMBER_PATTERN})\s+(?:fewer|less)\s+(.+)$")


def read_count_edit(text: str, cues: set[str], ctx: FollowupContext) -> list[GroupEdit] | None:
    """The count changes a clause states, else None (it says no count of a group)."""
    for pattern, phrase_group, factor_group in ((_MAKE_FACTOR, 1, 2), (_IS_FACTOR, 1, 2), (_FACTOR_MANY, 2, 1)):
        m = pattern.match(text)
        if m is not None:
            factor = FACTOR_WORDS[m.group(factor_group)]
            return _count_change(text, m.group(phrase_group), CountChange("factor", factor), ctx)
    m = _FACTOR_VERB.match(text)
    if m is not None:
        return _count_change(text, m.group(2), CountChange("factor", FACTOR_VERBS[m.group(1)]), ctx)
    m = _COMPARATIVE.match(text)
    if m is not None:
        factor = COMPARATIVES[m.group(2)]
        ctx.notes.append(f"'{m.group(2)}' with no number: read as x{factor:.2g}; say \"twice as long\" or a number "
                         f"to be exact")
        return _count_change(text, m.group(1), CountChange("factor", factor), ctx)
    m = _FEWER.match(text)
    if m is not None:
        return _count_change(text, m.group(2), CountChange("delta", -float(number_of(m.group(1)) or 0)), ctx)
    m = _MAKE_NUMBER.match(text)
    if m is not None and number_of(m.group(2)) is not None and resolve(m.group(1), ctx).found:
        return _count_change(text, m.group(1), CountChange("set", float(number_of(m.group(2)) or 1)), ctx)
    m = _SET_COUNT.match(text)
    if m is not None:
        reading = ctx.read(m.group(1))
        if reading.groups:
            g = reading.groups[0]
            ref = resolve(g.who, ctx, label=g.label)
            if ref.found and not states_action(m.group(1)[len(g.who):]):
                return [GroupEdit("change", text, ref, g, ("count",), CountChange("set", float(g.count.value)))]
    return None


def _count_change(text: str, phrase: str, change: CountChange, ctx: FollowupContext) -> list[GroupEdit]:
    ref = resolve(phrase, ctx)
    if not ref.found:
        ctx.notes.append(f"'{phrase}' names no group of the scenario{ctx.known_groups()}: no count changed")
        return []
    return [GroupEdit("change", text, ref, None, ("count",), change)]
