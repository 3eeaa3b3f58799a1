"""Chat spelling a researcher types in a hurry, written out before the prompt is parsed (round 14).

- a dropped "g" ("walkin", "headin'", "queuin"): the "-ing" form of a verb of what people do, unless
  it follows a determiner ("a walkin clinic" is a walk-in clinic);
- short words ("frm": from, "b4": before, "bc"/"bcos": because');
- "2" for "to" between a place and a place ("from the staff office 2 bay 4"), which needs the world:
  "2" is a number when it completes one of the world's names ("bay 2"), when it follows a word
  places are numbered by, or when a person, a unit or a plural follows ("2 drivers", "2 mins").

`spell_out` is world-free and runs with `text.normalise`; `chat_to` runs once the world is known.
"""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.chat_slips import written_out
from grove_tui.language.places import PlaceIndex
from grove_tui.language.informal_people import plain_people
from grove_tui.language.possessed_items import possessed_items
from grove_tui.language.tokens import lemma, verb_lemma

# Short words of chat the lexicon's CHAT_WORDS lacks (whole words only).
_SHORT = {"frm": "from", "b4": "before", "bc": "because", "bcos": "because", "cos": "because", "coz": "because",
          "bcz": "because", "tho": "though", "thx": "", "tmrw": "tomorrow", "w": "with", "til": "until", "nxt": "next", "outta": "out of", "gonna": "going to", "wanna": "want to",
          "in2": "into", "on2": "onto"}
# Chat short forms of the words places are named by ("the boardroom tbl", "mtg rm 2", "the toy dept").
_SHORT.update({"tbl": "table", "tbls": "tables", "rm": "room", "rms": "rooms", "mtg": "meeting",
               "dept": "department", "depts": "departments", "bldg": "building", "flr": "floor",
               "recep": "reception"})
_SHORT_WORD = re.compile(r"(?<![\w'/@&-])(" + "|".join(sorted(_SHORT, key=len, reverse=True)) + r")(?![\w'/@&-])",
                         re.IGNORECASE)
# "bc" is also a date ("300 BC") and "w" a compass point ("W exit"): only in lower case, after a word.
_CASE_SENSITIVE = frozenset({"bc", "w", "cos"})
_DROPPED_G = re.compile(r"(?<![\w'-])([A-Za-z]{2,}in)(?:'|’)?(?![\w'’-])")
_DETERMINER_BEFORE = re.compile(r"\b(?:a|an|the|this|that|our|their|his|her|my|its)\s+$", re.IGNORECASE)
# Verbs whose "-in'" form is read back: what people do, and the robot's verbs they react with.
_VERBS = frozenset(lx.INTENT_VERBS) | frozenset(lx.ROBOT_VERBS) | frozenset({"hang", "look", "get", "do", "be"})


def spell_out(text: str) -> str:
    """The text with chat's dropped "g"s and short words written out (see the module doc)."""
    text = _DROPPED_G.sub(_with_g, text)
    text = written_out(_SHORT_WORD.sub(_short, text))  # "teh", "are muckin out" (chat_slips.py)
    return possessed_items(plain_people(text))  # "seven nippers" (informal_people.py); "our son in bedroom 2, ..."


def _with_g(m: re.Match[str]) -> str:
    word = m.group(1)
    full = word + "g"
    stem = full.lower()[:-3]  # "doin", "goin": a short verb whose "-ing" the lemmatiser keeps whole
    if (verb_lemma(full.lower()) not in _VERBS and not (len(stem) == 2 and stem in _VERBS)) or \
            _DETERMINER_BEFORE.search(m.string[:m.start()]):
        return m.group(0)
    return full


def _short(m: re.Match[str]) -> str:
    word = m.group(1)
    if word.lower() in _CASE_SENSITIVE and (word != word.lower() or not re.search(r"[a-z]\s+$", m.string[:m.start()])):
        return word  # "300 BC", "the W exit"
    if word.lower() == "w" and not re.match(r"\s+(?:a|an|the|his|her|their|my|our|\d+|[a-z]+s)\b", m.string[m.end():]):
        return word  # "w" is "with" only before a determiner, a count or a plural ("w his kid", "w 2 kids")
    return _SHORT[word.lower()]


# "2" after a word or a place's number, and the word after it.
_TWO = re.compile(r"(?<=\w)(\s+)2(\s+)([A-Za-z][\w-]*)")
# Words after which "2" is not "to": prepositions that take a number ("at 2", "by 2", "from 2 to 4"),
# "to" itself, and words of joining.
_NOT_AFTER = lx.DETERMINERS | frozenset("at by from until till after before since to of or and about around than "
                                        "under over only just nearly almost all x times on in into onto with for "
                                        "past via through near every".split())


def chat_to(text: str, index: PlaceIndex) -> str:
    """The text with chat's "2" read as "to" before a place of the world ("walkin frm the staff office
    2 bay 4"), never as the number of one of its places ("bay 2") nor as a count ("2 drivers")."""
    numbered = {a for a, b in index.name_pairs if b.isdigit()} | _NUMBERED_BY

    def to(m: re.Match[str]) -> str:
        before = m.string[:m.start()].split()
        prev = before[-1].lower().strip(",.;:") if before else ""
        nxt = m.group(3).lower()
        if prev.isdigit():
            # "from bay 2 2 the café": a place's number, then "to"; "at 1 2 the ..." is no place
            if len(before) < 2 or before[-2].lower() not in numbered:
                return m.group(0)
        elif not prev or prev in _NOT_AFTER or prev in numbered or \
                (len(prev) >= 3 and any(n.startswith(prev) for n in numbered)):
            return m.group(0)  # "at 2", "bay 2", "plat 2": a time or a place's number
        head = lemma(nxt)
        if nxt in lx.DETERMINERS and nxt not in ("all", "both", "some", "any", "no"):
            return f"{m.group(1)}to{m.group(2)}{m.group(3)}"
        if verb_lemma(nxt) != nxt and lx.INTENT_VERBS.get(verb_lemma(nxt)) is not None:
            return m.group(0)  # "on plat 2 waiting": the verb after a place's number
        if head in lx.PERSON_NOUNS or head in lx.DURATION_UNITS or nxt.rstrip("s") in lx.DURATION_UNITS or \
                nxt in lx.NUMBER_WORDS or (head != nxt and nxt.endswith("s")) or not _place_word(nxt, index):
            return m.group(0)  # "2 drivers", "2 mins", "2 bags": a count
        return f"{m.group(1)}to{m.group(2)}{m.group(3)}"
    return _TWO.sub(to, text)


def _place_word(word: str, index: PlaceIndex) -> bool:
    """Whether a word starts a place: a word of the world's place names, or a word places are named by."""
    return lemma(word) in index.vocabulary or word in index.vocabulary or word in _NUMBERED_BY


# Words a place is numbered by ("gate 2", "bay 2"): after one of them "2" is the place's number.
_NUMBERED_BY = frozenset("gate desk platform room aisle till lane court ward bay stand floor level exit door counter "
                         "table bed screen track pier dock berth stop zone area block wing unit".split())
