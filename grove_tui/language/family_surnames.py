"""A family said by its surname in the plural ("the Hendersons", "the Okafors": plural_surnames.py): a
count set off by commas after it ("The Hendersons, a family of five, wander ...", "the Lees, four of
them, ...") says how many the family is and who they are, so it is one group, not the surname's people
and a second family beside them."""

from __future__ import annotations

from grove_tui.language.apposed_counts import class_named
from grove_tui.language.plural_surnames import plural_surname
from grove_tui.language.mention import Mention
from grove_tui.language.sentence import Sentence


def surname_family(s: Sentence, before: Mention) -> bool:
    """Whether the mention is "the" and one capitalised plural name ("the Hendersons"), never a
    capitalised common noun at the start of a sentence ("The nurses") nor a collective."""
    head = before.last
    if before.collective is not None or before.last != before.first + 1 or s.low[before.first] != "the":
        return False
    text = s.w[head].text
    return (len(text) > 3 and text[0].isupper() and text[1:].islower() and text.endswith("s")
            and s.w[head].pos == "PROPN")


def members_said(s: Sentence, before: Mention) -> bool:
    """Whether a count in apposition after the mention names its members by any noun: a school class or
    team said by its number ("Year 3, 28 children, ...") or a family by its surname."""
    return class_named(s, before) or surname_family(s, before)
