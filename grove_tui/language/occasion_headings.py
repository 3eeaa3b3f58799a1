"""An occasion that heads a chat line as its topic, named by whose it is ("kids bday: 9 on the wall + 3
parents on the bench", "school trip - 20 on dodgeball, 4 teachers in the cafe", "hen party: 8 at the
bar"): a few words with no count, then a colon or dash, then counted items. The people in the
heading are the people the items count, not a group of their own (place_topics.py reads a place
heading the same way)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx

if TYPE_CHECKING:
    from grove_tui.language.mention import Mention
    from grove_tui.language.sentence import Sentence

_MARKS = frozenset({":", "-", "—", "–", "|"})
_HEADING_WORDS = 4  # "kids bday", "year 6 leavers party": a heading is short


def without_heading(s: Sentence, found: list[Mention], m: Mention) -> list[Mention]:
    """`found` without the uncounted mentions of a short heading before a colon or dash that opens the
    text, when `m`, counted, comes right after the mark and counts the heading's people (module doc)."""
    if not found or m.count is None or m.count.kind != "exact" or m.relation is not None:
        return found
    mark = next((j for j in range(1, min(_HEADING_WORDS + 1, s.n)) if s.low[j] in _MARKS), None)
    if mark is None or not mark < m.first <= mark + 2 or s.hyphen_inside(mark):
        return found
    if any(_counted(s.low[j]) for j in range(0, mark)) or any(
            f.last >= mark or f.count is None or f.count.kind == "exact" or f.relation is not None or f.whole is not None
            for f in found):
        return found  # "3 kids: ...": a count of its own
    if len(found) == 1 and found[0].first == 0 and found[0].last == mark - 1:
        return found  # "Shoppers: 20 in the food court, 10 in ...": a whole of its parts, no occasion
    if not any(f.label == m.label for f in found) and m.label != "person":
        return found  # "nurses: 3 porters in the lift": other people
    named = [f.label for f in found if f.collective is None]
    if named and m.first == m.last:
        m.label = named[0]  # "kids party: 8 on the trampolines": 8 kids, not 8 of a party
    return []


def _counted(word: str) -> bool:
    return word.isdigit() or (word in lx.NUMBER_WORDS and word not in ("a", "an", "one"))
