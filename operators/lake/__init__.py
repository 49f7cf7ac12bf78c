"""The lake shading's own operators: presets, the glint's sun and the bump image, Cycles' caustics
(`kind.FEATURES` allows them for lakes only)."""

from .choices import OBJECT_OT_water_bump_set, OBJECT_OT_water_sun_set
from .physical_caustics import OBJECT_OT_water_physical_caustics
from .presets import OBJECT_OT_water_preset_add, OBJECT_OT_water_preset_apply, OBJECT_OT_water_preset_remove

classes = (
    OBJECT_OT_water_preset_apply,
    OBJECT_OT_water_preset_add,
    OBJECT_OT_water_preset_remove,
    OBJECT_OT_water_sun_set,
    OBJECT_OT_water_bump_set,
    OBJECT_OT_water_physical_caustics,
)
