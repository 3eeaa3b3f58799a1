"""What people call places besides their names: informal names and idioms ("the hole in the wall" is a
cash machine, "the loo" a toilet, "the caff" a café), and the chat words and times that end a place
phrase ("@ the coat counter b4 closing").

An informal name is read as its plain words, which the world's place index then matches by words and
by meaning like any phrase; a world that lacks the place refuses the whole name, never its words one by
one ("hole", "wall"). The embedding model does not know these names (the nearest place to "the hole in
the wall" is a door, at 0.42), so they are listed here, by what they mean in English, for every world.
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.places import PlaceIndex, PlaceMatch
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma, verb_lemma

# informal name -> what it means, in the words world names use
INFORMAL_PLACES: dict[str, str] = {
    "hole in the wall": "cash machine", "loo": "toilet", "loos": "toilets", "bog": "toilet", "bogs": "toilets",
    "lav": "toilet", "lavvy": "toilet", "khazi": "toilet", "crapper": "toilet", "little boys room": "men's toilet",
    "little girls room": "women's toilet", "powder room": "toilet", "facilities": "toilets",
    "gents": "men's toilet", "ladies": "women's toilet", "ladies room": "women's toilet", "mens room": "men's toilet",
    "men's room": "men's toilet", "caff": "cafe", "caf": "cafe", "greasy spoon": "cafe", "coffee place": "cafe",
    "newsie": "newsagent", "newsies": "newsagent", "chippy": "fish and chip shop", "offie": "off licence",
    "sarnie shop": "sandwich shop", "brew station": "kitchen", "tea point": "kitchen",
}
# How sure a place read from an informal name is at most: sure enough not to ask, never read outright.
INFORMAL_SURE = 0.7
_NAMES = {tuple(name.replace("'", " ").split()): plain for name, plain in INFORMAL_PLACES.items()}
_LONGEST = max(len(words) for words in _NAMES)

# Chat words for a time or a mood that end a place phrase ("@ the coat counter b4 closing", "the café 2nite").
CHAT_TIME_WORDS = frozenset("b4 til atm 2nite 2night tonite 2day 2moro 2morrow tmrw tmr l8r asap rn lol omg tbh imo "
                            "pls plz thx eod".split())
TIME_WORDS = frozenset("today tonight tomorrow yesterday now later soon noon midnight closing opening".split())
TIME_NOUNS = frozenset("lunch lunchtime breakfast dinner supper closing opening close noon midnight morning "
                       "afternoon evening night boarding".split())


def informal_at(words: Sequence[str], j: int) -> tuple[int, str] | None:
    """The informal name starting at word j ("hole in the wall", "the little boys' room" without
    its article), as (index after it, its plain words); None when none starts there. Hyphens and
    apostrophes inside the name are skipped ("hole-in-the-wall", "ladies' room")."""
    kept: list[str] = []
    ends: list[int] = []
    k = j
    while k < len(words) and len(kept) < _LONGEST:
        if words[k] in ("-", "'", "’") and kept:
            k += 1
            continue
        kept.append(words[k])
        k += 1
        ends.append(k)
    for n in range(len(kept), 0, -1):
        plain = _NAMES.get(tuple(kept[:n]))
        if plain is not None:
            end = ends[n - 1]
            while end < len(words) and words[end] in ("'", "’") and n and kept[n - 1].endswith("s"):
                end += 1  # "the gents'"
            return end, plain
    return None


# Chat for "for" and "to" after a place ("in departure lounge waitin 4 boarding", "in lobby going 2 bar").
_CHAT_LINKS = frozenset({"4", "2"})


def chat_ends_name(s: Sentence, j: int, phrase: Sequence[str], whole: bool) -> bool:
    """Whether word j ends a place phrase that is already a place's whole name (`whole`): a verb with
    its g dropped or not ("waitin", "chatting"), or the chat "4"/"2" for "for"/"to" before a word
    ("waitin 4 boarding"); never a word the world's names hold next to it ("pharmacy waiting chairs")."""
    low = s.low
    if not whole or not phrase or j >= s.n:
        return False
    w = low[j]
    if w in _CHAT_LINKS:
        return j + 1 < s.n and low[j + 1].isalpha() and not s.index.knows(w)
    nxt = lemma(low[j + 1]) if j + 1 < s.n else ""
    if (lemma(phrase[-1]), lemma(w)) in s.index.name_pairs or (lemma(w), nxt) in s.index.name_pairs:
        return False
    if w.endswith("in") and verb_lemma(w + "g") in lx.INTENT_VERBS:
        return True  # chat drops the g: no parser knows "waitin"
    return w.endswith("ing") and s.w[j].pos == "VERB" and verb_lemma(w) in lx.INTENT_VERBS


def informal_room(index: PlaceIndex, lemmas: Sequence[str], match: PlaceMatch) -> PlaceMatch:
    """An informal name read as a fixture its room fits as well (round 44): "the loo" is read as
    "toilet", the name of a house's toilet and an alias of its bathroom; said so, it is the room."""
    if match.kind != "entity":
        return match
    tied = [m for m in index.candidates(lemmas) if m.score >= match.score - 1e-9]
    return next((m for m in tied if m.kind == "zone" and m.name == match.zone and m.exact), match)
