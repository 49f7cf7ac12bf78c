"""How each preset key reaches a water that exists: the table `apply.py`, the one path, follows.
Plain Python (no bpy): `tests/plain/test_values_keys.py` walks it against `presets/schema.py`'s
fields and `kind.FEATURES`, so a new key or feature cannot miss it.

Every key of `schema.FIELDS` is one of three:

* a shader key (its field names a socket): a value of the water's shading group, set by
  `values.set_values` (a part whose switch crosses 0 comes in or goes out) and read by
  `values.read_values`; an ocean's shading holds only those it shares with the lake's;
* `WATER_KEYS`: a part of the water beside its shading, with the `kind.FEATURES` key that allows
  it: `apply.py` has one step that applies it and one reader (`_STEPS`, `_READERS`), used where
  the water's kind allows it and skipped elsewhere, as a preset's lake-only shader keys are on the
  ocean (a preset holds every key);
* `ADDING_KEYS`: made when the water is added (`plane.add_water`) and kept since: `write_values`
  and `apply_preset` leave them alone, as the README says; each says what changes it later.
"""

WATER_KEYS = {
    "underwater": "underwater",  # the hidden body a camera under the surface sees through
    "light_shafts": "underwater",  # a value of that body's fog: needs Underwater on
    "whitecaps": "whitecaps",  # the open sea's ocean shading (not a lake socket)
}

ADDING_KEYS = {
    "shading": "the material is built for its shading when the water is added",
    "size": "the plane's mesh is made when the water is added",
    "resolution": "the plane's mesh is made when the water is added",
    "waves": "added later with add_waves (Add Waves in the panel)",
    "sea": "the open sea's mesh and Ocean modifier are made when it is added",
    "sea_wind_speed": "the open sea's grid is graded to its wind's waves when it is added",
    "sea_spectrum": "the open sea's Ocean modifier, set when it is added (the panel shows it)",
    "sea_choppiness": "the open sea's Ocean modifier, set when it is added (the panel shows it)",
    "sea_depth": "the open sea's Ocean modifier, set when it is added (the panel shows it)",
    "sea_seed": "the open sea's Ocean modifier, set when it is added (the panel shows it)",
    "sea_swell_height": "changed later with set_swell (the panel's Swell)",
    "sea_swell_period": "changed later with set_swell (the panel's Swell)",
    "sea_swell_direction": "changed later with set_swell (the panel's Swell)",
}

# The `kind.FEATURES` keys no key of `WATER_KEYS` names, each with what decides it instead.
FEATURES_WITHOUT_VALUES = {
    "ray_tracing": "the mirror set-up",
    "surroundings": "set_surroundings",
    "shader_parts": "the shader keys that switch a part (absorption, foam_amount, caustics)",
    "floating": "float_on_water",
    "wake": "add_wake_source",
    "keep_out": "keep_water_out",
    "repair": "Repair Water",
    "mirror": "setup_mirror",
    "physical_caustics": "set_physical_caustics",
    "presets": "apply_preset's own refusal (lake water only)",
    "sun_choice": "the glint's sun operator",
    "bump_choice": "the bump image operator",
    "stored_normal": "the ocean's waves",
    "waves": "add_waves; the waves key only when adding",
    "swell": "set_swell; the sea_swell_* keys only when adding",
}
