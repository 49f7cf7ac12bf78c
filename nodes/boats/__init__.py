"""The node groups of what sits or moves on the water: `Water Wake` (`wake.py`) and its nested
groups, one module each, every one described beside its own nodes; `Water Keep Out` and the
floating fit (`Water Float Fit`)."""
