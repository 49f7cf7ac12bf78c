"""Issue 41 point 2: each physical constant of water is written once, in `nodes/physics.py`;
every other module of the add-on takes it from there."""

import math
import re
from pathlib import Path

from conftest import load

ROOT = Path(__file__).resolve().parents[2]
NOT_THE_ADDON = ("tests", "tools", "bench", "docs", ".ci")
# The numbers as code would write them (in a docstring or comment they may be named).
LITERALS = {
    "water's IOR": r"(?<![\d.])1\.33(?![\d])",
    "g": r"(?<![\d.])9\.8(1|0665)(?![\d])",
    "σ/ρ": r"(?<![\d.])7\.3e-5",
    "the Kelvin wedge's tangent": r"(?<![\d.])0\.35(36|355)",
}


def _code_lines(path):
    """The file's lines that are code: docstrings and comments dropped."""
    text = path.read_text(encoding="utf-8")
    text = re.sub(r'"""(.|\n)*?"""', lambda m: "\n" * m.group(0).count("\n"), text)
    return [line.split("#", 1)[0] for line in text.splitlines()]


def test_each_constant_is_written_in_one_module():
    found = []
    for path in sorted(ROOT.rglob("*.py")):
        relative = path.relative_to(ROOT)
        if relative.parts[0] in NOT_THE_ADDON or relative.as_posix() == "nodes/physics.py":
            continue
        for number, line in enumerate(_code_lines(path), 1):
            for name, pattern in LITERALS.items():
                if re.search(pattern, line):
                    found.append(f"{relative}:{number}: {name}: {line.strip()}")
    assert not found, "\n".join(found)


def test_the_groups_and_the_sea_read_them():
    physics = load("nodes.physics")
    # The wedge's half-angle is asin(1/3) (SPEC section 5), whatever the speed.
    assert abs(math.atan(physics.KELVIN_TAN) - math.asin(1.0 / 3.0)) < 1e-9
    assert load("water.sea.sea_math").GRAVITY == physics.G
    assert load("nodes.surface_parts").IOR == physics.WATER_IOR
    assert load("nodes.caustics").IOR == physics.WATER_IOR
    assert load("nodes.boats.wake").SPEC.nodes["k_scale"].values[0] == physics.G
    # The ring's dispersion, g + (σ/ρ) k², is worked out in its own nested group.
    assert load("nodes.boats.wake_ring").SPEC.nodes["ring_sk2"].values[1] == physics.SURFACE_TENSION
