#pragma once
// Intersections of two plane curves of any kinds (CurveView), each reported
// once with its kind: transversal, tangent (with its multiplicity) or
// overlap (the two parameter intervals that trace the same points).
//
// Per pair of Bézier pieces whose boxes meet, the piece of lower degree n is
// implicitized: its implicit equation f(x, y) = 0 is the determinant of the
// n x n Bézout matrix of X w(t) - x(t) and Y w(t) - y(t), whose entries are
// linear in (X, Y) (Sederberg, Anderson & Goldman, "Implicit representation of
// parametric curves and surfaces", CVGIP 28, 1984). Substituting the other
// piece B(t) gives one polynomial p(t) = f(B(t)) of degree n m, built in
// Bernstein form by products (Farin §5.8) for n <= 3, whose roots in [0, 1]
// are the parameters on B where it meets the implicit curve, each with its
// intersection multiplicity (bernstein_roots: simple roots, clusters,
// tangencies found within rounding). Each root is inverted on the first
// piece (ops/closest_point: every point within the tolerance), and a simple
// root is refined by Newton on A(s) - B(t) = 0. p identically zero within
// rounding means both pieces lie on one algebraic curve: the overlap is
// found from the end points of each piece that lie on the other. Results of
// all piece pairs are merged: a hit at a knot or an end, seen from two
// pieces, is one intersection; overlaps of consecutive pieces join.
//
// tests/ops/intersection_corpus_test.cpp compares the results with answers
// computed in exact rational arithmetic (tests/support/exact_intersections.hpp:
// resultants and exact root isolation in GMP) on a corpus of 80 cases
// (tests/support/intersection_corpus.hpp: up to 36 crossings, tangencies of
// order 2 to 4, overlaps, shared ends, hits at 0, 1/2 and 1, near misses by
// one ulp, nearly parallel lines, loops, cusps, a tacnode); W8 in bench/
// does the same on 10^4 random, tangent and near-tangent cubic pairs.
//
// Curves in space (R^3, or more) rarely meet exactly; there an intersection
// is where they come within the tolerance: per pair of pieces whose boxes
// meet, pairs of sub-curves are halved down to 1e-6 of a piece and
// Gauss-Newton from their middles reaches the nearest pair of points; within
// the tolerance it is reported, transversal when the tangents differ,
// tangent otherwise (multiplicity 2, or 3 where the curvature vectors agree);
// an overlap where each piece traces the other between shared end points.

#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/interval.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/curves/curve_view.hpp"

namespace casteljau {

/// How two curves meet at an intersection.
enum class IntersectionKind {
  /// They cross with distinct tangents (multiplicity 1).
  transversal,
  /// They meet with a common tangent line: multiplicity 2 for an ordinary
  /// tangency (touching), 3 where they also cross (an inflection on the
  /// tangent), more for higher contact; 0 where two arcs of one algebraic
  /// curve continue one another at a shared point (contact of every order).
  tangent,
  /// They trace the same points over a stretch of each.
  overlap,
};

/// One intersection. For a point (transversal, tangent), `a` and `b` are
/// single parameters (lower == upper) in each curve's own domain; for an
/// overlap, a = [a0, a1] with a0 < a1 and b = [b(a0), b(a1)], the parameters
/// of the same two points on the second curve (b.lower > b.upper when the
/// second curve runs the other way). `point` is the intersection point (for
/// an overlap, the point at a0).
struct CurveIntersection {
  IntersectionKind kind = IntersectionKind::transversal;
  Interval a;
  Interval b;
  Point point;
  int multiplicity = 1;
};

/// The default distance within which two curves count as meeting: 1e-9 of
/// the larger curve's size (size_of), tolerances::kDefaultIntersectionRelativeTolerance.
Tolerance default_intersection_tolerance(CurveView a, CurveView b);

/// Every intersection of the curves a and b (plane curves, or curves of one
/// space: see above), sorted by the parameter on a: points where they meet (closed domains: ends and knots included, each
/// reported once), classified as above, and overlaps. Parameters of simple
/// intersections are refined to full precision; a tangency is known to about
/// the square root of the rounding (its parameter to ~1e-8 of the piece).
/// `tolerance`: the distance within which a root of the implicit equation
/// counts as a point of the other curve (a near miss closer than it is a
/// tangency; in space, the distance within which they count as meeting).
/// The point of a meeting in space is a's (b's is within the tolerance).
/// Errors: a curve in R^1 ("intersections need curves in R^2 or more, the
/// first lives in R^1"), curves of two dimensions ("intersections need curves
/// in one space, the first lives in R^2, the second in R^3"), a tolerance not
/// finite or <= 0; and (ErrorKind::limit) curves that run along one another
/// about the tolerance apart, neither crossing nor one overlap, where more
/// pairs of sub-curves come within the tolerance than the search visits
/// (tolerances::kIntersectionPairBudget): "the intersection search gave up
/// near parameters 0.33 and 0.67 of the first curve and the second, ...";
/// its answer would depend on the order of the search (issue 42).
Expected<std::vector<CurveIntersection>> intersections(CurveView a, CurveView b, Tolerance tolerance);

/// The self-intersections of a curve (plane, or in space as above, where the
/// parts' injectivity is a sufficient half-space test): pairs of parameters a < b with
/// C(a) = C(b), each once, as intersections of the curve with itself (`a`
/// and `b` both on it; overlaps where it runs back over itself). Between
/// different Bézier pieces as `intersections` finds them (the joint of two
/// consecutive pieces, and the closing point of a closed curve of one piece or
/// many, are not self-intersections, even where rounding finds them a few ulps
/// off or, at a smooth joint, ~1e-9 of a piece off: within
/// tolerances::kIntersectionJointWindow of both pieces, unless the curve turns
/// back there); inside one piece, the piece is cut where its
/// hodograph turns by half a turn or more (within a part whose hodograph's
/// coefficients lie in an open half plane the curve is injective), and
/// two parts of one piece are intersected by subdivision of their boxes and
/// Newton on C(s) - C(t) = 0, kept when it converges to rounding with
/// s != t (a cusp, where C' vanishes, is not a self-intersection).
/// Errors: a curve in R^1, a tolerance not finite or <= 0, and (a limit) a
/// curve that runs back along itself about the tolerance apart, as above.
Expected<std::vector<CurveIntersection>> self_intersections(CurveView curve, Tolerance tolerance);

/// The name of a kind as the CLI's JSON writes it: "transversal", "tangent", "overlap".
const char* kind_name(IntersectionKind kind);

}  // namespace casteljau
