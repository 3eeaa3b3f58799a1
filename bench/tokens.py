"""Token table as in the paper: prompt tokens of the bt model's request, preset vs vanilla.

For each preset (emergency, normal, queuing) ten prompts over the three shipped worlds are run
through the strategic and tactical layers (RoI selection, retrieval, prompt building) and the
rendered chat prompt is tokenised by the bt model itself (its chat template included). The same
prompts are built with the vanilla preset (the whole world, every node document, no guidance).
Counting needs no generation, so the figures are exact and repeatable; a generation sends exactly
this prompt (LocalLLM reports the same prompt_tokens). GROVE's prompt is also split into its fixed
part (the system message, the same for every sentence in a world and preset, whose KV state is
cached) and its variable part (everything after it, evaluated on every request).

    python bench/tokens.py [--bt-model PATH]

The last line holds the headline figures as key=value pairs.
"""

from __future__ import annotations

import argparse
import statistics
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

# (world, prompt) per preset; every place named exists in its world.
PROMPTS: dict[str, list[tuple[str, str]]] = {
    "emergency": [
        ("hospital", "A fire alarm: twenty people in the main waiting room evacuate"),
        ("hospital", "Everyone in the cafeteria leaves through the terrace door"),
        ("hospital", "Fifteen visitors in the entrance lobby rush to the exit"),
        ("hospital", "Ten nurses and six patients in ward A evacuate during a fire"),
        ("office", "A fire alarm goes off and twelve employees in the open plan office evacuate"),
        ("office", "Eight people in the kitchen leave the building through the fire exit"),
        ("office", "The boardroom empties: ten colleagues escape to the back exit"),
        ("residential", "Smoke in the kitchen: a family of four in the living room leaves by the front door"),
        ("residential", "Two children in the child bedroom evacuate"),
        ("residential", "Three guests on the balcony hurry out of the flat"),
    ],
    "normal": [
        ("hospital", "A family of four walks from the entrance lobby to the cafeteria"),
        ("hospital", "Two nurses chat at the nurse station while a doctor walks to ward B"),
        ("hospital", "Several visitors wander around the lobby and look at the robot"),
        ("hospital", "Three patients sit in the main waiting room and one goes to the restroom"),
        ("office", "Four colleagues meet in meeting room 1 and then go to the kitchen"),
        ("office", "Six employees work at their desks in the open plan office"),
        ("office", "A visitor waits on the sofa in the reception"),
        ("residential", "Two children walk from the living room to the kitchen"),
        ("residential", "A couple talks in the kitchen"),
        ("residential", "A child wanders around the hallway"),
    ],
    "queuing": [
        ("hospital", "Ten patients queue at the pharmacy counter"),
        ("hospital", "Eight visitors line up at the reception desk"),
        ("hospital", "Six people wait in line at the coffee machine in the cafeteria"),
        ("hospital", "Five patients queue at the check-in kiosk"),
        ("hospital", "Twelve people wait for their turn at the food counter"),
        ("office", "Seven employees queue at the coffee machine in the kitchen"),
        ("office", "Four visitors line up at the reception desk"),
        ("office", "Five colleagues wait in line at the printer"),
        ("residential", "Three children queue at the fridge in the kitchen"),
        ("residential", "Two people wait in line for the bathroom sink"),
    ],
}
PRESETS = ("emergency", "normal", "queuing")


def build_request(world, preset, prompt, retriever):
    """The bt model's request exactly as GenerationPipeline.run builds it (without the optional RoI model)."""
    from grove_tui.generation.rois import select_rois
    from grove_tui.generation.synthesis import prepare_request
    from grove_tui.language.reading import read_prompt

    reading = read_prompt(prompt, world, seed=0)
    selection = select_rois(world, preset, reading)
    retrieved = (retriever.retrieve(prompt, preset.retrieval_filter, k=preset.retrieval_k)
                 if preset.retrieval_filter is not None and preset.retrieval_k > 0 else [])
    return prepare_request(preset, selection, retrieved, reading, retriever.documents_for, world=world,
                           cards_for=retriever.cards_for, documents_named=retriever.documents_named)


