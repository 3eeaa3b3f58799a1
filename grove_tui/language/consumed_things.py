"""Nouns after a place preposition that say no place, round 41: what is eaten or drunk ("to stock up on
IPA", "load up on doughnuts", "after a pint of stout") and a nap someone wakes from ("roused from a snooze",
"woken from a nap", "startled out of a doze"). A world lacking such a noun has no place to refuse; a
phrase whose head is a room ("the coffee shop", "the beer garden") keeps its head and is still a place."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma, verb_lemma

# Drinks and food by the head of a phrase ("a pint", "IPA", "crisps", "doughnuts").
FOOD_AND_DRINK = frozenset(
    "ipa ale lager beer stout cider wine prosecco champagne fizz gin whisky whiskey vodka rum cocktail pint "
    "coffee tea latte cappuccino espresso cuppa juice smoothie milkshake soda lemonade cola "
    "sandwich sarnie bap burger pizza chip crisp snack cake biscuit bun doughnut donut pastry croissant "
    "scone muffin sweet chocolate popcorn kebab noodle sushi soup salad fruit bread cheese candy "
    "breakfast brunch lunch dinner supper takeaway grub nibble treat".split())
# A nap or a sleep someone is in or wakes from.
NAPS = frozenset("snooze nap doze kip siesta catnap power-nap slumber sleep lie-in daydream reverie "
                 "forty winks".split())
# Words that end a noun phrase scanned for its head.
_ENDS = frozenset("PUNCT ADP CCONJ SCONJ AUX PRON".split())
# Verbs of buying in a stock ("stock up on", "load up on"), whatever follows them is no place.
_STOCKING = frozenset("stock load fill top stack".split())


def consumed_thing(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether the phrase from k after the preposition at `at` is food, drink or a nap (see the module doc)."""
    if prep == "on" and at >= 2 and s.low[at - 1] == "up" and verb_lemma(s.low[at - 2]) in _STOCKING:
        return True  # "stock up on IPA", "stocking up on sandwiches"
    end = k
    while end < s.n and s.w[end].pos not in _ENDS and not (end > k and s.low[end] in ("and", "or")):
        if end > k and s.w[end].pos == "VERB" and s.w[end].tag != "VBG":
            break
        end += 1
    if end == k:
        return False
    head = lemma(s.low[end - 1])
    return head in FOOD_AND_DRINK or head in NAPS or s.low[end - 1] in NAPS
