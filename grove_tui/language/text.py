"""The prompt as text, before it is parsed: what a keyboard, a phone or a chat window adds to English.

`normalise` gives the text the reader parses: Unicode compatibility forms folded (full-width
letters "Ｔｅｎ" are "Ten", ligatures are letters), symbols and emoji that are no words dropped
("👨‍👩‍👧‍👦 a family" is "a family"; a lone surrogate no longer reaches the parser), chat
abbreviations written out ("ppl" is "people", "&" is "and", "@ the desk" is "at the desk", "~30" is
"about 30", "swimmers x10" is "10 swimmers"), and runs of spaces collapsed. Letters
with accents stay ("café"); `plain` strips them where world names are compared.
"""

from __future__ import annotations

import re
import unicodedata

from grove_tui.language.posture_manners import without_posture_before_going
from grove_tui.language.robot_typos import with_robot_spelt
from grove_tui.language.paired_kin import as_paired_kin
from grove_tui.language.bare_items import bare_items
from grove_tui.language.bracketed_counts import commas_for_brackets
from grove_tui.language.chat_lists import chat_lists
from grove_tui.language.chat_places_first import places_first
from grove_tui.language.chat_people import chat_people
from grove_tui.language.chat_spelling import spell_out
from grove_tui.language.chat_years import chat_years
from grove_tui.language.some_one import some_one
from grove_tui.language.count_spelling import count_words_spelt
from grove_tui.language.ish_counts import ish_counts
from grove_tui.language.kin_counts import kin_counts
from grove_tui.language.placing_lists import placing_lists
from grove_tui.language.placing_verbs import placing_verbs
from grove_tui.language.name_stops import names_unstopped
from grove_tui.language.direction_phrases import towards_for_direction
from grove_tui.language.lexicon import CHAT_WORDS, DURATION_UNITS, PERSON_NOUNS
from grove_tui.language.robot_chat import robot_chat
from grove_tui.language.robot_sent import robot_sent
from grove_tui.language.study_years import year_of_people
from grove_tui.language.where_commas import where_commas
from grove_tui.language.kept_away import kept_away
from grove_tui.language.tokens import lemma

# Unicode categories that never carry a word: other symbols (emoji, pictographs), modifier symbols
# (skin tones), format characters (zero-width joiners, variation selectors), private use and
# surrogates. Punctuation, maths signs ("+") and currency stay.
_DROPPED_CATEGORIES = frozenset({"So", "Sk", "Cf", "Co", "Cs", "Cn"})
_CHAT_WORD = re.compile(r"(?<![\w'])(" + "|".join(re.escape(w) for w in sorted(CHAT_WORDS, key=len, reverse=True))
                        + r")(?![\w'])", re.IGNORECASE)
# "3 kids & their mum", "2 nurses + 1 porter"; not the "&" of an abbreviation ("A&E", "R&D")
_JOINING_SIGN = re.compile(r"(?<!\b[A-Za-z])(?<=\w)\s*(?:&|\+)\s*(?=\w)|(?<=\b[A-Za-z])\s+(?:&|\+)\s*(?=\w)"
                           r"|(?<=\b[A-Za-z])(?:&|\+)\s+(?=\w)")
# "@ the counter", "@gate 3": "at" in chat, but never inside an address ("bob@example.org")
_AT_SIGN = re.compile(r"(?<![\w.])@\s*(?=\w)")
# "queuing 4 the printers", "goes 2 the café": chat's "for" and "to" before a determiner, after a word
# (not "at 4 the doors open", "from 2 the queue grows": a time)
_FOR_TO = re.compile(r"(?<=[A-Za-z])(?<!\bat)(?<!\bby)(?<!\bfrom)(?<!\buntil)(?<!\btill)(?<!\bafter)(?<!\bbefore)"
                     r"(?<!\bsince)(?<!\bto)(?<!\bof)(?<!\bor)(?<!\band)\s+([24])\s+(?=(?:the|his|her|their|my|our|your|its)\b)",
                     re.IGNORECASE)
# "8 ppl waiting @ customer service 4 refunds": chat's "for" before the last word, a plural that names no
# person (not "... 4 nurses"), after a word that is not one a place is numbered by ("till 4", "gate 4")
# A chat list's item ends at its comma as the prompt ends ("6 pts queuin 4 scales, 3 more in waiting rm").
_FOR_LAST = re.compile(r"(?<=[A-Za-z])(?<!\bat)(?<!\bfor)(?<!\bto)(?<!\bof)(?<!\band)(?<!\bor)(?<!\bwith)"
                       r"\s+4\s+([a-z]+s)(?=\s*(?:[,;]|[.!]?\s*$))")
