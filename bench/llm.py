"""LLM benchmark (run by hand): decode speed with and without grammar, warm first-token latency,
and (--compare) draft quality of the embedded-model candidates.

    python bench/llm.py                 # the embedded model (or --model PATH)
    python bench/llm.py --compare       # smollm2 vs gemma3 on 20 prompts over the shipped worlds

The last line is key=value headline figures.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from grove_tui.generation.draft import DraftError, draft_grammar, parse_draft  # noqa: E402
from grove_tui.llm.embedded import CANDIDATES, EMBEDDED_MODEL, embedded_model_path  # noqa: E402
from grove_tui.errors import ModelError  # noqa: E402
from grove_tui.llm.local import LocalLLM  # noqa: E402

NODES = ["Sequence", "GoTo", "Queue", "Wait", "Wander", "Converse"]
SYSTEM = (
    "You write pedestrian scenarios for a simulator, one line per group: COUNT LABEL from SPAWN: TREE. "
    "COUNT: how many people; LABEL: who (one word); SPAWN: the place where they start; TREE: what they do, "
    "a node written Node(required values, optional port=value, children); only Sequence has children. "
    "Node types: GoTo(place) walk to a place; Queue(place) wait in line; Wait(duration=seconds); "
    "Wander(place); Converse(place) chat at a place; Sequence(nodes) do them in order. "
    "Use only the place names given.\n"
    "Example: 3 visitors from lobby: Sequence(GoTo(cafe), Wait(duration=30))"
)

# (sentence, places offered, expected spawn, expected target, expected count) over the shipped worlds
CASES = [
    ("Ten patients walk from the main waiting room to the pharmacy counter and queue there.",
     ["main_waiting_room", "pharmacy", "pharmacy_counter", "main_entrance"], "main_waiting_room", "pharmacy_counter", 10),
    ("Five visitors enter at the main entrance and go to the reception desk.",
     ["main_entrance", "entrance_lobby", "reception_desk", "cafeteria"], "main_entrance", "reception_desk", 5),
    ("Three nurses wander around the ward corridor.",
     ["ward_corridor", "nurse_station", "ward_a", "staff_room"], "ward_corridor", "ward_corridor", 3),
    ("Eight people in the cafeteria queue at the food counter.",
     ["cafeteria", "food_counter", "coffee_machine", "main_corridor"], "cafeteria", "food_counter", 8),
    ("Two doctors walk from the doctors office to the intensive care unit.",
     ["doctors_office", "intensive_care", "ward_corridor", "elevator_hall"], "doctors_office", "intensive_care", 2),
    ("Six patients in the outpatient waiting area go to the checkin kiosk.",
     ["outpatient_waiting", "checkin_kiosk", "central_corridor", "radiology"], "outpatient_waiting", "checkin_kiosk", 6),
    ("Four staff members chat at the staff coffee machine in the staff room.",
     ["staff_room", "staff_coffee_machine", "staff_sofa", "nurse_station"], "staff_room", "staff_coffee_machine", 4),
    ("Twelve people leave the entrance lobby through the main entrance.",
     ["entrance_lobby", "main_entrance", "pharmacy", "cafeteria"], "entrance_lobby", "main_entrance", 12),
    ("Seven patients wait in radiology and then walk to the ct scanner.",
     ["radiology", "ct_scanner", "xray_machine", "main_corridor"], "radiology", "ct_scanner", 7),
    ("Nine visitors walk from the elevator hall to the cafeteria.",
     ["elevator_hall", "cafeteria", "main_corridor", "pharmacy"], "elevator_hall", "cafeteria", 9),
    ("Five employees walk from the open plan office to the kitchen.",
     ["open_plan_office", "kitchen", "reception", "boardroom"], "open_plan_office", "kitchen", 5),
    ("Three colleagues queue at the coffee machine in the kitchen.",
     ["kitchen", "coffee_machine", "fridge", "main_corridor"], "kitchen", "coffee_machine", 3),
    ("Eight people go from the reception to the boardroom.",
     ["reception", "boardroom", "meeting_room_1", "kitchen"], "reception", "boardroom", 8),
    ("Two visitors wait at the reception desk.",
     ["reception", "reception_desk", "visitor_sofa", "main_entrance"], "reception", "reception_desk", 2),
    ("Six workers leave the open plan office through the fire exit.",
     ["open_plan_office", "fire_exit", "back_exit", "kitchen"], "open_plan_office", "fire_exit", 6),
    ("Four people chat at the printer in the open plan office.",
     ["open_plan_office", "printer", "whiteboard", "lounge_sofa"], "open_plan_office", "printer", 4),
    ("Two children walk from the child bedroom to the kitchen.",
     ["child_bedroom", "kitchen", "living_room", "bathroom"], "child_bedroom", "kitchen", 2),
    ("Three guests in the living room go to the balcony.",
     ["living_room", "balcony", "kitchen", "hallway"], "living_room", "balcony", 3),
    ("One person walks from the hallway to the front door.",
     ["hallway", "front_door", "bathroom", "kitchen"], "hallway", "front_door", 1),
    ("Five family members wander in the living room.",
     ["living_room", "sofa", "tv", "kitchen"], "living_room", "living_room", 5),
]


def messages_for(sentence: str, places: list[str]) -> list[dict[str, str]]:
    return [{"role": "system", "content": SYSTEM},
            {"role": "user", "content": f"Places: {', '.join(places)}\nScenario: {sentence}"}]


def compare(threads: int | None) -> dict[str, float]:
    figures: dict[str, float] = {}
    for name in CANDIDATES:
        path = embedded_model_path(name)
        llm = LocalLLM(path, role=f"bench-{name}", n_ctx=2048, n_threads=threads)
        started = time.monotonic()
        llm.start()
        load = time.monotonic() - started
        valid = spawn_ok = target_ok = count_ok = all_ok = 0
        seconds: list[float] = []
        tokens = 0
        for sentence, places, spawn, target, count in CASES:
            grammar = draft_grammar(NODES, places, max_groups=2, max_count=60, max_depth=2)
            try:
                result = llm.generate(messages_for(sentence, places), grammar=grammar, max_tokens=200, seed=0)
                draft = parse_draft(result.text, NODES, places, max_groups=2, max_count=60, max_depth=2)
            except (ModelError, DraftError) as error:
                print(f"  {name}: {sentence[:40]}... FAILED {error}")
                continue
            valid += 1
            seconds.append(result.seconds)
            tokens += result.completion_tokens
            used = draft.places()
            ok_spawn = any(group.spawn == spawn for group in draft.groups)
            ok_target = target in used - {g.spawn for g in draft.groups} or (target == spawn and target in used)
            ok_count = any(group.count == count for group in draft.groups)
            spawn_ok += ok_spawn
            target_ok += ok_target
            count_ok += ok_count
            all_ok += ok_spawn and ok_target and ok_count
            print(f"  {name}: spawn={ok_spawn:d} target={ok_target:d} count={ok_count:d} {result.seconds:5.1f}s {result.text[:110]}")
        llm.close()
        n = len(CASES)
        figures.update({f"{name}_valid": valid / n, f"{name}_spawn": spawn_ok / n, f"{name}_target": target_ok / n,
                        f"{name}_count": count_ok / n, f"{name}_all": all_ok / n,
                        f"{name}_median_s": statistics.median(seconds) if seconds else float("nan"),
                        f"{name}_tok_per_s": tokens / sum(seconds) if seconds else float("nan"), f"{name}_load_s": load})
        print(f"{name}: valid {valid}/{n}, spawn {spawn_ok}/{n}, target {target_ok}/{n}, count {count_ok}/{n}, "
              f"all three {all_ok}/{n}, median {figures[f'{name}_median_s']:.1f} s per draft")
    return figures


def speed(path: Path, threads: int | None) -> dict[str, float]:
    llm = LocalLLM(path, role="bench", n_ctx=2048, n_threads=threads)
    llm.start()
    sentence, places = CASES[0][0], CASES[0][1]
    messages = messages_for(sentence, places)
    grammar = draft_grammar(NODES, places, max_groups=2, max_depth=2)
    # Free text has no natural end here, so a fixed budget measures pure decode speed (length is expected).
    free_rates, grammar_rates, warm_first, reused = [], [], [], []
    for seed in range(3):
        started = time.monotonic()
        try:
            llm.generate(messages, max_tokens=96, seed=seed, length_retries=0)
        except ModelError:
            pass
        free_rates.append(96 / (time.monotonic() - started))
        result = llm.generate(messages, grammar=grammar, max_tokens=300, seed=seed)
        grammar_rates.append(result.completion_tokens / result.seconds)
        # Warm prefix: same system prompt, a different scenario sentence (what the pipeline does per request).
        other_sentence, other_places = CASES[seed + 1][0], CASES[seed + 1][1]
        other_grammar = draft_grammar(NODES, other_places, max_groups=2, max_depth=2)
        warm = llm.generate(messages_for(other_sentence, other_places), grammar=other_grammar, max_tokens=300, seed=seed)
        warm_first.append(warm.first_token_seconds or float("nan"))
        reused.append(warm.cached_tokens / warm.prompt_tokens)
    cold = LocalLLM(path, role="bench-cold", n_ctx=2048, n_threads=threads)
    cold.start()
    cold_first = cold.generate(messages, grammar=grammar, max_tokens=300).first_token_seconds or float("nan")
    prompt_tokens = llm.count_tokens(messages)
    cold.close()
    llm.close()
    figures = {"tok_per_s_free": statistics.median(free_rates), "tok_per_s_grammar": statistics.median(grammar_rates),
               "first_token_warm_s": statistics.median(warm_first), "first_token_cold_s": cold_first,
               "warm_prefix_share": statistics.median(reused),
               "prompt_tokens": prompt_tokens, "threads": llm.n_threads}
    print(f"{path.name}: {figures}")
    return figures


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", type=Path, default=None)
    parser.add_argument("--threads", type=int, default=None)
    parser.add_argument("--compare", action="store_true")
    args = parser.parse_args()
    figures = compare(args.threads) if args.compare else speed(args.model or embedded_model_path(EMBEDDED_MODEL), args.threads)
    print(" ".join(f"{key}={value:.3g}" if isinstance(value, float) else f"{key}={value}" for key, value in figures.items()))


if __name__ == "__main__":
    main()
