"""Names of a body of people with "of" inside, before the person noun they describe ("twelve Duke of
Edinburgh hikers", "ten Friends of the Museum volunteers", "two Knights of Columbus stewards"): the
name says what kind of person, and the noun after it heads the phrase. So too a name with a possessive
inside (round 44: "a busload of Women's Institute ladies", "two St John's Ambulance volunteers"): the
possessive is the name's, not an owner's, and the person noun after the name heads the phrase."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence


def _capital(s: Sentence, k: int) -> bool:
    return s.w[k].text[:1].isupper() and s.w[k].text.replace("'", "").isalpha()


def of_name_end(s: Sentence, k: int) -> int | None:
    """The word after a capitalised name with "of" inside that starts at k ("Duke of Edinburgh",
    "Friends of the Museum"), when a word follows it, else None."""
    if k == 0 or k + 2 >= s.n or not _capital(s, k) or s.low[k + 1] != "of":
        return None
    j = k + 2
    if s.low[j] == "the":
        j += 1
    start = j
    while j < s.n and j < start + 3 and _capital(s, j):
        j += 1
    if j == start or j >= s.n or _capital(s, j) or s.w[j].pos not in ("NOUN", "VERB", "PROPN"):
        return None
    return j


def possessive_name_end(s: Sentence, k: int) -> int | None:
    """The word after a capitalised name with a possessive inside that starts at k ("Women's
    Institute", "St John's Ambulance"), when a noun follows it, else None."""
    j = k
    while j < s.n and j < k + 2 and _capital(s, j) and s.low[j] not in ("i", "a"):
        j += 1  # "St John"
    if j == k or j + 1 >= s.n or s.low[j] not in ("'s", "’s"):
        return None
    j += 1
    start = j
    while j < s.n and j < start + 3 and _capital(s, j):
        j += 1
    if j == start or j >= s.n or _capital(s, j) or s.w[j].pos not in ("NOUN", "PROPN"):
        return None
    return j
