"""Sidebar panel (3D view, tab "Water") for the active water object and the selected boats.

It draws the sockets of the material's `Water Surface` group node directly:
the node is the one source of truth, so what the `.blend` holds is what shows. Below them, the
boat tools (floating, keep-out, wake) for the selected objects that are not water, whichever
object is active (`boat_tools_for`).
"""

import bpy

from ..nodes import ocean
from ..nodes.material import bump_image, glint_sun, parts_built, water_node
from ..nodes.ocean_material import ocean_nodes
from ..nodes.water_surface import DEBUG_VIEWS
from ..nodes.water_waves import WAVE_COUNT
from ..operators.part_ops import PART_ITEMS
from ..water import camera_clip, kind, physical_caustics, underwater
from ..water.boats import floating, keep_out, wake
from ..water.editable import why_not_editable
from ..water.mirror import find_probe
from ..water.repair import needs_repair
from ..water.sea import open_sea
from ..water.surroundings import surroundings_collection, surroundings_modifier
from ..water.values import is_water, water_material
from ..water.waves import input_ids, input_property, wave_modifier

# The ocean shading's inputs the panel shows: (which group node, input name).
_OCEAN_INPUTS = (
    ("normal", "Bump Strength"),
    ("normal", "Tex Stretch"),
    ("shade", "Deep Color"),
    ("shade", "Glint Power"),
    ("shade", "Water Fresnel"),  # from version 8 of the shade
    ("shade", "Debug View"),
)
# The ocean shading's surroundings inputs (as the lake's): absent from groups before version 3.
_OCEAN_SURROUNDINGS = ("Absorption", "Foam Width", "Foam Amount", "Caustics", "Caustics Scale")

# The open sea's Ocean modifier settings the panel shows: (property, label).
_SEA_PROPS = (
    ("wind_velocity", "Wind Speed (m/s)"),
    ("wave_direction", "Wind Direction"),
    ("spectrum", "Spectrum"),
    ("choppiness", "Choppiness"),
    ("depth", "Depth"),
    ("random_seed", "Seed"),
)

_SECTIONS = (
    ("Waves", "MOD_WAVE", ("Wave Height", "Wave Length", "Bump Strength", "Bump Layers")),
    ("Wind", "FORCE_WIND", ("Wind Direction", "Wind Force")),
    ("Tint", "COLOR", ("Dull Color", "Dull Blend")),
    ("Glint", "LIGHT_SUN", ("Specular Power", "Specular Strength")),
    ("Surroundings", "OUTLINER_COLLECTION", ("part:depth", "part:foam")),
    ("Caustics", "LIGHT_SUN", ("part:caustics",)),
)
# The optional parts of the lake shading (`water_surface.PARTS`): a switch, then their inputs
# while they are in the shader.
_PARTS = {
    "depth": ("Absorption", "Scatter Color"),
    "foam": ("Foam Width", "Foam Amount"),
    "caustics": ("Caustics", "Caustics Scale"),
}
_PART_LABELS = {name: label for name, label, _tip in PART_ITEMS}

# The boat tools' boxes, in the order drawn: each a `kind.FEATURES` key and a `draw_<key>` method.
BOAT_TOOLS = ("floating", "keep_out", "wake")


def boat_tools_for(context):
    """(the boat tools' boxes to draw, from `BOAT_TOOLS`; the object whose state they show).

    The active object not water: every box, for it (its buttons say what to select). The water
    active: the boxes its kind allows while objects that are not water are selected too (the
    README's "select the objects and, if you like, the water"), for the first of them by name;
    the water alone: none. The operators act on every selected object that is not water, on the
    selected or active water."""
    active = context.active_object
    if not is_water(active):
        return BOAT_TOOLS, active
    boats = sorted((obj for obj in context.selected_objects if not is_water(obj)), key=lambda obj: obj.name)
    if not boats:
        return (), None
    return tuple(tool for tool in BOAT_TOOLS if kind.allows(active, tool)), boats[0]


class WATER_MT_presets(bpy.types.Menu):
    """Water presets: built-in and the user's."""

    bl_label = "Water Presets"
    bl_idname = "WATER_MT_presets"

    def draw(self, _context):
        from .. import presets

        for preset in presets.all_presets():
            op = self.layout.operator(
                "object.water_surface_preset_apply", text=preset.name, icon="USER" if preset.user else "NONE"
            )
            op.preset = preset.id


