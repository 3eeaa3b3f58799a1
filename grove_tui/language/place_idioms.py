"""Phrases after a place preposition that are no place at all: what people talk or think about ("argue
about a bug", "chat over coffee", "worry about the weather") and what a feeling breaks into ("bursts
into tears", "breaks into song", "gets into trouble"). language/place_phrases.py reads neither as a
place nor refuses it as one the world lacks; a real place after a verb of going is still a place."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.feeling_topics import felt_about
from grove_tui.language.sentence import Sentence
from grove_tui.language.treatments import on_treatment
from grove_tui.language.tokens import lemma, verb_lemma

# Verbs whose "about" / "over" phrase is their topic.
TOPIC_VERBS = frozenset(
    "talk chat converse gossip discuss argue debate natter chatter banter bicker squabble quarrel row fight "
    "joke laugh think worry wonder complain moan grumble whine rant rave fuss agonise agonize care know hear "
    "read learn ask enquire inquire forget dream fret brood reminisce disagree agree haggle negotiate "
    "pore mull muse ponder puzzle obsess panic stress tell speak whisper mutter shout yell".split())
# What "into" leads to when it is a feeling or a state, not a room: "bursts into tears".
INTO_STATES = frozenset(
    "tear laughter laugh giggle hysterics song chant cheer applause sob tantrum rage fury panic trouble "
    "mischief difficulty debt action argument fight row conversation discussion chat smile grin frown "
    "sweat fit shape line view sight place position habit routine dance flame".split())


def is_idiom_phrase(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether the phrase from word k, after the preposition at `at`, is a topic or a state, not a place."""
    if on_treatment(s, k, prep, at):
        return True  # "patients on dialysis": what they are having
    if felt_about(s, at):
        return True  # "Furious about the sentence": what the feeling is about
    if at < s.n and s.low[at] in ("about", "over"):
        for x in range(at - 1, max(-1, at - 4), -1):  # "argue loudly about": the verb a word or two back
            if s.is_punct(x):
                break
            if verb_lemma(s.low[x]) in TOPIC_VERBS or lx.INTENT_VERBS.get(verb_lemma(s.low[x])) == "converse":
                return True
        return False
    if at < s.n and s.low[at] == "into":
        j = k
        while j < s.n and s.low[j] in lx.DETERMINERS:
            j += 1
        # "into tears", but "into the dance studio": a place word after it makes it a room's name
        return j < s.n and lemma(s.low[j]) in INTO_STATES and not (
            j + 1 < s.n and s.low[j + 1].isalpha() and s.index.knows(lemma(s.low[j + 1]))) and not (
            j + 1 < s.n and s.low[j + 1] in ("where", "wherever"))  # "into the place where the water is filtered"
    return False
