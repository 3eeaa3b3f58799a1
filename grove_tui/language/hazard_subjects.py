"""A thing that turns into a hazard, said as the subject of its verb: "Fat flares up on the grill",
"Oil ignites in the fryer", "Wiring smoulders behind the panel", "Toast catches fire". A capitalised
word opening the sentence with no determiner reads as a name ("Sarah scurries"); with a verb of
catching fire, burning or blowing up it is a thing on fire, nobody (round 49)."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Verbs a thing does as it becomes a hazard: people flee from these, they do not do them.
_HAZARD_VERBS = frozenset("flare ignite smoulder smolder combust explode spark billow blaze scorch overheat "
                          "burn".split())
# Verbs that are a hazard only with the word after them ("catches fire", "bursts into flames", "goes up in smoke").
_WITH_OBJECT = {"catch": frozenset({"fire", "alight", "light"}), "burst": frozenset({"into"}),
                "go": frozenset({"up"})}
_FIRE_WORDS = frozenset({"fire", "flames", "flame", "smoke"})


def hazard_verb(s: Sentence, v: int) -> bool:
    """Whether verb v says that its subject catches fire, burns or blows up (see the module doc)."""
    verb = s.verb(v)
    if verb in _HAZARD_VERBS:
        return not any(w.head == v and w.dep == "dobj" for w in s.w)  # not "a cook burns the toast"

    after = _WITH_OBJECT.get(verb)
    if after is None or v + 1 >= s.n or s.low[v + 1] not in after:
        return False
    if verb == "catch":
        return True
    return any(s.low[k] in _FIRE_WORDS for k in range(v + 2, min(s.n, v + 5)))  # "bursts into flames", "goes up in smoke"


def hazard_word(lemma: str) -> bool:
    """Whether a noun's lemma is a verb of a thing on fire: "Wiring smoulders behind the desk", parsed
    with "smoulders" as a plural noun whose "-er" reads like an agent's, names nobody."""
    return lemma in _HAZARD_VERBS
