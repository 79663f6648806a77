"""The data the scipy benchmark scripts share with the C++ benchmarks.

The same seeded numbers (splitmix64, as tests/support/splitmix.hpp) and the
same clamped uniform knots (as bspline/knot_vector.hpp clamped_uniform_knots),
so the Python rows evaluate exactly what the C++ rows do.
"""

import numpy as np

GAMMA = np.uint64(0x9E3779B97F4A7C15)


def splitmix_units(seed, count):
    """count doubles in [0,1): splitmix64 from `seed`, 53 bits each (as in C++)."""
    with np.errstate(over="ignore"):
        z = np.uint64(seed) + GAMMA * np.arange(1, count + 1, dtype=np.uint64)
        z = (z ^ (z >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
        z = (z ^ (z >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
        z = z ^ (z >> np.uint64(31))
    return (z >> np.uint64(11)).astype(np.float64) * 2.0**-53


def clamped_uniform_knots(p, count):
    """p+1 zeros, count-p-1 interior knots j/(count-p), p+1 ones (as casteljau's)."""
    spans = count - p
    interior = np.arange(1, spans) / spans
    return np.concatenate([np.zeros(p + 1), interior, np.ones(p + 1)])
