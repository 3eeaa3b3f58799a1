"""Gas that escapes, said by the thing that holds it and the sound or way it escapes (round 52): "a gas
bottle starts hissing", "gas is leaking", "a propane cylinder hisses", "the ammonia tank is venting".
A gas, or a thing that holds gas said with its gas ("gas bottle", "propane cylinder"), then within a
few words a verb of escaping: a hazard cue, so people who leave or are sent off after it evacuate
(`hazards.py`). A bottle, tank or pipe that hisses with no gas named ("the kettle hisses") is no cue."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Gases whose escape is a hazard.
_GASES = frozenset("gas gases propane butane methane ammonia chlorine lpg calor acetylene".split())
# Things that hold a gas, said after it ("gas bottle", "propane cylinder", "the gas main").
_HOLDERS = frozenset("bottle bottles cylinder cylinders canister canisters tank tanks main mains pipe pipes line "
                     "lines supply valve valves hob hobs cooker boiler heater".split())
# Verbs of gas escaping, every form ("hisses", "is leaking", "started venting").
_ESCAPING = frozenset(f"{v}{end}" for v in ("hiss", "leak", "vent", "spew") for end in ("", "s", "es", "ed", "ing")) | \
    frozenset("escape escapes escaped escaping".split())
# Words that may stand between the thing and its verb ("starts hissing", "is suddenly leaking").
_BETWEEN = frozenset("suddenly just then has have had is are was were starts start started begins begin began "
                     "can be could audibly loudly".split())


def gas_cue(s: Sentence, i: int) -> bool:
    """Whether the word at i names a gas, or its holder said with the gas, that then escapes."""
    if s.low[i] not in _GASES:
        return False
    k = i + 1
    while k < s.n and s.low[k] in _HOLDERS and k <= i + 2:
        k += 1
    stop = k + 3
    while k < s.n and k <= stop and s.low[k] in _BETWEEN:
        k += 1
    return k < s.n and s.low[k] in _ESCAPING
