"""Being on one's way is no place (round 53): "a student balances a board of bowls on her way from the
throwing studio to the drying area", "two porters on their way to the ward". "On her way" says the
person is going; the route is the "from" and "to" after it, and "way" must not be read as a door called
"the way in". "On the way" counts too when a route word follows ("on the way to the exit")."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

_OWNERS = frozenset({"her", "his", "their", "my", "our", "your", "its"})
_ROUTE = frozenset({"to", "from", "back", "home", "over", "across", "round", "towards", "toward", "into"})


def on_ones_way(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether "on" at `at` and the words from k are "her way", "their way", "the way to" (module doc)."""
    if prep != "on" or k + 1 >= s.n or s.low[at] != "on" or s.low[k + 1] != "way":
        return False
    if s.low[k] in _OWNERS:
        return True
    return s.low[k] == "the" and k + 2 < s.n and s.low[k + 2] in _ROUTE
