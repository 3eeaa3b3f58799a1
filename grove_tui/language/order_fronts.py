"""Words of order that open a sentence with no comma after them (round 64b): "First a family checks in
at the desk, then ...", "Initially a woman browses the bookshop", "Firstly a man shops in X". The small
parser reads "a man shops" as a compound noun after such a word; said with a comma ("First, a man shops")
it reads the verb. These words say when, never who, so the person's verb is found as if they were not
there."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.parser import Word

# Adverbs of order or time that open a sentence before its subject.
ORDER_WORDS = frozenset("first firstly initially next then later afterwards afterward finally lastly "
                        "meanwhile soon now eventually subsequently second secondly third thirdly".split())


def without_order_words(before: list[Word]) -> list[Word]:
    """The words before a verb, less the adverbs of order that open them ("First a man" -> "a man")."""
    j = 0
    while j < len(before) and before[j].pos == "ADV" and before[j].lower in ORDER_WORDS:
        j += 1
    return before[j:]
