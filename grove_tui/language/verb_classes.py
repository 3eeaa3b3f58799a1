"""Verbs of what people do that the lexicon's intent lists lack, read by class (round 13c).

The lexicon maps a verb's base form to an intent; these are the classes it misses, each a rule
rather than a word:
- a means of moving: a vehicle driven or ridden, or a thing pushed along ("drives to bay 4",
  "cycles", "scoots", "pushes a pram"), is a walk even when the place is one the world lacks, since
  the verb itself says they move;
- a way taken by its means ("take the lifts", "ride the escalator", "catch the shuttle"): the plural
  and the means words count, not only the lexicon's singular passage words;
- phrasal verbs of an activity ("do laps of", "stretch their legs", "kill time", "take a seat");
- a verb of motion followed by "round"/"around" past an adverb ("walk slowly round the gallery") with
  nowhere to go is wandering there;
- "pace" in "at a snail's pace" is manner, not the verb "to pace".
"""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.escaped_people import escapes_a_person
from grove_tui.language.activity_nouns import ACTIVITY_PHRASES
from grove_tui.language.spanned_intents import spanned_intent
from grove_tui.language.hauled_loads import hauls_a_load
from grove_tui.language.going_verbs import THING_TAKING_VERBS, carries_a_thing_to, more_verb_intent
from grove_tui.language.leaving import LEAVING_PHRASES, LEAVING_VERBS
from grove_tui.language.going_idioms import setting_out
from grove_tui.language.queue_lines import lined_queue
from grove_tui.language.run_objects import runs_a_thing
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Verbs of moving in or on something: a walk, whatever the world knows of where to.
VEHICLE_VERBS = frozenset("drive ride cycle bike pedal scoot skate skateboard rollerblade motor wheel taxi".split())
# Verbs of moving a thing along by hand: a walk when what is moved is something people are carried
# or shop in ("pushes a pram", "pulls a trolley"), not "pushes a button".
PUSHING_VERBS = frozenset("push pull tow drag steer trundle".split())
# Means of moving taken by a verb of taking ("take the shuttle"), beside the lexicon's passage words.
MEANS_WORDS = frozenset("lift lifts elevators escalators stair travelators shuttle shuttles monorail "
                        "paternoster ramps".split())
# Verbs whose object is a way or a means taken: "take the lifts", "ride the escalator".
WAY_TAKING_VERBS = lx.ROUTE_OBJECT_VERBS | frozenset({"ride", "catch"})
# Phrasal verbs of an activity the lexicon's phrases lack; the first word is a verb's base form.
_OWN = ("their", "his", "her", "my", "our")
# Verbs that go round a place by laps or circuits ("does laps of", "walks circuits of", "jogs a loop of").
_LAPPING = ("do", "walk", "run", "jog", "swim", "cycle", "complete", "make", "pace", "lap")
_HOW_LAPS = ("slow", "quick", "brisk", "gentle", "leisurely", "endless", "several", "more", "two", "three", "ten")
MORE_PHRASAL_INTENTS: dict[tuple[str, ...], str] = {
    **{(verb, *what): "wander" for verb in _LAPPING for what in (
        ("laps",), ("a", "lap"), ("lengths",), ("a", "length"), ("circuits",), ("a", "circuit"), ("a", "loop"),
        ("loops",), ("a", "lap", "of"), ("a", "few", "laps"), ("a", "couple", "of", "laps"), ("some", "laps"),
        *((how, rounds) for how in _HOW_LAPS for rounds in ("laps", "circuits", "loops", "lengths")))},
    **{("stretch", own, "legs"): "wander" for own in _OWN},
    ("have", "a", "wander"): "wander", ("have", "a", "stroll"): "wander", ("have", "a", "look", "round"): "wander",
    ("have", "a", "look", "around"): "wander", ("look", "round"): "wander", ("walk", "round"): "wander",
    ("wander", "round"): "wander", ("mill", "round"): "wander", ("potter", "about"): "wander",
    ("kill", "time"): "wait", ("take", "a", "seat"): "wait", ("grab", "a", "seat"): "wait",
    ("take", "a", "breather"): "wait", ("sit", "about"): "wait", ("sit", "around"): "wait",
    ("stand", "about"): "wait", ("stand", "round"): "wait",
    # "duck out of the lounge for a coffee", "ducks into the shop": going, not dodging (issue 29)
    **{("duck", way): "walk" for way in ("out", "into", "in", "across", "over", "down", "up", "round", "back")},
}
# Leaving phrases first: "make a run for it" is a whole phrase before the lexicon's "make a run".
PHRASAL_INTENTS: dict[tuple[str, ...], str] = {**LEAVING_PHRASES, **lx.PHRASAL_INTENTS, **MORE_PHRASAL_INTENTS,
                                              **ACTIVITY_PHRASES}  # nouns of activity: "have a natter"
# The phrases by their first word, each list in PHRASAL_INTENTS's order (its order decides between
# phrases that start alike): a reading looks up a verb's few phrases, not all two thousand.
_PHRASES_BY_FIRST: dict[str, list[tuple[int, tuple[str, ...], str]]] = {}
for _order, (_phrase, _intent) in enumerate(PHRASAL_INTENTS.items()):
    _PHRASES_BY_FIRST.setdefault(_phrase[0], []).append((_order, _phrase, _intent))
_AROUND = frozenset({"around", "about", "round"})
# Words after "round" that say where to: "round to the bar", "round into the yard".
_ON_TO = frozenset({"to", "into", "towards", "toward", "onto"})


