"""Lists of groups typed as chat, written out before the prompt is parsed (round 18).

- " n " joining two groups ("12 pickers in the mess room n 2 drivers @ dispatch"): "and";
- "like 40 teens": "about 40" (never "would like 2 guards", a wish);
- two groups typed one after the other with nothing between ("6 pickers in the canteen 2 drivers
  @ dispatch"): a comma before the second count when a plural of people follows it and a plain
  word, not one that numbers places ("bay 2 drivers"), nor a preposition, comes before it, after a
  place said with its preposition;
- short words of places and of what people do: "brk" (break), "rm" (room), "hse" (house), "shd"
  (should), "bldg" (building), "dept" (department), "rec" (reception) ...
"""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

# Short words of chat for places and what people do (whole words, lower case only: "RM" may be a name).
CHAT_SHORT = {"brk": "break", "brkfst": "breakfast", "rm": "room", "rms": "rooms", "hse": "house", "shd": "should",
              "bldg": "building", "dept": "department", "depts": "departments", "recep": "reception",
              "corr": "corridor", "caf": "cafe", "entr": "entrance", "wrkshp": "workshop", "lng": "lounge",
              "wkrs": "workers", "wkr": "worker", "q": "queue"}
_SHORT_WORD = re.compile(r"(?<![\w'/@&-])(" + "|".join(sorted(CHAT_SHORT, key=len, reverse=True)) + r")(?![\w'/@&-])")
_NUMBER = r"(?:\d+|" + "|".join(sorted((w for w in lx.NUMBER_WORDS if w.isalpha()), key=len, reverse=True)) + r")"
# " n " before a count or a determiner: "... in the canteen n 3 drivers".
_N_AND = re.compile(r"(?<=[\w.])\s+n\s+(?=(?:" + _NUMBER + r"|a|an|some|the|like|about|approx|few|couple)\b)")
# "like 40 teens": about forty; not after a word that wants ("would like 2 guards", "I'd like").
_LIKE = re.compile(r"\blike\s+(?=(?:" + _NUMBER + r")\b)", re.IGNORECASE)
# "something like 40", "smth like 5", "somewhere around 30", "in the region of 50": about that many.
_SOMETHING_LIKE = re.compile(r"\b(?:(?:something|smth|sth|summat|somewhere|somethin)\s+(?:like|about|around|near)|"
                             r"in\s+the\s+region\s+of)\s+(?=(?:" + _NUMBER + r")\b)", re.IGNORECASE)
_WANTING = frozenset("would 'd i we you they should also really don't do does did".split())


def chat_lists(text: str) -> str:
    """The text with chat's " n ", "like <number>" and short words written out (see the module doc)."""
    text = _N_AND.sub(" and ", text)
    text = _LIKE.sub(_about, _SOMETHING_LIKE.sub(lambda m: "About " if m.group(0)[:1].isupper() else "about ", text))
    text = _UNJOINED.sub(_joined, text)
    return _SHORT_WORD.sub(lambda m: CHAT_SHORT[m.group(1)], text)


def _about(m: re.Match[str]) -> str:
    before = m.string[:m.start()].split()
    prev = before[-1].lower() if before else ""
    if prev in _WANTING or prev.endswith("'d") or prev in ("look", "looks", "looked", "seem", "seems", "feel", "feels"):
        return m.group(0)
    if prev in ("is", "'s", "was") and re.match(r"\S+\s+(?:deep|long|strong)\b", m.string[m.end():]):
        return ""  # "the q is like 8 deep": a line's length as said (chat_requests.py), a filler before it
    return "about "


# A count in figures and a plural after a word: "... canteen 2 drivers".
_UNJOINED = re.compile(r"(?<=[a-z])(\s+)(\d+)(\s+)([a-z]+s)\b")
# Words after which a count starts no new group: prepositions, joining words, words numbering places.
_NOT_AFTER = lx.DETERMINERS | frozenset("at by from until till after before since to of or and about around than under "
                                        "over only just nearly almost all with for past via through near every in on "
                                        "into onto n plus minus are were is was be have has had got get gets need "
                                        "needs want wants".split()) | frozenset("gate desk platform room aisle till lane "
                                        "court ward bay stand floor level exit door counter table bed screen track "
                                        "pier dock berth stop zone area block wing unit".split())

# Words before the place the first group is at ("in the canteen 2 drivers").
_PLACE_PREPOSITIONS = frozenset("in at on by near round around outside inside behind beside".split())


def _joined(m: re.Match[str]) -> str:
    before = m.string[:m.start()].split()
    prev = before[-1].lower() if before else ""
    window = [w.lower() for w in before[-5:-1]]
    if not re.fullmatch(r"[a-z]+", prev) or prev in _NOT_AFTER or prev in lx.APPROXIMATE_WORDS or \
            lemma(m.group(4)) not in lx.PERSON_NOUNS or not any(w in _PLACE_PREPOSITIONS for w in window) or \
            any(not re.fullmatch(r"[a-z]+", w) for w in window[next(k for k, w in enumerate(window)
                                                                   if w in _PLACE_PREPOSITIONS):]):
        return m.group(0)  # "roughly 25 travellers", "year 6 pupils", "the café's 8 customers": one group
    return f",{m.group(1)}{m.group(2)}{m.group(3)}{m.group(4)}"
