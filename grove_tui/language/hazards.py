"""Hazards said as a narrative, and the things named as their cause (round 14).

The lexicon's hazard nouns ("fire", "smoke", "a gas leak") make leaving an evacuation when named on
their own. People also say a hazard by what they notice ("a smell of burning", "fumes", "sparks"), by
an alarm that goes off ("the fire alarm goes off", "alarms are sounding") or by a thing that fails
("a burst pipe", "the kitchen is on fire"): each is a hazard cue here.

A hazard's cause is often a thing ("smell of burning from the toaster", "smoke in the kitchen bin"):
a place phrase that hangs off the hazard, with no person in its clause, names where the hazard is,
not where anybody goes or is, so a thing the world lacks there is no place to refuse. A room kind the
world lacks ("smoke from the boiler room") is still refused: people would be sent there or from there.
"""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.calm_alarms import calm_alarm as calm_alarm
from grove_tui.language.cue_in_names import in_a_place_name as in_a_place_name
from grove_tui.language.gas_leaks import gas_cue
from grove_tui.language.giving_off import giving_off_cue
from grove_tui.language.hazard_events import event_cue
from grove_tui.language.hazard_scares import scare_cue
from grove_tui.language.outside_sources import outside_at
from grove_tui.language.place_kinds import PLACE_KINDS
from grove_tui.language.sentence import Sentence
from grove_tui.language.trouble_events import trouble_cue
from grove_tui.language.weather_damage import damage_cue

# Nouns that say a hazard by what is noticed ("fumes", "sparks"), beside the lexicon's hazard nouns.
_NOTICED = frozenset("fumes sparks burning blaze gas siren sirens flame flames".split())
# Words after "smell of" / "smell" that make a smell a hazard ("a smell of burning", "smells of gas").
_SMELLS = frozenset("burning smoke gas fumes fire petrol chemicals".split())
# An alarm's verbs of sounding ("the alarm goes off", "alarms are sounding", "the fire alarm rings",
# "the fire alarm trips").
_SOUNDING = frozenset("go goes went going gone sound sounds sounded sounding ring rings rang ringing "
                      "blare blares blaring trigger triggers triggered wail wails wailing "
                      "trip trips tripped tripping".split())
_ALARMS = frozenset({"alarm", "alarms", "siren", "sirens", "bell", "bells"})
# A bell is an alarm only when said as one ("the fire bell", "alarm bells"): "when the bell goes at
# 8 pm" ends visiting time or a lesson, and people then walk out.
_BELL_ALARMS = frozenset("fire alarm alarms emergency evacuation warning".split())
# Things that fail into a hazard ("a burst pipe", "a burst water main").
_BURST = frozenset({"pipe", "pipes", "main", "mains", "boiler", "tank"})
# Heads of phrases that name a room, not a thing: a cause said in one is still a place to refuse (the
# kinds of place a world may lack, the lexicon's words for places, and rooms by their usual names).
ROOM_HEADS = lx.GENERIC_PLACE_HEADS | lx.BUILDING_WORDS | lx.OUTDOOR_WORDS | lx.DOOR_WORDS | \
    frozenset(w for kind in PLACE_KINDS for w in kind.split("_")[-1:]) | \
    frozenset(w for group in lx.PLACE_SYNONYMS for w in group) | frozenset(
    "room kitchen office hall lab laboratory ward basement cellar loft attic garage shop store storeroom "
    "stockroom corridor lobby lounge canteen cafeteria cafe café toilet toilets bathroom "
    "washroom library gym studio theatre chamber suite wing floor level plant depot warehouse yard gallery "
    "classroom cinema bar pub restaurant pool court garden terrace balcony platform bay gate".split())
# Prepositions that say where a hazard comes from or is ("from the toaster", "in the bin").
_CAUSE_PREPOSITIONS = frozenset("from in inside behind under near by at out of".split())


def cue(s: Sentence, i: int) -> bool:
    """Whether the word at i says a hazard by what is noticed, an alarm going off or a thing failing."""
    low = s.low
    w = low[i]
    nxt = low[i + 1] if i + 1 < s.n else ""
    after = low[i + 2] if i + 2 < s.n else ""
    if w in _NOTICED and s.w[i].pos in ("NOUN", "PROPN", "VERB") and not (w == "gas" and nxt not in ("leak", "leaks")):
        return w != "burning" or (i >= 2 and low[i - 2].startswith("smell"))  # "smell of burning"
    if w.startswith("smell") and (nxt in _SMELLS or (nxt == "of" and after in _SMELLS)):
        return True
    if w in ("bell", "bells") and not (i > 0 and low[i - 1] in _BELL_ALARMS):
        return False
    if w in _ALARMS and not calm_alarm(s, i) and (nxt in _SOUNDING or (nxt in ("is", "are", "has", "have", "starts", "start") and after in _SOUNDING)):
        return True  # "the alarm goes off", "alarms are sounding"
    if w == "burst" and (nxt in _BURST or after in _BURST):
        return True
    if event_cue(s, i) or gas_cue(s, i) or scare_cue(s, i) or giving_off_cue(s, i) or damage_cue(s, i) or \
            trouble_cue(s, i):  # "a pipe bursts", "a heater sparks"
        return True
    # "catches fire", and the British "catches light" / "caught light" (never "catches the light": a shine).
    return w == "on" and nxt == "fire" or w in ("ablaze", "alight") or (
        (w.startswith("catch") or w == "caught") and nxt in ("fire", "light"))


def said(s: Sentence) -> bool:
    """Whether the prompt says a hazard in one of these ways anywhere."""
    return any(cue(s, i) for i in range(s.n))


def cause_thing(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether the phrase from word k, after the preposition at `at`, names the cause of a hazard
    said just before it in a clause with nobody in it ("smell of burning from the toaster", "smoke
    in the kitchen bin"), a thing rather than a room (see the module doc)."""
    if prep not in _CAUSE_PREPOSITIONS:
        return False
    start = at
    while start > 0 and not s.is_punct(start - 1) and s.low[start - 1] not in lx.CLAUSE_STARTERS and \
            s.w[start - 1].sentence == s.w[at].sentence:
        start -= 1
    before = range(start, at)
    if not any(cue(s, x) or (s.lemma(x) in lx.HAZARD_NOUNS or s.low[x] in lx.HAZARD_NOUNS) and s.w[x].dep != "compound"
               for x in before):
        return False
    if any(s.low[x] in lx.PERSONAL_PRONOUNS or s.lemma(x) in lx.PERSON_NOUNS for x in before):
        return False  # "the cook in the kitchen smells burning": a person's place
    end = k
    while end < s.n and not outside_at(s, end) and (s.w[end].pos in ("DET", "ADJ", "NOUN", "PROPN", "NUM") or
                                                 s.low[end] in ("'s", "’s")):
        end += 1
    if end > k and end < s.n and outside_at(s, end):
        return True  # "from a bonfire next door": outside the building, no place of it
    heads = [s.lemma(x) for x in range(k, end) if s.w[x].pos in ("NOUN", "PROPN")]
    return bool(heads) and heads[-1] not in ROOM_HEADS and s.low[end - 1] not in ROOM_HEADS
