#pragma once
// Inflection points of a plane curve of any kind: where its signed curvature
// changes sign. On each Bézier piece they are the roots of
// det[A, A', A''] (A the homogeneous curve (w x, w y, w); for a polynomial
// piece w = 1 and this is C' x C''), a polynomial of degree 3n - 3 built in
// Bernstein form by products (Farin §5.8) and solved by bernstein_roots.

#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/curves/curve_view.hpp"

namespace casteljau {

/// The parameters of the inflections of a plane curve, increasing: the roots
/// of odd multiplicity of its curvature inside the domain (a flat point,
/// where the curvature touches zero without changing sign, is not one; a
/// straight piece, where it is zero throughout, has none). A junction of
/// pieces counts when the curvature changes sign across it at a zero.
/// Error: a curve that is not plane ("inflections need a plane curve, this
/// one lives in R^3").
Expected<std::vector<double>> inflection_parameters(CurveView curve);

}  // namespace casteljau
