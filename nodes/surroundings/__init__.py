"""What lies around and under a water, lake or open sea: `Water Surroundings` measures it on the
water's hidden cache, `Water Surroundings Sample` reads it onto the water after its waves; a
module each, the attribute names between them in `surroundings_parts.py`."""
