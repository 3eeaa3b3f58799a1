"""Things someone has with them, counted (round 29): "a delivery driver with two crates of milk hangs
about", "a porter with three cages of linen waits", "a lad with four sacks walks". The reader took the
counted plural no list names for a group of people of their own beside the one who has them; a count
of containers, or of anything "of" a stuff, after "with" is what they carry, and the phrase only
describes its carrier, so it is left out before the sentence is read ("a delivery driver hangs
about"). A count of people ("a teacher with thirty Brownies", "with two friends of hers") is kept."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx

# Containers and loads counted after "with" ("two crates", "six sacks"): things, whatever follows.
CONTAINERS = frozenset("""crate box bag sack case tray carton pallet tub bucket bottle can jar parcel package
basket cage barrel keg tin pack packet bundle armful bin hamper roll trunk suitcase holdall rucksack
backpack flask churn drum canister""".split())
_COUNT = r"(?:\d+|a couple of|a pair of|a few|several|a dozen|" + \
    "|".join(sorted((w for w in lx.UNITS if w.isalpha() and w not in ("one", "zero")), key=len, reverse=True)) + ")"
_LOAD = re.compile(r"\s+with\s+(?:" + _COUNT + r")\s+([a-z]+)(\s+of\s+(?!the\b|his\b|her\b|their\b|them\b|us\b)[a-z]+)?\b",
                   re.IGNORECASE)


def without_counted_loads(text: str) -> str:
    """The text with "with two crates of milk" after its carrier left out (see the module doc)."""
    def dropped(m: re.Match[str]) -> str:
        noun = m.group(1).lower()
        single = noun[:-3] + "y" if noun.endswith("ies") else noun[:-2] if noun.endswith(("xes", "ches", "shes")) \
            else noun[:-1] if noun.endswith("s") else noun
        if single in lx.PERSON_NOUNS or noun in lx.PERSON_NOUNS or single in lx.NON_PEOPLE:
            return m.group(0)
        return "" if single in CONTAINERS or m.group(2) else m.group(0)
    return _LOAD.sub(dropped, text)