_NUMBERED_BY = frozenset("gate desk platform room aisle till lane court ward bay stand floor level exit door counter "
                         "table bed screen track pier dock berth stop zone area block wing unit".split())
# "~30 pax", "~ 10 people": about so many (read before "+"/"&" join items, so "hut + ~10 juniors" is two)
_TILDE = re.compile(r"(?<![\w~])~\s*(?=\d)")
_NUMBER_WORD = r"(?:twenty|thirty|forty|fifty|sixty|seventy|eighty|ninety|hundred|ten|eleven|twelve|[a-z]+teen)"
# "a dozen-ish kids", "half a dozen-ish": a dozen or so
_DOZEN_ISH = re.compile(r"\b(?:(a|half\s+a)\s+)?dozen\s*-?\s*ish\b", re.IGNORECASE)

# "swimmers x10", "nurses (x3)", "shoppers ×20": so many of them; "10x shoppers", "x3 porters": so many
_TIMES_AFTER = re.compile(r"\b([A-Za-z]{3,})(?:\s+|\s*\(\s*)[x×]\s?(\d+)\s*\)?(?![\w.])")
_TIMES_BEFORE = re.compile(r"(?<![\w.])(?:(\d+)\s?[x×]|[x×](\d+))\s+(?=[A-Za-z]{3,})")

# "15+ guests", "20+ ppl": at least that many (not "2 nurses + 1 porter", which joins two groups)
_PLUS_COUNT = re.compile(r"(?<![\w.])(\d+)(?:\+|\s+\+(?!\s))(?=\s*[A-Za-z])")
# "ten-plus guests", "40-plus fans": at least so many, the word written out
_PLUS_WORD = re.compile(r"\b(\d+|" + _NUMBER_WORD + r")\s*-\s*plus\b(?=\s+[A-Za-z])", re.IGNORECASE)
# "n=20 pedestrians", "N = 8 agents": a count as a researcher writes it
_N_EQUALS = re.compile(r"(?<![\w=])[nN]\s*=\s*(?=\d)")
# "gate A1 -> security", "lobby → lifts": a route; a short place after a colon or comma is where they set off
_ROUTE_ARROW = re.compile(r"([:,;(]\s*|^)((?:[\w'-]+\s+){0,3}[\w'-]+)\s*(?:-+>|→|⟶|=>)\s*")
_ARROW = re.compile(r"\s*(?:-+>|→|⟶|=>)\s*")

# "a second-year", "two first-years": students of that year ("a first-year lecture" names no one).
_YEAR_PERSON = re.compile(r"\b(first|second|third|fourth|final|1st|2nd|3rd|4th)-year(s?)\b(?![- ]?(?:students?|"
                          r"undergrad\w*|pupils?|lectures?|class\w*|courses?|modules?|exams?|groups?|seminars?|"
                          r"tutorials?|rooms?|labs?|halls?|projects?)\b)", re.IGNORECASE)

# "does its rounds of the gallery", "is making the rounds", "goes on its rounds": patrols.
# Words people also write apart or hyphenated that the reader knows joined ("newly-weds", "after school
# club"): written joined before parsing, so the parser takes one word and not a preposition or an adverb.
_JOINED = re.compile(r"\b(newly|after)[- ](weds?|school)\b", re.IGNORECASE)
# "the in-store chemist", "the on-site café": of the place the scene is in, so the place's own name.
_OF_THIS_PLACE = re.compile(r"\b(?:in|on)\s*-\s*(?:store|site|house|campus|premises|station)\s+(?=[A-Za-z])", re.IGNORECASE)
# A game named by its side's size ("five-a-side", "7-a-side") is one word, not a count of people.
_A_SIDE = re.compile(r"\b([A-Za-z]+|\d+)\s*-\s*a\s*-\s*side\b", re.IGNORECASE)
_ROUNDS = re.compile(r"\b(do|does|did|done|doing|make|makes|made|making|go\s+on|goes\s+on|went\s+on|gone\s+on|"
                     r"going\s+on)\s+(?:its|his|her|their|the|our|my)\s+rounds\b(?:\s+(?:of|in|through|around|round)\b)?",
                     re.IGNORECASE)
_PATROL_FORMS = {"do": "patrol", "make": "patrol", "does": "patrols", "makes": "patrols", "goes": "patrols",
                 "go": "patrol", "did": "patrolled", "made": "patrolled", "done": "patrolled", "went": "patrolled",
                 "gone": "patrolled", "doing": "patrolling", "making": "patrolling", "going": "patrolling"}


