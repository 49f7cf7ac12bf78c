"""The whitecaps' coverage from the wind (Monahan and O'Muircheartaigh's), the foam's streaks,
and their drivers."""

import pytest
from conftest import load


@pytest.mark.parametrize(("wind", "share"), [(10.0, 0.0099), (15.0, 0.039), (20.0, 0.105)])
def test_coverage_is_monahan_s_in_a_breaking_sea(wind, share):
    math = load("water.sea.whitecap_math")
    assert math.whitecap_coverage(wind) == pytest.approx(share, rel=0.02)


def test_light_winds_raise_next_to_no_whitecaps():
    math = load("water.sea.whitecap_math")
    assert math.whitecap_coverage(3.0) == 0.0
    assert math.whitecap_coverage(5.0) < 0.001 * 0.5
    assert math.whitecap_coverage(0.0) == 0.0


def test_the_driver_expression_computes_the_same_coverage():
    math = load("water.sea.whitecap_math")
    expression = math.coverage_expression("u")
    for wind in (0.0, 3.0, 5.0, 7.5, 10.0, 15.0, 20.0, 40.0):
        value = eval(expression, {"__builtins__": {}}, {"pow": pow, "min": min, "max": max, "u": wind})
        assert value == pytest.approx(math.whitecap_coverage(wind), rel=1e-9, abs=1e-12), wind


def test_the_foam_is_drawn_into_streaks_from_beaufort_6_and_its_driver_says_the_same():
    math = load("water.sea.whitecap_math")
    assert math.streaks(5.0) == math.streaks(9.0) == 1.0  # bubbles in light and moderate winds
    assert 4.0 < math.streaks(12.0) < math.streaks(15.0) <= math.streaks(25.0) == math.STREAKS_MOST
    expression = math.streaks_expression("u")
    for wind in (0.0, 5.0, 10.0, 12.0, 15.0, 20.0, 25.0, 40.0):
        value = eval(expression, {"__builtins__": {}}, {"min": min, "max": max, "u": wind})
        assert value == pytest.approx(math.streaks(wind), rel=1e-9), wind
