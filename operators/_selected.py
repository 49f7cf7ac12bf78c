"""What the object operators (float, keep water out, wake) share: the selected objects that are
not water, the water each one acts on, and one report for all of them."""

from ..water.boats.floating import water_for
from ..water.editable import NotEditableError
from ..water.values import is_water
from ._poll import selected_waters


def not_water(context):
    """The selected objects that are not water."""
    return [obj for obj in context.selected_objects if not is_water(obj)]


def _depth(obj):
    depth = 0
    while obj.parent is not None:
        obj, depth = obj.parent, depth + 1
    return depth


def run_on_selected(operator, context, act, errors, nothing, floating_first=True):
    """Calls `act(obj, water)` for each selected object that is not water, on the water
    `floating.water_for` picks for it (the selected or active water, `_poll.selected_waters`,
    else, with `floating_first`, the water it floats on, else the water straight below or above
    it); `errors` (exception types, the first raised when there is no water) become warnings, and
    the operator is cancelled, saying `nothing` and why, when no object was done. The poll
    (`_poll.selected_water_allowing`) has made sure at most one water is selected or active.
    Returns the operator's result."""
    chosen = next(iter(selected_waters(context)), None)
    # Every object's water is found before any is acted on: acting changes the scene (a wake's
    # modifier), and ray casting an evaluated water of the depsgraph from before that crashes.
    depsgraph = context.evaluated_depsgraph_get()
    targets, skipped = [], []
    # Parents before their children: floating a parent first, its child is then refused, with
    # a reason (it rides with it), not the other way round.
    for obj in sorted(not_water(context), key=_depth):
        try:
            targets.append((obj, water_for(obj, context.scene, errors[0], chosen, floating_first, depsgraph)))
        except errors as error:
            skipped.append(str(error))
    done = []
    for obj, water in targets:
        try:
            done += act(obj, water)
        except (*errors, NotEditableError) as error:
            skipped.append(str(error))
    for message in skipped:
        operator.report({"WARNING"}, message)
    if not done:
        operator.report({"ERROR"}, f"{nothing}: " + "; ".join(skipped))
        return {"CANCELLED"}
    operator.report({"INFO"}, "; ".join(done))
    return {"FINISHED"}


def take_off_selected(operator, context, take_off):
    """What Stop Floating, Let Water In and Remove Wake share: `take_off(obj)` on each selected
    object, the ones that cannot be edited (linked, overridden) said and left alone."""
    changes = []
    for obj in context.selected_objects:
        try:
            changes += take_off(obj)
        except NotEditableError as error:
            operator.report({"WARNING"}, str(error))
    operator.report({"INFO"}, "; ".join(changes) or "no change")
    return {"FINISHED"}