def normalise(text: str) -> str:
    """The prompt as the reader parses it (see the module doc); "" when nothing readable is left."""
    folded = unicodedata.normalize("NFKC", text or "")
    kept = "".join(" " if unicodedata.category(ch) in _DROPPED_CATEGORIES or _variation_selector(ch) else ch
                   for ch in folded)
    kept = towards_for_direction(names_unstopped(with_robot_spelt(kept)))  # "scared of the robto": the robot  # "the T. rex", "St. Mary's ward": no sentence end
    kept = robot_sent(robot_chat(some_one(chat_years(spell_out(count_words_spelt(kept))))))  # "walkin frm", "robo shd wait": chat's dropped g, short words
    kept = placing_lists(placing_verbs(kin_counts(chat_lists(chat_people(as_paired_kin(kept))))))  # "a father-and-daughter pair": "a father-daughter pair"  # "... n 3 drivers @", "Post a trio ...", "twin toddlers"
    kept = _JOINING_SIGN.sub(" and ", _PLUS_COUNT.sub(r"at least \1", _PLUS_WORD.sub(r"at least \1", _TILDE.sub("about ", kept))))
    kept = _ARROW.sub(" to ", _ROUTE_ARROW.sub(_route_start, _N_EQUALS.sub("", kept)))
    kept = _TIMES_BEFORE.sub(lambda m: f"{m.group(1) or m.group(2)} ", _TIMES_AFTER.sub(r"\2 \1", kept))
    kept = _DOZEN_ISH.sub(lambda m: f"{m.group(1) or 'a'} dozen or so", kept)
    kept = ish_counts(_TILDE.sub("about ", _AT_SIGN.sub("at ", kept)))  # "the 200-ish fans", "30ish"
    kept = _FOR_TO.sub(lambda m: " for " if m.group(1) == "4" else " to ", kept)
    kept = _FOR_LAST.sub(_for_the_last, kept)
    kept = _CHAT_WORD.sub(lambda m: _spelled_out(m.group(1)), kept)
    kept = _JOINED.sub(lambda m: f"{m.group(1)}{'-' if m.group(1).lower() == 'after' else ''}{m.group(2)}", kept)
    kept = commas_for_brackets(places_first(kept))  # "dorm 1 asleep (3 ppl)"; "the school group (25 children) walks"
    kept = _OF_THIS_PLACE.sub("", _A_SIDE.sub(r"\1aside", kept))
    kept = _YEAR_PERSON.sub(lambda m: m.group(0) if year_of_people(kept, m.end()) else f"{m.group(1)} year student{m.group(2)}", kept)  # "third-year law students"
    kept = _ROUNDS.sub(lambda m: _PATROL_FORMS[m.group(1).split()[0].lower()], kept)
    kept = kept_away(where_commas(kept))  # "keeping away from the kitchen": avoiding it; "the boardroom where eight people are": the people a group of their own
    kept = without_posture_before_going(kept)  # "shuffles on his knees after the robot": after it
    return " ".join(bare_items(kept).split())  # "..., intern at printer": one person, an item of its own


def _for_the_last(m: re.Match[str]) -> str:
    """"... customer service 4 refunds" as "... for refunds"; a count of people or of minutes, or a
    numbered place, is kept."""
    before = m.string[:m.start()].split()
    word = lemma(m.group(1))
    if word in PERSON_NOUNS or word in DURATION_UNITS or word.rstrip("s") in DURATION_UNITS or (before and before[-1].lower() in _NUMBERED_BY):
        return m.group(0)
    return f" for {m.group(1)}"


def _route_start(m: re.Match[str]) -> str:
    """"12 agents: gate A1 -> security" as "12 agents: from gate A1 to security"; a phrase that
    already says where from, or one that names people ("12 agents -> security"), only gets its "to"."""
    said = m.group(2)
    if said.split()[0].lower() in ("from", "to") or any(lemma(w) in PERSON_NOUNS for w in said.split()):
        return f"{m.group(1)}{said} to "
    return f"{m.group(1)}from {said} to "


def _variation_selector(ch: str) -> bool:
    """Emoji presentation selectors ("⚕️" is U+2695 U+FE0F), marks of no letter."""
    code = ord(ch)
    return 0xFE00 <= code <= 0xFE0F or 0xE0100 <= code <= 0xE01EF


def _spelled_out(word: str) -> str:
    full = CHAT_WORDS[word.lower()]
    return full[:1].upper() + full[1:] if word[:1].isupper() else full


def plain(word: str) -> str:
    """The word without accents ("café" -> "cafe"), as world names are written."""
    if word.isascii():
        return word
    return unicodedata.normalize("NFKD", word).encode("ascii", "ignore").decode() or word
