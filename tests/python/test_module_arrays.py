"""The numpy boundary rules of python/src/arrays.hpp, on BSplineCurve's batch
functions: which inputs are read in place, converted once or refused, how
out= is checked, and that chunked parameter checks name the right index.

References: each converted input must give exactly the float64 C-ordered
result (the same C++ call on the same doubles); the points themselves are
checked against scipy elsewhere (test_module_bspline.py)."""

import numpy as np
import pytest

import casteljau as cj

CHUNK = 1 << 18  # python/src/arrays.hpp kParameterChunk


@pytest.fixture(scope="module")
def curve():
    rng = np.random.default_rng(11)
    return cj.BSplineCurve(3, cj.clamped_uniform_knots(3, 40), 100.0 * rng.random((40, 3)))


@pytest.fixture(scope="module")
def parameters():
    return np.random.default_rng(12).random(1000)


def test_converted_inputs_give_the_float64_result(curve, parameters):
    expected = cj.points_at(curve, parameters)
    wide = np.empty(2000)
    wide[::2] = parameters
    for variant in (parameters.astype(np.float32).astype(np.float64), wide[::2], list(parameters),
                    np.asfortranarray(parameters)):
        got = cj.points_at(curve, variant)
        reference = cj.points_at(curve, np.ascontiguousarray(variant, dtype=np.float64))
        np.testing.assert_array_equal(got, reference)
    np.testing.assert_array_equal(cj.points_at(curve, wide[::2]), expected)
    small = parameters.astype(np.float32)
    np.testing.assert_array_equal(cj.points_at(curve, small), cj.points_at(curve, small.astype(np.float64)))
    integers = np.array([0, 1], dtype=np.int32)
    np.testing.assert_array_equal(cj.points_at(curve, integers), cj.points_at(curve, np.array([0.0, 1.0])))


def test_control_points_in_any_layout(curve):
    points = curve.control_points
    knots = curve.knots
    for variant in (np.asfortranarray(points), np.repeat(points, 2, axis=0)[::2], points.tolist()):
        assert cj.BSplineCurve(3, knots, variant) == curve
    single = points.astype(np.float32)
    assert cj.BSplineCurve(3, knots, single) == cj.BSplineCurve(3, knots, single.astype(np.float64))
    whole = np.rint(points).astype(np.int64)
    assert cj.BSplineCurve(3, knots, whole) == cj.BSplineCurve(3, knots, whole.astype(np.float64))


@pytest.mark.parametrize("value, error", [
    (np.array([0.5, 0.2], dtype=complex), TypeError),
    (np.array([True, False]), TypeError),
    (np.array(["a", "b"]), TypeError),
    (np.array([0.5, None], dtype=object), TypeError),
    (None, TypeError),
    (np.zeros((2, 2)), ValueError),
    (0.5, ValueError),
])
def test_refused_parameter_arrays(curve, value, error):
    with pytest.raises(error):
        cj.points_at(curve, value)


def test_ragged_control_points_are_a_value_error():
    with pytest.raises(ValueError, match="control_points"):
        cj.BSplineCurve(1, [0, 0, 1, 1], [[0.0, 1.0], [2.0]])


def test_empty_batches_give_empty_results(curve):
    assert cj.points_at(curve, np.empty(0)).shape == (0, 3)
    with pytest.raises(ValueError, match="empty"):
        cj.BSplineCurve(0, [0, 1], np.empty((0, 2)))


def test_out_is_written_in_place_and_checked(curve, parameters):
    out = np.empty((parameters.size, 3))
    assert cj.points_at(curve, parameters, out=out) is out
    np.testing.assert_array_equal(out, cj.points_at(curve, parameters))
    bad_outs = [np.empty((parameters.size, 2)), np.empty((parameters.size, 3), dtype=np.float32),
                np.empty((3, parameters.size)).T, np.empty(parameters.size * 3)]
    read_only = np.empty((parameters.size, 3))
    read_only.flags.writeable = False
    bad_outs.append(read_only)
    for bad in bad_outs:
        with pytest.raises(ValueError, match="out"):
            cj.points_at(curve, parameters, out=bad)
    with pytest.raises(TypeError, match="out"):
        cj.points_at(curve, parameters, out=[[0.0] * 3] * parameters.size)


def test_bad_values_are_named_by_index_across_chunks(curve):
    us = np.linspace(0, 1, CHUNK + 1000)
    for index in (0, CHUNK - 1, CHUNK, CHUNK + 999):
        bad = us.copy()
        bad[index] = np.nan
        with pytest.raises(ValueError, match=rf"us \[{index}\] is NaN"):
            cj.points_at(curve, bad)
        bad[index] = np.inf
        with pytest.raises(ValueError, match=rf"us \[{index}\] is infinite"):
            cj.points_at(curve, bad, extrapolate=True)
        bad[index] = 1.5
        with pytest.raises(ValueError, match=rf"us \[{index}\] = 1.5 is outside the domain \[0, 1\]"):
            cj.points_at(curve, bad)
        np.testing.assert_array_equal(cj.points_at(curve, bad, extrapolate=True)[index],
                                      cj.point_at(curve, 1.5, extrapolate=True))


def test_single_parameters_accept_python_and_numpy_scalars(curve):
    expected = cj.point_at(curve, 1.0)
    for u in (1, np.float32(1.0), np.int64(1), np.float64(1.0)):
        np.testing.assert_array_equal(cj.point_at(curve, u), expected)
    table = cj.derivatives_up_to(curve, 1, 2)  # an int u
    assert table.shape == (3, 3)
    np.testing.assert_array_equal(table[0], expected)


def test_threads_evaluate_at_once(curve, parameters):
    """The GIL is released during the batch: threads give the serial results."""
    from concurrent.futures import ThreadPoolExecutor
    batches = [np.roll(parameters, k) for k in range(8)]
    with ThreadPoolExecutor(4) as pool:
        results = list(pool.map(lambda us: cj.points_at(curve, us), batches))
    for us, got in zip(batches, results):
        np.testing.assert_array_equal(got, cj.points_at(curve, us))
