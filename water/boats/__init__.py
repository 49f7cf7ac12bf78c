"""What floats on a water and what it does to it: the float (`floating`, its rig `float_rig`, the
footprint's maths `footprint_math`), Keep Water Out (`keep_out`, its dry mask `dry_mask_math`)
and the wake (`wake`). They build on the water's own modules one level up (`kind`, `values`,
`waves`, `editable`, `float_constraints`: which objects float, which the surroundings and
removal read too)."""
