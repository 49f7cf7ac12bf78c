"""What the selected objects do on the water (`water/boats/`): float, keep the water out, leave a wake."""

from .floating import OBJECT_OT_water_float
from .keep_out import OBJECT_OT_water_keep_out
from .wake import OBJECT_OT_water_wake, OBJECT_OT_water_wake_bake

classes = (
    OBJECT_OT_water_float,
    OBJECT_OT_water_keep_out,
    OBJECT_OT_water_wake,
    OBJECT_OT_water_wake_bake,
)
