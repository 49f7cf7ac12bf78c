"""The open sea: Blender's Ocean modifier set from the wind (`open_sea`, its maths `sea_math`),
the mesh that reaches the horizon (`sea_mesh`) and the whitecaps (`whitecaps`, their maths
`whitecap_math`). They build on the water's own modules one level up (`waves`, `editable`)."""
