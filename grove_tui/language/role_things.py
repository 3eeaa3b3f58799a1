"""Words for a thing that name a role too ("the keynote speaker", "a session chair"): such a word is
one person when it is the subject of a verb people do and, for a word that is mostly furniture, a
noun before it says whose role it is."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.aspect_verbs import governed_verb
from grove_tui.language.sentence import Sentence

# Things whose word names a role: a loudspeaker never walks, so "the speaker walks" is somebody;
# a chair may "stand" in a corner, so it needs a modifier ("the session chair", "the committee chair").
_ROLES_ALONE = frozenset({"speaker"})
_ROLES_MODIFIED = frozenset({"chair"})


def _people_verb(s: Sentence, head: int) -> bool:
    verb = s.verb(governed_verb(s, head))
    return s.w[head].pos == "VERB" and verb not in lx.THING_VERBS and verb not in lx.SOUND_LIGHT_VERBS and (
        verb in lx.INTENT_VERBS or verb in lx.HUMAN_SUBJECT_VERBS or verb in lx.PEOPLE_GOING_VERBS)


def role_thing(s: Sentence, i: int) -> bool:
    """Whether word i is a thing's word standing for a role ("the guest speaker heads to ...")."""
    lem = s.lemma(i)
    if lem not in _ROLES_ALONE and lem not in _ROLES_MODIFIED:
        return False
    word = s.w[i]
    # (The parser may join the verb to the noun: "the keynote speaker heads ...", "speaker" a compound of "heads".)
    verb = word.head if word.dep == "nsubj" else i + 1 if word.dep == "compound" and word.head == i + 1 else i
    if verb == i or not _people_verb(s, verb):
        return False
    modified = i > 0 and s.w[i - 1].head == i and s.w[i - 1].dep in ("compound", "amod") and \
        s.low[i - 1] not in lx.ROBOT_WORDS
    return lem in _ROLES_ALONE or modified
