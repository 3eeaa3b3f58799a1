"""A word of surprise fronted before its subject and a comma ("Shocked, a manager ...", "Stunned, a
porter ...") says how the person takes the robot: avoiding it then is Surprised, not Scared. A
startled person said as such ("a startled intern jumps back") and a fright said too keep Scared."""

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "Stunned, a porter in the lobby shrinks back as the robot rolls past."),
    ("office", "Ten devs code in the open office. Shocked, a manager at reception jumps aside as the robot rolls by."),
    ("museum", "Startled, a guard in the main hall leaps back when the robot turns the corner."),
])
def test_fronted_surprise_makes_avoiding_surprised(read, world, prompt):
    group = read(world, prompt).groups[-1]
    assert (group.count.value, group.robot_interaction, group.robot_reaction) == (1, "avoid", "Surprised")


@pytest.mark.parametrize("world,prompt", [
    ("office", "A startled intern jumps back when the robot passes."),
    ("office", "Startled, an intern in the kitchen jumps back in terror as the robot passes."),
])
def test_no_fronted_surprise_keeps_fright(read, world, prompt):
    (group,) = read(world, prompt).groups
    assert (group.robot_interaction, group.robot_reaction) == ("avoid", "Scared")
