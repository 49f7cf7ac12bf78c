"""What the selected objects do on the water (`water/boats/`): float, keep the water out, leave a wake."""

from .floating import OBJECT_OT_water_float, OBJECT_OT_water_float_stop
from .keep_out import OBJECT_OT_water_keep_out, OBJECT_OT_water_let_in
from .wake import OBJECT_OT_water_wake_add, OBJECT_OT_water_wake_bake, OBJECT_OT_water_wake_remove

classes = (
    OBJECT_OT_water_float,
    OBJECT_OT_water_float_stop,
    OBJECT_OT_water_keep_out,
    OBJECT_OT_water_let_in,
    OBJECT_OT_water_wake_add,
    OBJECT_OT_water_wake_remove,
    OBJECT_OT_water_wake_bake,
)