def base(s: Sentence, i: int) -> str:
    """A verb's base form: the sentence's, then by its ending for a verb of moving the lexicon lacks
    ("cycles", "scooting", "rode"; the parser often calls "cycles" a noun)."""
    v = s.verb(i)
    if v in VEHICLE_VERBS or v in PUSHING_VERBS:
        return v
    w = s.low[i]
    if w in ("rode", "ridden", "drove", "driven"):
        return "ride" if w[0] == "r" else "drive"
    for cut, add in ((1, ""), (2, ""), (3, ""), (3, "e"), (2, "e"), (1, "e"), (4, "")):
        stem = w[:-cut] + add if len(w) > cut + 2 else ""
        if w.endswith(("s", "ing", "ed", "d")) and (stem in VEHICLE_VERBS or stem in PUSHING_VERBS):
            return stem
    return v


def verb_intent(s: Sentence, i: int) -> str | None:
    """The intent the verb at i gives its people: the lexicon's, or walking for a verb of moving in or
    with something; None for "pace" in a phrase of manner ("at a brisk pace")."""
    v = s.verb(i)
    if s.low[i] in ("pace", "crawl") and any(s.low[k] == "at" for k in range(max(0, i - 4), i)):
        return None  # "walk at a snail's pace", "move at a crawl": how fast, not pacing about
    if _object_noun(s, i):
        return None  # "swap a failed drive in row B": a thing worked on, no driving
    if runs_a_thing(s, i):
        return None  # "actors run lines in the green room": a thing done there, no running
    if escapes_a_person(s, i):
        return "walk"  # "a toddler escapes from his mum": going off, no evacuation
    if v in lx.INTENT_VERBS:
        return lx.INTENT_VERBS[v]
    if v in LEAVING_VERBS or verb_lemma(s.low[i]) in LEAVING_VERBS:
        return "walk"  # "two carers bail", "the kids scarper"
    b = base(s, i)
    if b in VEHICLE_VERBS and not s.after_determiner(i):
        return "walk"
    if b in PUSHING_VERBS and any(s.lemma(k) in lx.CARRYING_THINGS for k in range(i + 1, min(i + 5, s.n))):
        return "walk"  # "pushes a pram to the café", "a porter pulls a trolley"
    if hauls_a_load(s, i):
        return "walk"  # "pull their wheelie cases from the check-in hall to gate A2"
    return more_verb_intent(s, i)  # "mooch around", "takes her lunch to the lounge"


def phrasal_intent(s: Sentence, i: int) -> tuple[tuple[str, ...], str] | None:
    """The phrasal verb starting at i and its intent ("line up", "do laps", "stretches her legs")."""
    first = {verb_lemma(s.low[i]), s.verb(i)}
    for _, phrase, intent in sorted(p for word in first for p in _PHRASES_BY_FIRST.get(word, ())):
        if tuple(s.low[i + 1:i + len(phrase)]) == phrase[1:]:
            if phrase[0] in THING_TAKING_VERBS and carries_a_thing_to(s, i):
                return None  # "takes her lunch to the lounge": going there with it, not a lunch break
            if phrase[-1] in _AROUND and i + len(phrase) < s.n and s.low[i + len(phrase)] in _ON_TO:
                continue  # "walks round to the bar": going there the way round, not wandering about
            return phrase, intent
    spanned = spanned_intent(s, i)  # "swap holiday stories", "snake back from the hatch"
    if spanned is not None:
        return spanned
    lined = lined_queue(s, i)  # "form a long line at the servery", "join the back of the long queue"
    if lined is not None:
        return lined, "queue"
    setting = setting_out(s, i)  # "sets off for the library", "strike out towards the gate"
    return (setting, "walk") if setting is not None else None


def takes_a_way(s: Sentence, i: int, verb: str, end: int) -> bool:
    """Whether the verb at i takes a way or a means of moving as its object up to `end` ("take the
    lifts", "use the side entrance", "ride the escalators", "catch the shuttle")."""
    return verb in WAY_TAKING_VERBS and any(
        s.low[x] in lx.PASSAGE_WORDS or s.lemma(x) in lx.PASSAGE_WORDS or s.low[x] in MEANS_WORDS
        for x in range(i + 1, end))


def around_after(s: Sentence, i: int) -> bool:
    """Whether "around", "about" or "round" follows the verb at i, past adverbs of manner ("walks
    slowly round the gallery", "hurries round the ward")."""
    k = i + 1
    while k < s.n and (s.w[k].pos == "ADV" and s.low[k] not in _AROUND or s.low[k] in lx.SLOW_WORDS | lx.FAST_WORDS):
        k += 1
    # "wanders round to the toilets": round is the way to a place, not wandering about
    return k < s.n and s.low[k] in _AROUND and not (k + 1 < s.n and s.low[k + 1] in _ON_TO)


def _object_noun(s: Sentence, i: int) -> bool:
    """Whether word i is a noun the parser makes the object of another verb, after a determiner and the
    words that describe it ("a failed drive", "the last run"): a thing, whatever verb it spells."""
    w = s.w[i]
    if w.pos != "NOUN" or w.dep != "dobj" or w.head == i or s.w[w.head].pos not in ("VERB", "AUX"):
        return False
    k = i - 1
    while k >= 0 and k >= i - 3 and s.w[k].dep in ("amod", "compound") and s.w[k].head == i:
        k -= 1
    return k < i - 1 and k >= 0 and s.low[k] in ("a", "an", "the", "this", "that", "their", "his", "her", "its")
