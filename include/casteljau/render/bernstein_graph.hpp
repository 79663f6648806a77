#pragma once
// The graph t -> B_{n,k}(t) of one Bernstein polynomial as a certified
// polyline, from its closed form. A figure of the basis of degree n draws n+1
// such graphs: written as Bézier curves of degree n (bernstein_graph in
// plots.hpp) each evaluation costs O(n^2) and the figure O(n^3) times the
// vertices per graph; from the closed form a vertex costs O(n) (bernstein(),
// one running product) and so does the bound that certifies a segment.

#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/core/vec.hpp"

namespace casteljau::render {

/// An upper bound on |B''_{n,k}(t)| over t in [a, b] (0 <= a <= b <= 1), the
/// smaller of two certified bounds, each evaluated through bernstein() (O(n)):
/// - the Bernstein form B''_{n,k} = n (n-1) (B_{n-2,k-2} - 2 B_{n-2,k-1} +
///   B_{n-2,k}) (Farin §5.3, the derivative of a Bézier curve), bounded by
///   n (n-1) max(M_{k-2} + M_k, 2 M_{k-1}) with M_j the largest value of the
///   unimodal B_{n-2,j} on [a, b] (at its mode j/(n-2), clamped into [a, b]);
///   tight away from the peak, loose by a factor of about n t (1-t) at it;
/// - for 0 < a and b < 1, the logarithmic form B'' = B (g^2 + g') with
///   g = (log B)' = k/t - (n-k)/(1-t) decreasing and g' = -k/t^2 - (n-k)/(1-t)^2
///   negative, so |B''| <= max B * max(g(a)^2, g(b)^2, k/a^2 + (n-k)/(1-b)^2);
///   tight at the peak (where g = 0).
/// Rounding (3n ulps per bernstein value) is absorbed by a factor
/// 1 + 4 n tolerances::kRoundingSlack. 0 for n < 2 (a line).
double bernstein_second_derivative_bound(int n, int k, double a, double b);

/// Vertices (t_i, B_{n,k}(t_i)), 0 = t_0 < ... < t_m = 1, of a polyline within
/// `tolerance` of the graph of B_{n,k} in the vertical direction, hence in
/// Hausdorff distance: on each [t_i, t_{i+1}] the graph deviates from its chord
/// by at most (t_{i+1} - t_i)^2 / 8 max |B''| (the linear interpolation error),
/// certified by bernstein_second_derivative_bound against the tolerance minus
/// the vertices' rounding (2 n tolerances::kRoundingSlack, B <= 1). Steps are
/// taken as long as the bound allows (about sqrt(8 tolerance / |B''|)), so the
/// count is near the fewest such a bound permits. O(n) per trial step, about
/// two trials per vertex. Errors: n outside [1, tolerances::kMaxBezierDegree],
/// k outside [0, n], a tolerance that is not finite and > 10 x that rounding,
/// more than tolerances::kMaxFlattenSegments segments.
Expected<std::vector<Vec2>> bernstein_graph_polyline(int n, int k, Tolerance tolerance);

}  // namespace casteljau::render
