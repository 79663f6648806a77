#pragma once
// The checks of the parameters given to the curve operations that cut a
// curve (split_at, segment): one rule and one message per operation, the
// same for every curve kind (Bézier, piecewise Bézier, B-spline/NURBS), so
// the same mistake reads the same whatever the curve.

#include "casteljau/core/expected.hpp"
#include "casteljau/core/interval.hpp"

namespace casteljau {

/// u finite and strictly inside the domain, so that both parts of a split
/// have a domain of positive length ("the split parameter 1.5 is not
/// strictly inside the domain [0, 1]").
Status check_split_parameter(double u, Interval domain);

/// u0 and u1 finite, inside the closed domain, and u0 < u1: the ends of a
/// segment ("the segment [0.5, 0.25] needs its start below its end").
Status check_segment_parameters(double u0, double u1, Interval domain);

}  // namespace casteljau
