"""The boat tools in the panel (floating, keep-out, wake) for the selected objects that are not
water, whichever object is active (`boat_tools_for`)."""

from ..operators import _switch
from ..operators.boats.floating import OBJECT_OT_water_float
from ..operators.boats.keep_out import OBJECT_OT_water_keep_out
from ..operators.boats.wake import OBJECT_OT_water_wake
from ..water import kind
from ..water.boats import floating, keep_out, wake
from ..water.values import is_water

# The boat tools' boxes, in the order drawn: each a `kind.FEATURES` key (`_DRAW`).
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


def _switch_buttons(row, context, cls, on_text, on_icon, off_text):
    """A switch's on and off buttons (`operators/_switch.py`), each greyed where its way may not
    run, as the two operators' buttons were; `on_text` None: the operator's own label."""
    for enable, text, icon in ((True, on_text, on_icon), (False, off_text, "X")):
        part = row.row(align=True)
        part.enabled = _switch.way_allowed(cls, enable, context)
        named = {} if text is None else {"text": text}  # text="" would draw no label at all
        button = part.operator(cls.bl_idname, icon=icon, **named)
        if button is not None:  # None while the operator's poll refuses (linked data)
            button.enable = enable


def draw_floating(layout, context, obj):
    """Float the selected objects on the water below them (or the selected one), or stop;
    `obj`'s state (`boat_tools_for`)."""
    box = layout.box()
    box.label(text="Floating", icon="MOD_OCEAN")
    row = box.row(align=True)
    _switch_buttons(row, context, OBJECT_OT_water_float, None, "CON_SHRINKWRAP", "Stop")
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


def draw_keep_out(layout, context, obj):
    """Keep the water out of the selected hulls, or let it in again; `obj`'s state."""
    box = layout.box()
    box.label(text="Dry Inside", icon="MOD_BOOLEAN")
    row = box.row(align=True)
    _switch_buttons(row, context, OBJECT_OT_water_keep_out, None, "MOD_BOOLEAN", "Let In")
    if obj is None:
        return
    for water in keep_out.kept_out_of(obj, context.scene):
        box.label(text=f"'{water.name}' is kept out of it")
        stale = keep_out.mask_out_of_date(obj, water)
        if stale is not None:
            box.label(text=stale, icon="ERROR")
            box.operator("object.water_keep_out", text="Keep Water Out Again", icon="FILE_REFRESH")


def draw_wake(layout, context, obj):
    """Make the selected objects leave a wake, or no longer; `obj`'s state."""
    box = layout.box()
    box.label(text="Wake", icon="FORCE_HARMONIC")
    row = box.row(align=True)
    _switch_buttons(row, context, OBJECT_OT_water_wake, "Add Wake", "FORCE_HARMONIC", "Remove")
    for modifier in wake.modifiers_of(obj) if obj is not None else ():
        box.label(text=f"Leaves a wake on '{modifier.id_data.name}'")
        note = wake.coarse_note(modifier)
        if note:
            box.label(text=note, icon="ERROR")
    for water in {m.id_data for m in (wake.modifiers_of(obj) if obj is not None else ())}:
        for problem in wake.bake_problems(water, context.scene):
            box.label(text=problem, icon="ERROR")
        box.operator("object.water_wake_bake", icon="FILE_REFRESH")


_DRAW = {"floating": draw_floating, "keep_out": draw_keep_out, "wake": draw_wake}


def draw_boat_tools(layout, context):
    """The boxes `boat_tools_for` picks, for the object it says."""
    tools, subject = boat_tools_for(context)
    for tool in tools:
        _DRAW[tool](layout, context, subject)
