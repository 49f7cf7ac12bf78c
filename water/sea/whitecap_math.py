"""How much of the sea whitecaps cover, from the wind. Plain Python (tested in `tests/plain`).

Monahan and O'Muircheartaigh (1980) measured the sea's whitecap coverage as
W = 3.84e-6 U^3.41 at a wind of U m/s (10 m up): about 1% at 10 m/s, 4% at 15, 10% at 20. Below
about 4 m/s the sea hardly breaks at all, so the coverage here fades out between CALM and
BREAKING (their fit still gives 0.09% at 5 m/s). The ocean shading's `Whitecap Coverage` is
driven by this (a simple expression of the Ocean modifier's wind speed, `coverage_expression`).
"""

MONAHAN = (3.84e-6, 3.41)  # W = a U^b
CALM = 4.0  # m/s: no whitecaps below ...
BREAKING = 8.0  # ... Monahan's coverage from here on
MAX_COVERAGE = 0.5


def monahan(wind_speed):
    """Share of the sea whitecaps cover at `wind_speed` m/s (Monahan and O'Muircheartaigh)."""
    return MONAHAN[0] * max(wind_speed, 0.0) ** MONAHAN[1]


def whitecap_coverage(wind_speed):
    """The share the sea's whitecaps are given: Monahan's, faded out in light winds."""
    fade = min(1.0, max(0.0, (wind_speed - CALM) / (BREAKING - CALM)))
    return min(MAX_COVERAGE, monahan(wind_speed) * fade)


def coverage_expression(wind="u"):
    """`whitecap_coverage` as a simple-expression driver of the variable `wind` (m/s)."""
    fade = f"min(1, max(0, ({wind} - {CALM:g}) / {BREAKING - CALM:g}))"
    return f"min({MAX_COVERAGE:g}, {MONAHAN[0]:g} * pow(max({wind}, 0), {MONAHAN[1]:g}) * {fade})"


def crest_speed(wind_speed):
    """Metres a second the crests of a grown sea's peak waves run at: g / omega_p, with Pierson
    and Moskowitz's omega_p = 0.877 g / U, so U / 0.877."""
    return max(wind_speed, 0.0) / 0.877


# The foam's streaks (Beaufort 6 and up: "foam blown in streaks along the direction of the wind",
# dense from 9): the lace drawn out a times along the wind, 1 below STREAKS_FROM m/s, rising by
# 1 every STREAKS_PER m/s, at most STREAKS_MOST (`ocean_parts.STREAKS_INPUT`; 2 a^2 times longer than wide).
STREAKS_FROM = 9.0
STREAKS_PER = 0.5
STREAKS_MOST = 8.0


def streaks(wind_speed):
    """`Foam Streaks` at `wind_speed` m/s: 1 (bubbles) in light winds, up to STREAKS_MOST in a gale."""
    return min(STREAKS_MOST, max(1.0, 1.0 + (wind_speed - STREAKS_FROM) / STREAKS_PER))


def streaks_expression(wind="u"):
    """`streaks` as a simple-expression driver of the variable `wind` (m/s)."""
    return f"min({STREAKS_MOST:g}, max(1, 1 + ({wind} - {STREAKS_FROM:g}) / {STREAKS_PER:g}))"
