"""The node groups a moving object leaves on the water: `Water Wake` (`wake.py`) and its nested
groups, one module each, every one described beside its own nodes."""
