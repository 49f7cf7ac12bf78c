"""Issue 57 point 3: the Water panel offers what the selection allows. With objects that are not
water selected, the boat tools (Float on Water, Keep Water Out, the wake's buttons) show whatever
object is active, the water too, as the README's "select the objects (and, if you like, the
water)" says; their operators act on those objects and on the selected or active water.

The panel's choice is `ui.boats.boat_tools_for`, and its own `draw` (run through test_repair's
recording layout) draws what that says; the operators run on the real selection. Each tool is one
switch (`object.water_<feature>` with `enable`): its on and off buttons are the one operator."""

import bpy
import pytest
from test_repair import Layout, draw_panel

import harness

BOAT_OPERATORS = ("object.water_float", "object.water_keep_out", "object.water_wake")
# Each tool's buttons, as the artist sees them: (operator, text, `enable`); "" is the operator's label.
BOAT_BUTTONS = {
    ("object.water_float", "", True),
    ("object.water_float", "Stop", False),
    ("object.water_keep_out", "", True),
    ("object.water_keep_out", "Let In", False),
    ("object.water_wake", "Add Wake", True),
    ("object.water_wake", "Remove", False),
}


def _boats_ui():
    return harness.addon("ui.boats")


def _select(objects, active):
    for other in bpy.context.view_layer.objects.selected:
        other.select_set(False)
    for obj in objects:
        obj.select_set(True)
    bpy.context.view_layer.objects.active = active


def _operators(log):
    return {entry[1] for entry in log if entry[0] == "operator"}


def _buttons(monkeypatch):
    """Draws the panel; returns {(operator, text, the `enable` it sets)} of its buttons."""
    drawn = []
    operator = Layout.operator

    def recording(self, idname, text="", icon="NONE", **options):
        properties = operator(self, idname, text, icon, **options)
        drawn.append((idname, text, properties, getattr(self, "enabled", True)))
        return properties

    monkeypatch.setattr(Layout, "operator", recording)
    draw_panel()
    return {(idname, text, getattr(properties, "enable", True)) for idname, text, properties, _ in drawn}


def _greyed(monkeypatch):
    """Draws the panel; returns the switches' ways whose buttons are greyed: {(operator, enable)}."""
    drawn = []
    operator = Layout.operator

    def recording(self, idname, text="", icon="NONE", **options):
        properties = operator(self, idname, text, icon, **options)
        drawn.append((idname, properties, getattr(self, "enabled", True)))
        return properties

    monkeypatch.setattr(Layout, "operator", recording)
    draw_panel()
    monkeypatch.setattr(Layout, "operator", operator)
    return {(idname, getattr(props, "enable", True)) for idname, props, enabled in drawn if not enabled}


@pytest.fixture
def lake_and_boat(scene):
    api = harness.addon("api")
    lake = api.add_water(scene, name="Lake", size=8, resolution=8, see_surroundings=False).object
    boat = harness.add_cube(scene, (0.0, 0.0, 0.2), size=0.6, name="Boat")
    return lake, boat


