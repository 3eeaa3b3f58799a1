"""People typed as chat (round 26), written out before the prompt is parsed.

- short words of people: "pt + porter waiting @ lifts" (a patient), "guy n his gf" (girlfriend),
  "bf", "bro", "sis", "custs";
- " n " before a possessive or a person joins two people: "guy n his gf", "bf n gf": "and";
- a bare count before what its people do, as an item of a list: "5 browsing seed packets n 3 nr
  cacti", "4 queuing at the cafe, 2 by the fountain": "5 people browsing ...".
"""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.ordered_counts import ordered_before_a_place
from grove_tui.language.tokens import lemma, verb_lemma

# Whole words, lower case only ("PT" may be a name or a lesson).
_SHORT_PEOPLE = {"pt": "patient", "pts": "patients", "gf": "girlfriend", "gfs": "girlfriends", "bf": "boyfriend",
                 "bfs": "boyfriends", "bro": "brother", "bros": "brothers", "sis": "sister", "cust": "customer",
                 "custs": "customers", "vols": "volunteers", "oaps": "pensioners"}
_SHORT = re.compile(r"(?<![\w'/@&.-])(" + "|".join(sorted(_SHORT_PEOPLE, key=len, reverse=True)) + r")(?![\w'/@&-])")
_N_POSSESSIVE = re.compile(r"(?<=\w)\s+n\s+(?=(?:his|her|their|my|our|its)\b)")
_N_PERSON = re.compile(r"(?<=\w)\s+n\s+(?=([a-z]+)\b)")
_NUMBER = r"(?:\d+|" + "|".join(sorted((w for w in lx.NUMBER_WORDS if w.isalpha() and w not in
                                         ("couple", "pair", "handful", "dozens")), key=len, reverse=True)) + r")"
_BARE_COUNT = re.compile(r"(^|[,;+&]\s*|\b(?:and|n|while|plus)\s+|(?:^|[.!?]\s+)(?:Have|Get|Put|Keep|Leave)\s+)(" + _NUMBER + r")\s+([a-z]+ing)\b(?=\s+(\w+))",
                         re.IGNORECASE)
# What people do, said by a bare count: "5 browsing", "4 queuing", "2 chatting".
_DOING = frozenset("browse queue queueing wait sit stand chat talk wander stroll walk mill hang shop eat drink look line "
                   "loiter linger gossip read work lounge relax rest head hover huddle gather sleep doze play "
                   "run jog smoke argue laugh pray sing dance study do doing".split())  # "doing": kept whole by the lemmatiser
# Nouns a "-ing" word makes with a count: "5 waiting rooms", "2 parking spaces".
_ING_NOUNS = frozenset("room rooms area areas space spaces bay bays lane lanes spot spots point points station "
                       "stations desk desks hall halls list lists bench benches machine machines".split())


def chat_people(text: str) -> str:
    """The text with people typed as chat written out (see the module doc)."""
    text = _SHORT.sub(lambda m: _SHORT_PEOPLE[m.group(1)], text)
    text = _N_POSSESSIVE.sub(" and ", text)
    text = _N_PERSON.sub(lambda m: " and " if lemma(m.group(1)) in lx.PERSON_NOUNS else m.group(0), text)
    return _BARE_COUNT.sub(_counted_people, text)


def _counted_people(m: re.Match[str]) -> str:
    doing = m.group(3).lower()
    if verb_lemma(doing) not in _DOING or m.group(4).lower() in _ING_NOUNS:
        return m.group(0)
    if ordered_before_a_place(m.group(1), m.group(4)) is False:
        return m.group(0)  # "Have two shopping bags": an order's count before a place only ("Have two waiting in")
    return f"{m.group(1)}{m.group(2)} people {m.group(3)}"