class VIEW3D_PT_water_surface(bpy.types.Panel):
    """Shape the active water object; float the selected objects on it, keep it out of them,
    make them leave a wake"""

    bl_label = "Water Surface"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Water"

    def draw(self, context):
        layout = self.layout
        if water_material(context.active_object) is None:
            layout.label(text="The active object is not water", icon="INFO")
            layout.operator("object.water_surface_add", icon="ADD")
        else:
            self.draw_water(layout, context)
            layout.use_property_split = False  # the lake's inputs split; the boat rows do not
        tools, subject = boat_tools_for(context)
        for tool in tools:
            getattr(self, f"draw_{tool}")(layout, context, subject)

    def draw_water(self, layout, context):
        """The active water's own settings, by its kind (or only the way back, needing repair)."""
        material = water_material(context.active_object)
        node = water_node(material)
        row = layout.row(align=True)
        row.label(text=f"Material: {material.name}", icon="MATERIAL")
        row.operator("object.water_remove", text="", icon="TRASH")
        why = why_not_editable(context.active_object, material)
        if why is not None:
            layout.label(text=why, icon="LIBRARY_DATA_DIRECT")
        problem = needs_repair(material)
        if problem is not None:
            # A replaced group, or one missing sockets: no input is drawn, only the way back.
            layout.label(text=problem, icon="ERROR")
            layout.operator("object.water_surface_repair", icon="TOOL_SETTINGS")
            if kind.allows(context.active_object, "waves"):
                self.draw_waves(layout, context.active_object)
            return
        obj = context.active_object
        if not kind.allows(obj, "presets"):  # ocean shading: its own inputs, the sea's or waves
            self.draw_ocean(layout, material)
            self.draw_ocean_surroundings(layout, obj, material)
            if kind.allows(obj, "whitecaps"):
                self.draw_sea(layout, obj, material)
            if kind.allows(obj, "waves"):
                self.draw_waves(layout, obj)
            self.draw_underwater(layout, obj)
            return

        row = layout.row(align=True)
        row.menu("WATER_MT_presets", text="Presets", icon="PRESET")
        row.operator("object.water_surface_preset_add", text="", icon="ADD")
        row.operator("object.water_surface_preset_remove", text="", icon="REMOVE")
        layout.use_property_split = True
        for title, icon, names in _SECTIONS:
            self.draw_section(layout.box(), context, material, node, (title, icon, names))
        self.draw_lake_tail(layout, context, material, node)
        self.draw_underwater(layout, obj)

    def draw_section(self, box, context, material, node, section):
        """One box of the lake's inputs, `section` = (title, icon, input names or "part:<name>"),
        with the box's own button (surroundings, physical caustics, the glint's sun)."""
        title, icon, names = section
        box.label(text=title, icon=icon)
        for name in names:
            if name.startswith("part:"):
                self.draw_part(box, node, name[len("part:") :])
                continue
            socket = node.inputs[name]
            if name == "Wind Direction":
                col = box.column(align=True)
                col.prop(socket, "default_value", index=0, text="Wind X")
                col.prop(socket, "default_value", index=1, text="Y")
            else:
                box.prop(socket, "default_value", text=name)
        if title == "Surroundings":
            self.draw_surroundings(box, context.active_object)
        if title == "Caustics":
            on = physical_caustics.is_on(context.active_object)
            op = box.operator(
                "object.water_physical_caustics",
                text=f"Physical Caustics (Cycles): {'On' if on else 'Off'}",
                icon="CHECKBOX_HLT" if on else "CHECKBOX_DEHLT",
            )
            if op is not None:  # None while the operator's poll refuses (linked water)
                op.enable = not on
        if title == "Glint":
            sun = glint_sun(material)
            box.operator(
                "object.water_surface_sun_set",
                text=f"Sun: {sun.name if sun else 'Default Light'}",
                icon="LIGHT_SUN",
            )

    def draw_lake_tail(self, layout, context, material, node):
        """Below the lake's inputs: its bump image, the debug view, its waves and the mirror's state."""
        image = bump_image(material)
        layout.operator(
            "object.water_surface_bump_set",
            text=f"Bump: {image.name if image else 'none'}",
            icon="IMAGE_DATA",
        )
        view = node.inputs["Debug View"]
        names = {number: label for number, _id, label, _tip in DEBUG_VIEWS}
        layout.prop(view, "default_value", text=f"Debug: {names.get(view.default_value, '?')}")

        self.draw_waves(layout, context.active_object)

        box = layout.box()
        probe = find_probe(context.active_object)
        eevee = context.scene.eevee
        ready = probe is not None and eevee.use_raytracing
        box.label(
            text="Mirror ready" if ready else "Mirror not set up",
            icon="CHECKMARK" if ready else "ERROR",
        )
        box.operator("object.water_mirror_setup", icon="MOD_MIRROR")

    def draw_part(self, box, node, name, spec=None):
        """A part's switch, and its inputs while it is in the shader (out, it costs nothing);
        `spec`: the shading's description with every part (default: the lake's)."""
        label, inputs = _PART_LABELS[name], _PARTS[name]
        on = name in (parts_built(node.node_tree, spec) if spec else parts_built(node.node_tree))
        op = box.operator(
            "object.water_part_switch",
            text=f"{label}: {'On' if on else 'Off'}",
            icon="CHECKBOX_HLT" if on else "CHECKBOX_DEHLT",
        )
        if op is not None:  # None while the operator's poll refuses (linked water)
            op.part, op.enable = name, not on
        if on:
            for input_name in inputs:
                box.prop(node.inputs[input_name], "default_value", text=input_name)

    def draw_underwater(self, layout, obj):
        """The `Underwater` switch: what a camera under the surface sees through."""
        on = underwater.find(obj) is not None
        text = "Underwater: on (fog by distance)" if on else "Underwater: off (clear as air)"
        button = layout.operator("object.water_underwater", text=text, icon="MOD_FLUIDSIM", depress=on)
        button.enable = not on
        node = underwater.fog_node(obj) if on else None
        if node is not None and "Light Shafts" in node.inputs:
            layout.prop(node.inputs["Light Shafts"], "default_value", text="Light Shafts")

    def draw_surroundings(self, box, obj):
        """Which collection the water measures its depth and shore against."""
        if surroundings_modifier(obj) is None:
            text = "Surroundings: none (add them)"
        else:
            collection = surroundings_collection(obj)
            text = f"Surroundings: {collection.name if collection else 'nothing'}"
        box.operator("object.water_surroundings_set", text=text, icon="OUTLINER_COLLECTION")

    def draw_ocean(self, layout, material):
        """The ocean shading's inputs: bump taps, deep colour, glint."""
        normal, shade = ocean_nodes(material)
        box = layout.box()
        box.label(text="Ocean", icon="MOD_OCEAN")
        box.use_property_split = True
        nodes = {"normal": normal, "shade": shade}
        for which, name in _OCEAN_INPUTS:
            if name in nodes[which].inputs:  # an older group lacks the newer inputs
                box.prop(nodes[which].inputs[name], "default_value", text=name)

    def draw_ocean_surroundings(self, layout, obj, material):
        """The ocean's depth colour, shore foam and caustics, and what it measures them against."""
        _normal, shade = ocean_nodes(material)
        box = layout.box()
        box.label(text="Surroundings", icon="OUTLINER_COLLECTION")
        box.use_property_split = True
        for name in _OCEAN_SURROUNDINGS:
            if name in shade.inputs and name not in _PARTS["caustics"]:
                box.prop(shade.inputs[name], "default_value", text=name)
        if "Caustics" in shade.inputs:  # a part: in the shader only while on
            self.draw_part(box, shade, "caustics", ocean.FULL_SHADE_SPEC)
        self.draw_surroundings(box, obj)

    def draw_sea(self, layout, obj, material):
        """The open sea's Ocean modifier settings and its whitecaps."""
        ocean, _fade = open_sea.sea_modifiers(obj)
        box = layout.box()
        box.label(text="Open Sea (Ocean modifier)", icon="MOD_OCEAN")
        box.use_property_split = True
        for prop, text in _SEA_PROPS:
            box.prop(ocean, prop, text=text)
        swell = open_sea.swell_values(obj)
        if swell["sea_swell_height"] > 0.0:
            height, period, (x, y) = (swell[key] for key in open_sea.SWELL_KEYS)
            text = f"Swell: {height:g} m, {period:g} s, to ({x:.2f}, {y:.2f})"
        else:
            text = "Swell: none"
        box.operator("object.water_sea_swell", text=text, icon="MOD_OCEAN")
        whitecaps = open_sea.whitecaps_input(material)
        if whitecaps is not None:
            box.prop(whitecaps, "default_value", text="Whitecaps")
        note = camera_clip.clip_note(bpy.context.scene, obj)
        if note is not None:  # the camera cuts the far sea off: offer to see it all
            clip_end = bpy.context.scene.camera.data.clip_end
            box.label(text=f"The camera's Clip End cuts the sea off at {clip_end:g} m", icon="ERROR")
            box.operator("object.water_camera_clip", icon="CAMERA_DATA")

    def draw_floating(self, layout, _context, obj):
        """Float the selected objects on the water below them (or the selected one), or stop;
        `obj`'s state (`boat_tools_for`)."""
        box = layout.box()
        box.label(text="Floating", icon="MOD_OCEAN")
        row = box.row(align=True)
        row.operator("object.water_float", icon="CON_SHRINKWRAP")
        row.operator("object.water_float_stop", text="Stop", icon="X")
        water = floating.floating_on(obj) if obj else None
        if water is None:
            return
        settings = floating.footprint_settings(obj)
        if settings:
            box.label(
                text=f"Floats on '{water.name}': draft {settings['draft']:.2g} m, "
                f"{settings['length']:.3g} x {settings['beam']:.3g} m"
            )
        else:
            box.label(text=f"Floats on '{water.name}' by its origin (float again: by its footprint)")
        stale = floating.rig_out_of_date(obj)
        if stale is not None:
            box.label(text=stale, icon="ERROR")
            again = box.operator("object.water_float", text="Float Again", icon="FILE_REFRESH")
            if again is not None and settings:  # as it floats now, from where it is now
                again.draft_from_bounds = False
                again.draft, again.length, again.beam = (settings[k] for k in ("draft", "length", "beam"))
                again.tilt_damping = floating.tilt_damping_of(obj)

    def draw_keep_out(self, layout, context, obj):
        """Keep the water out of the selected hulls, or let it in again; `obj`'s state."""
        box = layout.box()
        box.label(text="Dry Inside", icon="MOD_BOOLEAN")
        row = box.row(align=True)
        row.operator("object.water_keep_out", icon="MOD_BOOLEAN")
        row.operator("object.water_let_in", text="Let In", icon="X")
        if obj is None:
            return
        for water in keep_out.kept_out_of(obj, context.scene):
            box.label(text=f"'{water.name}' is kept out of it")
            stale = keep_out.mask_out_of_date(obj, water)
            if stale is not None:
                box.label(text=stale, icon="ERROR")
                box.operator("object.water_keep_out", text="Keep Water Out Again", icon="FILE_REFRESH")

    def draw_wake(self, layout, context, obj):
        """Make the selected objects leave a wake, or no longer; `obj`'s state."""
        box = layout.box()
        box.label(text="Wake", icon="FORCE_HARMONIC")
        row = box.row(align=True)
        row.operator("object.water_wake_add", icon="FORCE_HARMONIC")
        row.operator("object.water_wake_remove", text="Remove", icon="X")
        for modifier in wake.modifiers_of(obj) if obj is not None else ():
            box.label(text=f"Leaves a wake on '{modifier.id_data.name}'")
            note = wake.coarse_note(modifier)
            if note:
                box.label(text=note, icon="ERROR")
        for water in {m.id_data for m in (wake.modifiers_of(obj) if obj is not None else ())}:
            for problem in wake.bake_problems(water, context.scene):
                box.label(text=problem, icon="ERROR")
            box.operator("object.water_wake_bake", icon="FILE_REFRESH")

    def draw_waves(self, layout, obj):
        """The wave modifier's inputs, wave by wave, or a button to add it."""
        modifier = wave_modifier(obj)
        box = layout.box()
        if modifier is None:
            box.operator("object.water_waves_add", icon="MOD_WAVE")
            return
        box.label(text="Waves", icon="MOD_WAVE")
        names = input_ids(modifier)
        missing = [
            f"{name} {number}"
            for number in range(1, WAVE_COUNT + 1)
            for name in ("Amplitude", "Wavelength", "Speed", "Direction")
            if f"{name} {number}" not in names
        ]
        if missing:
            box.label(text=f"Group '{modifier.node_group.name}' lacks '{missing[0]}'", icon="ERROR")
            return
        box.use_property_split = True
        for number in range(1, WAVE_COUNT + 1):
            col = box.column(align=True)
            for name in ("Amplitude", "Wavelength", "Speed"):
                col.prop(*input_property(modifier, f"{name} {number}"), text=f"{name} {number}")
            owner, path = input_property(modifier, f"Direction {number}")
            row = col.row(align=True)
            row.prop(owner, path, index=0, text=f"Direction {number} X")
            row.prop(owner, path, index=1, text="Y")