def test_with_the_water_active_and_a_boat_selected_the_boat_tools_show_and_float_it(
    lake_and_boat, monkeypatch
):
    lake, boat = lake_and_boat
    _select((boat, lake), active=lake)
    assert _boats_ui().boat_tools_for(bpy.context) == (("floating", "keep_out", "wake"), boat)
    log = draw_panel()
    assert "object.water_remove" in _operators(log), "the water's own settings still show"
    assert set(BOAT_OPERATORS) <= _operators(log)
    assert BOAT_BUTTONS <= _buttons(monkeypatch), "on and off: one operator, `enable` set"
    labels = {op: getattr(bpy.types, "OBJECT_OT_" + op.split(".")[1]).bl_label for op in BOAT_OPERATORS}
    assert (
        labels["object.water_float"] == "Float on Water"
        and labels["object.water_keep_out"] == "Keep Water Out"
    )
    for operator in ("water_float", "water_keep_out", "water_wake"):
        assert getattr(bpy.ops.object, operator).poll(), operator
    # Each way's button greyed where that way may not run, as the two operators' were.
    off_ways = {(op, False) for op in BOAT_OPERATORS}
    assert _greyed(monkeypatch) == off_ways, "nothing floats, is kept dry or leaves a wake yet"

    assert bpy.ops.object.water_float(wake=False) == {"FINISHED"}
    assert _greyed(monkeypatch) == off_ways - {("object.water_float", False)}, "Stop, once it floats"
    floating = harness.addon("water.boats.floating")
    assert floating.floating_on(boat) == lake
    labels = [entry[1] for entry in draw_panel() if entry[0] == "label"]
    assert any(label.startswith("Floats on 'Lake'") for label in labels), "the boat's state, the water active"
    assert bpy.ops.object.water_float(enable=False) == {"FINISHED"}  # the panel's Stop
    assert floating.floating_on(boat) is None


def test_the_water_alone_shows_no_boat_tools_and_any_other_object_all_of_them(lake_and_boat, scene):
    lake, boat = lake_and_boat
    _select((lake,), active=lake)
    assert _boats_ui().boat_tools_for(bpy.context) == ((), None)
    assert not set(BOAT_OPERATORS) & _operators(draw_panel())
    _select((boat, lake), active=boat)  # the boat active: as before, every box, for it
    assert _boats_ui().boat_tools_for(bpy.context) == (("floating", "keep_out", "wake"), boat)
    _select((), active=boat)
    log = draw_panel()
    assert {"object.water_add", "object.water_float", "object.water_keep_out"} <= _operators(log)
    # Several boats with the water active: the first by name speaks for them.
    dinghy = harness.add_cube(scene, (2.0, 0.0, 0.2), size=0.4, name="Dinghy")
    _select((boat, dinghy, lake), active=lake)
    assert _boats_ui().boat_tools_for(bpy.context) == (("floating", "keep_out", "wake"), boat)


def test_the_active_water_is_the_one_acted_on_even_unselected(scene):
    """The water active but not selected (clicked, then the boat shift-clicked and the water
    deselected, or a script's context): the boat floats on it and is kept out of it, not the water
    straight below the boat."""
    api = harness.addon("api")
    upper = api.add_water(scene, name="Upper", size=8, resolution=8, see_surroundings=False).object
    lower = api.add_water(
        scene, name="Lower", size=8, resolution=8, see_surroundings=False, location=(0, 0, -3)
    ).object
    boat = harness.add_cube(scene, (0.0, 0.0, 0.2), size=0.6, name="Boat")
    floating = harness.addon("water.boats.floating")
    assert floating.water_for(boat, scene, LookupError) == upper, "the water straight below"
    _select((boat,), active=lower)
    assert not lower.select_get() and bpy.context.active_object == lower
    assert _boats_ui().boat_tools_for(bpy.context) == (("floating", "keep_out", "wake"), boat)
    assert bpy.ops.object.water_float(wake=False) == {"FINISHED"}
    assert floating.floating_on(boat) == lower
    assert bpy.ops.object.water_keep_out() == {"FINISHED"}
    assert harness.addon("water.boats.keep_out").kept_out_of(boat, scene) == [lower]
    # The same through a context override: a selected water and another active one is refused.
    with bpy.context.temp_override(active_object=lower, selected_objects=[boat, upper]):
        assert bpy.ops.object.water_float.poll(), "the boat floats: Stop may run"
        with pytest.raises(RuntimeError, match="Select one water at most"):
            bpy.ops.object.water_float()
        assert not bpy.ops.object.water_wake.poll(), "no wake to take off, and two waters"
        with pytest.raises(RuntimeError, match="Select one water at most"):
            bpy.ops.object.water_wake()
    with bpy.context.temp_override(active_object=upper, selected_objects=[boat, upper]):
        assert bpy.ops.object.water_wake.poll()
