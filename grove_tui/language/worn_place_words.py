"""What people wear when the world calls a place by the same word: "nine tots in armbands troop from
group changing" (a swimming bath's goggles rack is also "armbands"), "four drivers in helmets walk from
the kit room" (the helmet racks), "three scientists in gowns walk from the lab" (the gown rack). Read as
a place, the clothes became where the people start and pushed the place said after "from" out. Worn
things say nothing of where anyone is, so "in"/"wearing" and the worn words are left out after a word
for people, whatever verb follows; with "the" ("in the costume store") or a following place word ("in
kit room 2", "in the helmet store") the phrase is a place still."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from grove_tui.language.tokens import lemma
from grove_tui.language.worn_clothes import _CLOTHES, _names_a_place, _person

if TYPE_CHECKING:
    from grove_tui.language.places import PlaceIndex

# Worn things the clothes list lacks: swimming aids, passes and badges, protective wear.
_MORE = ("armbands? water\\s+wings rubber\\s+rings? lanyards? wristbands? name\\s+badges? badges? bibs? hairnets? "
         "ear\\s+defenders earmuffs headphones headsets? knee\\s+pads shin\\s+pads pinafores? tutus? leotards? "
         "slippers harness(?:es)? skates nappies ppe visors? swim\\s+caps? swimming\\s+caps? race\\s+suits? "
         "lab\\s+coats? white\\s+coats? hard-hats?").split()
_WORN_WORDS = "|".join(sorted(_CLOTHES + _MORE, key=len, reverse=True))
_WORN = re.compile(
    rf"\b(?P<person>[A-Za-z][A-Za-z-]*)(?P<worn>,?\s+(?:in|wearing|dressed\s+in|clad\s+in|kitted\s+out\s+in)\s+"
    rf"(?P<mods>(?:(?:his|her|their|matching|full|bright|dark|smart|long|little|tiny|orange|yellow|red|blue|"
    rf"green|white|black|pink|purple|new|old|[a-z]+-[a-z]+)\s+){{0,2}})"
    rf"(?P<thing>{_WORN_WORDS}))\b(?P<after>\s*(?P<next>[A-Za-z-]*))", re.IGNORECASE)
_NEVER_A_PLACE_CUE = frozenset("room rooms store stores rack racks rail rails shop shops desk counter area bay "
                               "cupboard locker lockers display stand pegs hooks station".split())

def without_worn_place_words(text: str, index: PlaceIndex) -> str:
    """The text without what people wear where the world also names a place by it (module doc)."""
    def drop(m: re.Match[str]) -> str:
        thing = m.group("thing").lower().split()
        nxt = m.group("next").lower()
        if not _person(m.group("person")) or nxt in _NEVER_A_PLACE_CUE or (nxt and _names_a_place(index, lemma(thing[-1]), lemma(nxt))):
            return m.group(0)  # "a guard in kit room 2", "drivers in helmet racks": a place
        if not any(index.knows(lemma(w)) or index.knows(w) for w in thing):
            return m.group(0)  # worn words no place is called by: left to the rules of clothes
        return m.group(0)[:m.start("worn") - m.start(0)] + m.group("after")
    return _WORN.sub(drop, text)
