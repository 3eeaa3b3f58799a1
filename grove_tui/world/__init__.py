"""The semantic world: zones, doors, entities and obstacles from a world YAML (`model`), read and
checked by `loader`, drawn by `render`. Everything else imports from here."""

from grove_tui.world.loader import check_world_file, format_path, list_worlds, load_world, parse_world, read_world_file, resolve_world_path
from grove_tui.world.model import (
    OUTSIDE,
    Door,
    Entity,
    Obstacle,
    Point2,
    RoI,
    World,
    WorldError,
    WorldProblem,
    Zone,
)

__all__ = ["OUTSIDE", "Door", "Entity", "Obstacle", "Point2", "RoI", "World", "WorldError", "WorldProblem", "Zone",
           "check_world_file", "format_path", "list_worlds", "load_world", "parse_world", "read_world_file",
           "resolve_world_path"]
