"""Where a floating hull feels the water, and how those heights become its heave, pitch and roll.

Plain maths (no bpy), so it is tested without Blender. A hull rides the water under its
whole waterplane: its heave is the surface's mean over the footprint and its pitch and roll
the slopes of the plane that fits the surface there best. The footprint is sampled by probes
on a grid `ALONG` x `ACROSS` over its length and beam, and each probe's height is weighted by
Simpson's rule, so the probes' mean and moments are the footprint's integrals to within a few
per cent for waves longer than the hull (a plain mean of even points over-weighs the ends:
0.85 against 0.90 of a crest for waves four hulls long). Waves much shorter than the hull
cancel out over it, as they do under a real one.
"""

ALONG = 7  # probes over the length (odd, for Simpson's rule)
ACROSS = 3  # probes over the beam (odd)


def simpson(count):
    """Simpson's weights for `count` (odd, 3 or more) even points, summing to 1."""
    if count < 3 or count % 2 == 0:
        raise ValueError(f"Simpson's rule needs an odd count of 3 or more, not {count}")
    raw = [1.0] + [4.0 if i % 2 else 2.0 for i in range(1, count - 1)] + [1.0]
    total = sum(raw)
    return [w / total for w in raw]


def _even(count, half):
    return [-half + 2.0 * half * i / (count - 1) for i in range(count)]


def probe_grid(length, beam, centre=(0.0, 0.0), long_axis="X"):
    """[(x, y, weight)]: the probes in the object's own XY (metres from its origin, scale applied)
    over a footprint `length` x `beam` centred at `centre`, the length along `long_axis`."""
    if length <= 0.0 or beam <= 0.0:
        raise ValueError(f"a footprint needs a length and beam above 0 (got {length:g} x {beam:g})")
    points = []
    for along, wa in zip(_even(ALONG, length / 2.0), simpson(ALONG)):
        for across, wb in zip(_even(ACROSS, beam / 2.0), simpson(ACROSS)):
            x, y = (along, across) if long_axis == "X" else (across, along)
            points.append((centre[0] + x, centre[1] + y, wa * wb))
    return points


def _solve3(matrix, vector):
    """x with matrix x = vector, a 3 x 3 system (Cramer's rule)."""

    def det(m):
        return (
            m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
        )

    whole = det(matrix)
    if abs(whole) < 1e-12:
        raise ValueError("the probes lie on a line: no plane fits them")
    result = []
    for column in range(3):
        swapped = [[vector[r] if c == column else matrix[r][c] for c in range(3)] for r in range(3)]
        result.append(det(swapped) / whole)
    return result


def plane_weights(points):
    """For each probe (x, y, w), the weights (h, sx, sy) such that sum(weight x probe height) is,
    for the plane fitted to the heights by least squares weighted by w, its height at the origin
    (h) and its slopes along x (sx) and y (sy)."""
    normal = [[0.0] * 3 for _ in range(3)]
    for x, y, w in points:
        row = (1.0, x, y)
        for i in range(3):
            for j in range(3):
                normal[i][j] += w * row[i] * row[j]
    weights = []
    for x, y, w in points:
        # column of (A^T W A)^-1 A^T W for this probe: solve normal . c = w (1, x, y)
        weights.append(tuple(_solve3(normal, [w, w * x, w * y])))
    return weights


def default_draft(height):
    """How deep a hull `height` tall sits when the user has not said: a third of it, as a
    laden boat's hull (a box floats at its density's share; most boats at a third or less)."""
    return height / 3.0
