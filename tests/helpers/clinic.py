"""A small clinic world (lobby, corridor, pharmacy, cafeteria, restroom) for pipeline unit tests."""

CLINIC = """
name: clinic
description: A small clinic for tests.
zones:
  - name: lobby
    type: lobby
    description: Entrance lobby with the reception desk.
    aliases: [entrance hall, foyer]
    boundary: [[0, 0], [10, 0], [10, 8], [0, 8]]
    doors:
      - {name: main_entrance, position: [5, 0], width: 2.0, leads_to: outside, exit: true}
      - {name: lobby_corridor_door, position: [10, 4], width: 1.6, leads_to: corridor}
    entities:
      - {name: reception_desk, type: desk, footprint: [[3, 6], [7, 6], [7, 7], [3, 7]], interaction_point: [5, 5.4], tags: [reception, check-in]}
  - name: corridor
    type: corridor
    description: Main corridor.
    boundary: [[10, 2], [24, 2], [24, 6], [10, 6]]
    doors:
      - {name: corridor_pharmacy_door, position: [16, 6], width: 1.4, leads_to: pharmacy}
      - {name: corridor_cafeteria_door, position: [20, 2], width: 1.6, leads_to: cafeteria}
      - {name: back_exit, position: [24, 4], width: 1.6, leads_to: outside, exit: true}
  - name: pharmacy
    type: pharmacy
    description: Pharmacy with a dispensing counter.
    boundary: [[12, 6], [22, 6], [22, 14], [12, 14]]
    entities:
      - {name: pharmacy_counter, type: counter, footprint: [[14, 12.5], [20, 12.5], [20, 13.5], [14, 13.5]], interaction_point: [17, 11.8]}
  - name: cafeteria
    type: cafeteria
    description: Cafeteria with tables and a coffee counter.
    aliases: [canteen]
    boundary: [[14, -8], [26, -8], [26, 2], [14, 2]]
    entities:
      - {name: coffee_counter, type: counter, footprint: [[15, -7.5], [19, -7.5], [19, -6.5], [15, -6.5]], interaction_point: [17, -5.8]}
      - {name: vending_machine, type: vending_machine, footprint: [[24.5, 0], [25.5, 0], [25.5, 1], [24.5, 1]], interaction_point: [25, -0.6]}
  - name: restroom
    type: restroom
    description: A tiny restroom.
    aliases: [bathroom, toilet]
    boundary: [[0, 8], [3, 8], [3, 10], [0, 10]]
    doors:
      - {name: restroom_door, position: [1.5, 8], width: 0.9, leads_to: lobby}
"""


# ---- a bundle's generation result built by hand on the clinic (no model): post-processing + planning
from grove_tui.generation.draft import Draft, DraftNode  # noqa: E402
from grove_tui.generation.pipeline import GenerationResult  # noqa: E402
from grove_tui.generation.planning import plan_operational  # noqa: E402
from grove_tui.generation.postprocess import postprocess  # noqa: E402
from grove_tui.generation.presets import load_preset  # noqa: E402
from grove_tui.generation.rois import select_rois  # noqa: E402
from grove_tui.language.reading import read_prompt  # noqa: E402
from grove_tui.navigation.grid import build_grid  # noqa: E402
from grove_tui.scenario.model import Scenario  # noqa: E402


def make_result(world, preset_name, prompt, groups, seed=0):
    preset = load_preset(preset_name)
    grid = build_grid(world)
    reading = read_prompt(prompt, world, seed=seed)
    selection = select_rois(world, preset, reading)
    post = postprocess(world, grid, preset, Draft(tuple(groups)), selection, seed, reading,
                       ("Sequence", "GoTo", "Queue", "FollowVelocityField"))
    op = plan_operational(world, grid, preset, post, seed)
    scenario = Scenario(world=str(world.source), preset=preset.name, prompt=prompt, seed=seed, models={"bt": "hand"},
                        agents=tuple(op.agents), robot=op.robot,
                        fields={fid: f"fields/{fid}.npz" for fid in op.fields})
    return GenerationResult(scenario, op.trees, op.fields, grid, {"stages": {}, "notes": post.notes})


QUEUE = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": "pharmacy_counter"}),
                                   DraftNode("Queue", {"service_point": "pharmacy_counter"})))