def fixed_tokens(llm, messages) -> int:
    """Tokens of the rendered prompt up to the user's content: the part shared by every sentence.

    The chat template is rendered with and without the user's content; their common text ends at
    special tokens (end of the system turn, start of the user turn), where tokenization splits, so
    its token count is exactly the shared token prefix.
    """
    full = llm.render(messages)
    empty = llm.render([*messages[:-1], {**messages[-1], "content": ""}])
    shared = 0
    for a, b in zip(full, empty):
        if a != b:
            break
        shared += 1
    return llm.count_tokens(full[:shared])


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bt-model", default=None, help="GGUF whose tokenizer counts (default: the bt role's model)")
    args = parser.parse_args()

    from grove_tui.generation.presets import load_preset
    from grove_tui.generation.retrieval import NodeRetriever
    from grove_tui.world import load_world
    from grove_tui.llm.local import LocalLLM
    from grove_tui.llm.registry import resolve_models

    choice = resolve_models(None, args.bt_model)["bt"]
    llm = LocalLLM(choice.path, role="bt", n_ctx=choice.n_ctx)
    retriever = NodeRetriever()
    vanilla = load_preset("vanilla")
    worlds = {}
    table: dict[str, dict[str, list[int]]] = {"vanilla": {}, "grove": {}, "fixed": {}, "variable": {}}
    try:
        for preset_name in PRESETS:
            preset = load_preset(preset_name)
            for row in table.values():
                row[preset_name] = []
            for world_name, prompt in PROMPTS[preset_name]:
                world = worlds.setdefault(world_name, load_world(world_name))
                guided = build_request(world, preset, prompt, retriever)
                baseline = build_request(world, vanilla, prompt, retriever)
                g, v = llm.count_tokens(guided.messages), llm.count_tokens(baseline.messages)
                fixed = fixed_tokens(llm, guided.messages)
                table["grove"][preset_name].append(g)
                table["vanilla"][preset_name].append(v)
                table["fixed"][preset_name].append(fixed)
                table["variable"][preset_name].append(g - fixed)
                print(f"{preset_name:9s} {world_name:11s} grove={g:6d} (fixed {fixed:5d}, variable {g - fixed:5d}) "
                      f"vanilla={v:6d}  {prompt}", file=sys.stderr)
    finally:
        llm.close()

    means = {k: {p: statistics.mean(v) for p, v in rows.items()} for k, rows in table.items()}
    improvement = {p: 1.0 - means["grove"][p] / means["vanilla"][p] for p in PRESETS}
    print(f"Prompt tokens of the bt model's request, mean over {len(PROMPTS['normal'])} prompts per preset "
          f"(model: {Path(choice.path).name})")
    print(f"{'Method':12s} {'Emergency':>10s} {'Normal':>10s} {'Queuing':>10s}")
    print(f"{'Vanilla':12s} " + " ".join(f"{means['vanilla'][p]:10.0f}" for p in PRESETS))
    print(f"{'GROVE':12s} " + " ".join(f"{means['grove'][p]:10.0f}" for p in PRESETS))
    print(f"{'Improvement':12s} " + " ".join(f"{improvement[p] * 100:9.0f}%" for p in PRESETS))
    print(f"{'  fixed':12s} " + " ".join(f"{means['fixed'][p]:10.0f}" for p in PRESETS) + "   (system: world + preset, cached)")
    print(f"{'  variable':12s} " + " ".join(f"{means['variable'][p]:10.0f}" for p in PRESETS) + "   (per sentence)")
    print(f"{'  variable max':12s} " + " ".join(f"{max(table['variable'][p]):10d}" for p in PRESETS))
    most_variable = max(max(rows) for rows in table["variable"].values())
    print(" ".join([f"{p}_grove={means['grove'][p]:.0f} {p}_vanilla={means['vanilla'][p]:.0f} "
                    f"{p}_reduction={improvement[p]:.3f} {p}_variable={means['variable'][p]:.0f}" for p in PRESETS]
                   + [f"min_reduction={min(improvement.values()):.3f}", f"max_variable={most_variable}"]))
    return 0 if min(improvement.values()) >= 0.5 else 1


if __name__ == "__main__":
    sys.exit(main())
