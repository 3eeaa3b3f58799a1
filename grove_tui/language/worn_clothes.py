"""What a person wears after "in", "wearing" or "dressed in" (round 34): "a diver in a wetsuit pads from
...", "four players in concert black wait backstage", "two medics in scrubs", "a guard in hi-vis". Read
as a place, the clothes were refused as a place the world lacks ("wetsuit pads") and the person, run
into it, was lost. Clothes say nothing of where anyone is or how many there are, so the phrase is left
out after a word for people (or a counted plural no list names: "nine cub scouts in party hats, ...")
where it runs into a verb in "-s", ends an aside or is theirs ("regulars in their best coats wait in the
foyer", in a world with coat rails); a place named with a clothing word ("in the uniform store", "the kit room"
of the world) is a place still."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

if TYPE_CHECKING:
    from grove_tui.language.places import PlaceIndex

_CLOTHES = ("wetsuits? drysuits? scrubs hi-vis hi-viz high-vis high-viz uniforms? overalls? boiler\\s+suits? suits? "
            "jackets? coats? raincoats? anoraks? cagoules? parkas? fleeces? hoodies? tracksuits? tabards? aprons? "
            "gowns? robes? dresses? frocks? skirts? kilts? saris? jeans trousers shorts leggings lycra leathers "
            "waterproofs wellies wellingtons waders trainers boots sandals flip-flops helmets? hard\\s+hats? hats? "
            "gloves caps? beanies? bobble\\s+hats? balaclavas? masks? sunglasses shades glasses goggles vests? t-shirts? "
            "shirts? jumpers? sweaters? cardigans? blazers? waistcoats? tuxedos? dinner\\s+jackets? pyjamas "
            "pajamas dressing\\s+gowns? onesies? costumes? fancy\\s+dress fatigues camouflage camo whites blacks "
            "black white red blue green yellow orange pink purple grey gray navy tweed denim kit gear livery "
            "cassocks? habits? wimples? turbans? headscarf headscarves hijabs? burkas? niqabs? veils? "
            "sashes? scarf scarves bikinis? swimsuits? swimming\\s+costumes? trunks ponchos? capes? cloaks? togas? "
            "black\\s+tie tails").split()
_CLOTHING = "|".join(sorted(_CLOTHES, key=len, reverse=True))
_WORN = re.compile(rf"(?:\b(?P<det>[A-Za-z]+)\s+)?(?P<person>\b[A-Za-z][A-Za-z-]*)(?P<worn>,?\s+(?:in|wearing|dressed\s+in|clad\s+in|kitted\s+out\s+in)"
                   rf"\s+(?:(?:a|an|the|his|her|their|matching|full|bright|dark|smart|long|white|black|red|blue|"
                   rf"green|yellow|orange|pink|grey|navy|[a-z]+-[a-z]+|[a-z]+)\s+){{0,3}}"
                   rf"(?:{_CLOTHING}))(?P<after>\b[,.;:!?]?\s*(?P<next>[A-Za-z-]*))", re.IGNORECASE)
_PERSON_ENDS = ("er", "ers", "or", "ors", "ist", "ists", "ian", "ians", "ee", "ees", "ic", "ics", "man", "men",
                "woman", "women", "people", "folk", "lad", "lads", "girl", "girls", "boy", "boys", "kid", "kids")
_NOT_PEOPLE = frozenset("water paper corner number order letter power centre center floor door lobby hour".split())


_COLOURS = frozenset("black white red blue green yellow orange pink purple grey gray navy tweed denim camo "
                     "camouflage whites blacks kit gear livery".split())
_DETERMINERS = frozenset("a an one two three four five six seven eight nine ten some several few".split())


def _names_a_place(index: PlaceIndex, first: str, second: str) -> bool:
    """Whether two words said one after the other are in a place's name ("kit room", "coat rack")."""
    return any(first in phrase and phrase.index(first) + 1 < len(phrase) and phrase[phrase.index(first) + 1] == second
               for entry in index.entries for phrase in entry.phrases)


def _person(word: str) -> bool:
    low = word.lower()
    if low in _NOT_PEOPLE or low in lx.ROBOT_WORDS:
        return False
    return lemma(low) in lx.PERSON_NOUNS or low in lx.PERSON_NOUNS or low.endswith(_PERSON_ENDS)


_NUMBER = re.compile(r"\b(?:\d+|" + "|".join(sorted((w for w in lx.NUMBER_WORDS if w.isalpha()), key=len, reverse=True)) +
                     r")(?:-[a-z]+)?\s+(?:[A-Za-z][A-Za-z-]*\s+){0,2}$", re.IGNORECASE)


def _counted_before(text: str, at: int) -> bool:
    """Whether a count stands at most two words before the plural at `at` ("nine cub scouts in party hats"):
    people, though no list names the noun."""
    return _NUMBER.search(text[max(0, at - 40):at]) is not None


def without_worn_clothes(text: str, index: PlaceIndex) -> str:
    """The text without what people wear after a word for people (module doc)."""
    def drop(m: re.Match[str]) -> str:
        worn_words = m.group("worn").lower().replace(",", " ").split()
        nxt = m.group("next").lower()
        after = m.group("after").strip()
        place_word = any(index.knows(lemma(w)) for x in worn_words[1:-1] for w in x.split("-"))
        owned = any(w in ("his", "her", "their", "my", "our", "your") for w in worn_words[1:-1])
        if not after[:1] in (",", ";") and (not (nxt.endswith("s") and not nxt.endswith("ss")) or
                                            worn_words[-1] in _COLOURS) and not place_word and not owned:
            return m.group(0)  # "two medics in scrubs walk", "women in pink sashes": read as it is
        # but "regulars in their best coats wait": clothes someone owns are no room, whatever follows
        # but "a couple in paint-spattered jeans wander": no paint department in their clothes
        word = m.group("person").lower()
        if word in lx.ROBOT_WORDS or word in _NOT_PEOPLE or \
                not (_person(word) or (m.group("det") or "").lower() in _DETERMINERS or _counted_before(text, m.start("person"))) or \
                (nxt and _names_a_place(index, lemma(worn_words[-1]), lemma(nxt))) or \
                (worn_words[1] == "the" and index.knows(lemma(worn_words[-1]))):
            return m.group(0)
        return m.group(0)[:m.start("worn") - m.start(0)] + m.group("after")
    return _WORN.sub(drop, text)
