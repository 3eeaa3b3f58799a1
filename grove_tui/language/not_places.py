"""Nouns after a place preposition that say no place, so nothing to refuse when the world lacks them:
the cause of a hazard (hazards.py) and, round 22:

- the doer of a passive: "with the roof torn off by the storm", "its windows blown in by the gale"
  (a phrase whose head names no room: "a bag left by the casino door" is still a place);
- what is leafed through: "leafing through magazines", "flicks through a brochure" (a verb of turning
  pages, or a bare plural that no determiner makes a place: "through leaflets");
- an activity gone for: "set off for a walk", "head off for a jog" (a noun the lexicon knows as a verb
  of going, or a pause: "for a smoke");
- a call someone is on (round 23): "busy on a phone call", "in a video call";

and, round 23, a span of the event ("in the interval", "during the break") and what people are busy on
("on a phone call", "on a break", "on duty"); round 69, what someone is absorbed in ("glued to the
racing", absorbed_in.py) and, never read as a place at all (not_a_place, read by place_phrases.py), a
walking aid ("on a zimmer frame", walking_aids.py).
"""

from __future__ import annotations

__all__ = ["caught_by", "heading_adverb", "infinitive_verb", "no_place_said", "not_a_place"]

from grove_tui.language.heading_adverbs import heading_adverb
from grove_tui.language.infinitive_verbs import infinitive_verb
from grove_tui.language.absorbed_in import absorbed_in
from grove_tui.language.walking_aids import walking_aid
from grove_tui.language import lexicon as lx
from grove_tui.language.activity_nouns import PAUSE_NOUNS
from grove_tui.language.consumed_things import consumed_thing
from grove_tui.language.courses_taken import a_course_taken
from grove_tui.language.eaten_into import eaten_into
from grove_tui.language.event_names import names_an_event
from grove_tui.language.hazards import ROOM_HEADS, cause_thing
from grove_tui.language.held_and_spans import held_or_span
from grove_tui.language.held_origins import origin_of_held
from grove_tui.language.hidden_behind import hidden_behind
from grove_tui.language.no_place_things import no_place_thing
from grove_tui.language.outing_words import an_outing
from grove_tui.language.person_relatives import in_persons_relative
from grove_tui.language.weather_words import the_weather
from grove_tui.language.who_from import who_they_are_from
from grove_tui.language.bid_things import a_thing_bid_on
from grove_tui.language.caught_by import caught_by  # read by place_phrases.py with no_place_said
from grove_tui.language.sentence import Sentence
from grove_tui.language.span_ends import span_after_part
from grove_tui.language.times_and_manners import time_or_manner
from grove_tui.language.tokens import lemma, verb_lemma

# Verbs of turning pages ("leafs through", "flicking through", "thumbs through").
_PAGING = frozenset("leaf flick thumb riffle rifle skim browse page scroll sift rummage read look glance".split())
# Verbs that "for" makes a way to a place ("heads for the wedding"): any other "for" an event is why they come.
_HEADING = frozenset("head make run dash bolt race aim set leave depart go".split())
# Particles that may stand between a passive participle and "by" ("torn off by", "blown in by").
_PARTICLES = frozenset("off in out down over up away apart".split())
# Spans of an event people are in ("in the interval", "during half-time"), and what people are on ("on a call").
_SPANS = frozenset("interval intermission half-time halftime meantime break recess".split())
_BUSY_ON = frozenset("call break duty shift lunch tea".split())


def no_place_said(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether the phrase from k after the preposition at `at` says no place (see the module doc)."""
    if (prep in ("at", "from", "in", "during") or prep == "for" and verb_lemma(s.low[at - 1]) not in _HEADING) \
            and names_an_event(s, k):
        return True  # "at the tea dance", "from the Cub pack", "come in for the sale": a gathering, no place to refuse
    if absorbed_in(s, k, prep, at):
        return True  # "glued to the racing", "engrossed in the snooker": what holds them (absorbed_in.py)
    if in_persons_relative(s, at):
        return True  # "a teenager who slipped on the wet tiles": before the scene (person_relatives.py)
    if a_thing_bid_on(s, k, prep, at):
        return True  # "lost out on the bureau she came for": a thing (bid_things.py)
    if who_they_are_from(s, k, prep, at):
        return True  # "infants from the village school traipse across": who they are (who_from.py)
    if held_or_span(s, k, prep, at):
        return True  # "clipboard in hand", "at the interval", "midway through the lecture" (round 46)
    if hidden_behind(s, k, prep, at):
        return True  # "ducks behind the curtains": a thing one hides by, which the world lacks (round 52)
    if no_place_thing(s, k, prep):
        return True  # "through forty-odd pickers", "recording it on a phone": people, a device
    if consumed_thing(s, k, prep, at):
        return True  # "stock up on IPA", "roused from a snooze": food, drink, a nap (round 41)
    if cause_thing(s, k, prep, at) or origin_of_held(s, k, prep, at):
        return True  # "smell of burning from the toaster", "clutching mugs from the seconds shelf"
    if an_outing(s, k, prep) or the_weather(s, k, prep) or a_course_taken(s, k, prep):
        return True  # "on a geography trip", "against the cold": an outing, the weather (round 45)
    if eaten_into(s, k, prep, at):
        return True  # "tucking into curry": food (eaten_into.py)
    if span_after_part(s, k, prep, at):
        return True  # "at the end of his session": a time (span_ends.py)
    if time_or_manner(s, k, prep):
        return True  # "on a wet Tuesday", "on foot", "at half past nine"
    if prep in ("on", "in", "during") and _a_call(s, k):
        return True  # "busy on a phone call", "in a video call": what they are doing, not where
    head = k
    while head < s.n and s.w[head].pos in ("DET", "ADJ", "NOUN", "PROPN"):
        head += 1
    said = lemma(s.low[head - 1]) if head > k else ""
    if prep in ("in", "during") and said in _SPANS or prep == "on" and said in _BUSY_ON:
        return True  # "In the interval, ...", "busy on a phone call in the boardroom"
    if prep == "by":
        v = at - 1
        if v >= 1 and s.low[v] in _PARTICLES:
            v -= 1
        end = k
        while end < s.n and s.w[end].pos in ("DET", "ADJ", "NOUN", "PROPN"):
            end += 1
        return v >= 1 and s.w[v].tag == "VBN" and end > k and lemma(s.low[end - 1]) not in ROOM_HEADS
    if prep == "through":
        paged = at >= 1 and verb_lemma(s.low[at - 1]) in _PAGING
        bare_plural = k < s.n and s.low[k] not in lx.DETERMINERS and s.w[k].tag == "NNS"
        return paged or bare_plural
    if prep == "for":
        j = k
        while j < s.n and s.low[j] in ("a", "an", "their", "his", "her", "quick", "short", "long", "little", "brisk"):
            j += 1
        word = lemma(s.low[j]) if j < s.n else ""
        return j > k and (lx.INTENT_VERBS.get(word) in ("walk", "wander") or word in PAUSE_NOUNS)
    return False


def not_a_place(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether the phrase from k is never a place, whatever the world has: what a set-off participle
    was stirred by ("Intrigued by the lights, ..."), a walking aid ("on a zimmer frame")."""
    return caught_by(s, k, prep, at) or walking_aid(s, k, prep, at)


def _a_call(s: Sentence, k: int) -> bool:
    """Whether the phrase from k is a call someone is on ("a phone call", "a long video call")."""
    end = k
    while end < s.n and s.w[end].pos in ("DET", "ADJ", "NOUN", "PROPN", "PRON"):
        end += 1
    return end > k and lemma(s.low[end - 1]) in ("call", "phonecall")
