"""Verbs of going somewhere in a manner (round 50): "bustles over to the pastry room", "scurries back to
the desk", "plods up to the ward". Not known as verbs of walking, they were not read as where a clause
sets off, so "locks her office and bustles over to X" lost the office as where they start, and the
lemmatiser left "bustles" as it was written. They are read as walking, like "hurry" and "trot". ("dawdle",
idling along with no goal, is wandering: lexicon.py.) "trudge" is left out: known as walking, it sends
"forty-odd grumbling season-ticket holders trudge off platform one" down the path that loses the count
(the same as "walk off"), a count bug of its own.)"""

from __future__ import annotations

MANNER_WALKS = "bustle scurry scuttle hobble traipse plod limp tiptoe hasten lumber stomp tramp"
