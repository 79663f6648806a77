#pragma once
// Every epsilon of casteljau lives here, with its unit and its reason
// (style rule 6). Exact operations take no tolerance; approximate ones
// require a Tolerance from the caller. Comparisons are relative to the data's
// scale (scale_of), never numeric_limits::epsilon() used as an absolute.

#include <cstddef>
#include <cstdint>
#include <limits>

namespace casteljau {

/// A distance in model units that an approximate operation must stay within
/// (flattening, degree reduction checks, later fitting and tessellation).
/// Must be finite and > 0; operations assert it.
struct Tolerance {
  double distance = 0.0;
};

namespace tolerances {

/// Relative size, against the control points' scale, below which a derivative
/// is treated as vanishing when looking for a tangent direction. A derivative
/// of a curve whose control points are O(s) is computed with an absolute error
/// of about n * 1e-16 * s per order; 1e-12 sits well above that noise for
/// degrees up to a few hundred and well below any real tangent.
inline constexpr double kVanishingDerivative = 1e-12;

/// Largest recursion depth accepted by subdivide_recursive: 2^24 + 1 points
/// (about 400 MB in 3D) is already far beyond any drawing need; deeper is
/// refused as a "huge size" rather than exhausting memory.
inline constexpr int kMaxSubdivisionDepth = 24;

/// Largest number of segments one flattening may produce. A request that
/// would need more (a tolerance tiny against the curve's size) is refused.
inline constexpr long kMaxFlattenSegments = 1L << 24;

/// Smallest arc-length accuracy accepted, as a fraction of the curve's size
/// (size_of: the diagonal of its control points' box). Each quadrature node
/// sums O(n) products of O(size) numbers, so the length of one interval is
/// known to about 1e-16 x size; over the thousands of intervals a long curve
/// needs, 1e-14 is what double precision can still promise (the request is
/// met down to 1e-13 in tests/ops/arc_length_test.cpp).
inline constexpr double kMinArcLengthRelativeTolerance = 1e-14;

/// Default accuracy of the CLI's `length`, relative to the curve's size.
inline constexpr double kDefaultArcLengthRelativeTolerance = 1e-12;

/// Default distance within which two curves count as meeting
/// (ops/intersection), relative to the larger curve's size: the roots of the
/// implicit equation are found to about 1e-15 of the size for simple
/// intersections and about 1e-8 of a piece for tangencies (the square root of
/// the rounding), so 1e-9 accepts every true intersection and refuses curves
/// that pass farther apart than a billionth of their size.
inline constexpr double kDefaultIntersectionRelativeTolerance = 1e-9;

// --- Arc fitting (ops/arc_spline) --------------------------------------------

/// Bisection steps on the end of the longest certified biarc from a point:
/// 12 put it within 2^-12 of the stretch's length of the longest one, so the
/// greedy chain is within a fraction of a biarc of the greedy optimum; more
/// halvings follow only when no biarc is certified yet.
inline constexpr int kArcFitReachSteps = 12;

/// Consecutive elements lie on one circle when their curvatures agree within
/// this fraction of the larger (or of 1 / the curve's size) and their tangents
/// at the joint within this angle: rounding leaves the two halves of a biarc
/// fitted to a true circle about 1e-15 apart; a join is certified again anyway.
inline constexpr double kArcSameCircle = 1e-9;

/// Largest sweep of one joined arc: short of a whole circle (which has no
/// bulge, start and end being one point), so that a circle becomes two arcs.
inline constexpr double kArcLargestSweep = 1.9 * 3.14159265358979323846;

// --- Intersections (ops/intersection) ----------------------------------------
// Parameters are on [0, 1] per piece, or fractions of a curve's domain width.

/// A Newton solution of A(s) = B(t) is a crossing when its two points are
/// within this fraction of the pieces' size (64 ulps): rounding alone, not a
/// near miss; near a tangency the points come that close only at the contact.
inline constexpr double kIntersectionConverged = 64.0 * 2.220446049250313e-16;

/// The sine of the angle between the two tangents below which a meeting is a
/// tangency, not a crossing, where the implicit equation cannot tell (two
/// parts of one algebraic curve, a branch of its double point). A crossing at
/// a smaller angle than 1e-6 rad is found as a tangency of multiplicity 2.
inline constexpr double kIntersectionTangentSine = 1e-6;

/// How far (a fraction of the pieces' size) the point of a simple root of the
/// implicit equation may be from the implicitized piece before Newton on the
/// pair: the root of a degree-36 resultant is known to about 1e-8 of a piece.
inline constexpr double kIntersectionLooseRoot = 1e-6;

/// Two crossings whose parameters differ by less than this (of the domain)
/// are one, seen from two pieces or two starts; tangencies, known to about the
/// square root of the rounding, are one within kIntersectionSameTangency.
inline constexpr double kIntersectionSameCrossing = 1e-12;
inline constexpr double kIntersectionSameTangency = 1e-7;

/// Parameters of joints and of the ends of overlaps agree within this
/// fraction of the domain (an end point of one piece found on another).
inline constexpr double kIntersectionJointSlack = 1e-9;

/// Tangent solutions within this of each other in both parameters are one
/// contact zone (zones are about sqrt(tolerance / curvature) wide); farther
/// than kIntersectionZoneReach they are two tangencies.
inline constexpr double kIntersectionContactZone = 1e-3;
inline constexpr double kIntersectionZoneReach = 5e-2;

/// Subdivision of two pieces (for parts of one algebraic curve) stops at
/// sub-curves this narrow in their parameter, where Newton takes over.
inline constexpr double kIntersectionSubdivisionWidth = 1e-6;

/// The order of contact of a tangency (ops/intersection): the two branches'
/// curvatures (in space, curvature vectors) count as equal below this
/// fraction of the larger (or of 1 / size), and then their rates of change
/// along the arc below kIntersectionContactRate of the larger. A tangency is
/// known to about 1e-8 of a piece, its curvatures to about 1e-6 and their
/// rates, by central differences over 1e-4 of the piece, to about 1e-3 (the
/// corpus' contacts of order 2 to 4 sit orders of magnitude either side).
inline constexpr double kIntersectionContactCurvature = 1e-4;
inline constexpr double kIntersectionContactRate = 1e-2;

/// Largest number of quadrature intervals one arc-length computation may use
/// (15 evaluations each). A curve that needs more at the requested accuracy
/// (a tolerance tiny against a long, wildly varying curve) is refused rather
/// than computed for minutes.
inline constexpr long kMaxArcLengthIntervals = 1L << 22;

/// Rounding of a squared distance |C - q|^2 built from Bernstein
/// coefficients (ops/closest_point): each of its 2n + 1 coefficients sums
/// products of coordinate differences, exact to a few ulps of the largest
/// one. Candidates whose squared distances differ by less than this times
/// (2n + 1) times the largest coefficient are not told apart by the bound:
/// all of them are polished on the curve and compared by their true
/// distance. 64 ulps (1.4e-14) covers the sums of degree-15 products with
/// room; a near tie that close is a tie at any accuracy users ask for.
/// Dimensionless (a fraction of the largest squared distance).
inline constexpr double kClosestPointTieSlack = 64.0 * 2.220446049250313e-16;

/// Resolution, in a Bézier piece's parameter t in [0, 1], of the roots that
/// inflections, curvature extrema and cusps are found at (ops/inflections,
/// ops/curvature_extrema): bernstein_roots stops splitting below it, and a
/// root this close to an end of a piece is taken as that end (the junction
/// logic decides there, so a point at a knot is reported once). 1e-12 is a
/// thousand times the resolution a simple root reaches and far below any
/// feature a curve's parameter can show. Unit: fraction of the piece's span.
inline constexpr double kCurvatureRootResolution = 1e-12;

/// A piece has constant curvature (a segment, a circular arc) when every
/// coefficient of the numerator N of dkappa/dt (ops/curvature_extrema) is
/// below this fraction of the largest coefficient of the two products it is
/// the difference of: what is left is their rounding (a few hundred ulps for
/// the degree-24 products of a rational cubic), not a variation of kappa.
/// 1e-10 is well above that noise; a real variation of kappa by less than
/// 1e-10 of its size is not a feature anyone looks for. Dimensionless.
inline constexpr double kConstantCurvature = 1e-10;

/// How far on each side of a stationary point (where a piece's velocity
/// vanishes) ops/curvature_extrema looks to tell a cusp (the velocities
/// there point opposite ways, as (t^2, t^3) at 0) from a stationary point on
/// a smooth arc (the same way, as (t^3, t^5)). The point itself is known to
/// about the cube root of the rounding for the latter (a triple root of
/// P . P'), 1e-5 of the piece; 1e-4 is beyond that and below any loop a
/// drawing shows at a point. Unit: fraction of the piece's span.
inline constexpr double kCuspSide = 1e-4;

/// The curvature is continuous across a junction of pieces (so a sign change
/// of dkappa/dt there is an extremum, not a jump) when the two one-sided
/// curvatures differ by less than this fraction of the larger: each is
/// computed to about 1e-14 relative from the pieces' derivatives, and a C^1
/// curve's jump is many orders larger. Dimensionless.
inline constexpr double kCurvatureContinuity = 1e-9;

/// Degree up to which kernels keep their de Casteljau triangle on the stack.
/// Beyond it, a batch call allocates one workspace for the whole call.
inline constexpr int kMaxStackDegree = 255;

/// Relative rounding unit used when a bound has to absorb floating-point
/// error: a few ulps of double (2^-52 = 2.2e-16) for the handful of
/// operations behind one control point of a subdivided curve.
inline constexpr double kRoundingSlack = 8.0 * 2.220446049250313e-16;

/// Rounding allowance of flattening, relative to the curve's scale (largest
/// absolute control-point coordinate), times max(1, n/4) and the weight ratio
/// max w / min w of a rational curve. flatten() certifies each segment against
/// tolerance minus this amount: it absorbs the rounding of the vertices
/// (de Casteljau, about n ulps of the scale each) and of the deviation bound
/// itself (a few dozen operations on O(scale) numbers), both far below
/// 1e-13 x scale. Unit: fraction of the scale.
inline constexpr double kFlattenRoundingAllowance = 1e-13;

/// Smallest flattening tolerance accepted, as a multiple of that allowance:
/// below 10 x allowance (about 1e-12 x scale) double precision cannot
/// certify the distance, and flatten() refuses the request instead of
/// subdividing down to rounding noise.
inline constexpr double kFlattenSmallestToleranceFactor = 10.0;

/// How far the two axes given for a circle, arc or ellipse (nurbs/conics.hpp)
/// may be from orthonormal: | |X| - 1 |, | |Y| - 1 | and |X . Y| must each be
/// at most this (dimensionless). Axes computed in double (a rotation matrix, a
/// normalized cross product) are off by a few ulps (1e-16); 1e-12 accepts those
/// and still refuses a forgotten normalization or a wrong axis. The accepted
/// axes are then re-orthonormalized (Gram-Schmidt), so the conic is as exact
/// as double allows whatever rounding the caller's axes carried.
inline constexpr double kOrthonormalAxes = 1e-12;


/// The smallest scale a relative comparison divides by or multiplies with
/// (max(scale, kScaleFloor)): data whose scale is 0 (every point at the
/// origin, a zero derivative) then compares absolutely instead of dividing
/// by zero. 1e-300 lies below any coordinate that matters and above the
/// subnormal range, where a quotient by it would overflow. Unit: model units.
inline constexpr double kScaleFloor = 1e-300;

// --- Valid model numbers (core/model_numbers.hpp) -----------------------------
// The ranges every make() accepts, chosen so that a valid curve or surface
// never fails to evaluate: its points and first derivatives are finite
// everywhere on its domain. They share out double's exponent range (up to
// DBL_MAX = 1.8e308). The first derivative of a degree-p B-spline or NURBS
// curve is computed from its de Boor triangle as (Q1 - Q0) (p / h) on rows
// (w P, w), h the width of the span, then C' = (A' - w' C) / w (The NURBS
// Book eq. 4.8), so
//   |C'| <= 4 p (w_max / w_min) M / h,   intermediates <= 4 p w_max M / h,
// M the largest coordinate. With p <= kMaxBSplineDegree (1e4), weights in
// [kMinWeight, kMaxWeight] (a ratio up to 1e100), M <= kMaxCoordinate and
// h >= kMinKnotSpan: |C'| <= 4e4 * 1e100 * 1e100 / 1e-100 = 4e304, and the
// intermediates stay below 4e254. A Bézier curve is the case h = 1, each
// partial derivative of a surface the case of its direction's degree and
// spans. Orders >= 2 grow like (2p/h)^k M: finite for any ordinary data, but
// at the corners of these ranges they can overflow to +-inf, as can products
// of two first derivatives (normals, curvature), which must be scaled first.
// Coordinates below kScaleFloor, subnormals included, are valid (they
// evaluate to finite values; relative comparisons treat them as scale 0).

/// Largest absolute coordinate of a control point (and of the points,
/// tangents, conic centres and radii the constructions take). 1e100: a third
/// of the exponent range (see above), far beyond any geometry (the
/// observable universe is 1e27 m), and squares of coordinate differences
/// (squared distances, dot and cross products of chords: <= 4e200 d) stay
/// finite. Unit: model units.
inline constexpr double kMaxCoordinate = 1e100;

/// Largest absolute knot, and parameter value of interpolation and fitting
/// (parameters become knots). 1e100 keeps sums and differences of knots
/// finite (the domain's width, midpoints (a + b) / 2, reversal's
/// (a + b) - t), and the width of a knot vector at most 2e200 times its
/// narrowest span, so that a parameter normalized to [0, 1] (Coons
/// boundaries, tessellation cells) still has normal-number spans (>= 5e-201).
/// Unit: parameter units.
inline constexpr double kMaxKnot = 1e100;

/// Narrowest non-empty knot span t_{i+1} - t_i > 0, and the closest two
/// parameters of interpolation and fitting may be. 1e-100: its reciprocal
/// (1e100) and p times it are representable with room for the coordinate
/// and weight ranges (see above); spans of a subnormal width (5e-324,
/// 1e-310) have no finite reciprocal at all. Spans of one ulp of ordinary
/// knots (1 and nextafter(1, 2): 2.2e-16) are far above it. Unit: parameter
/// units.
inline constexpr double kMinKnotSpan = 1e-100;

/// Smallest and largest weight of a NURBS (rational) curve or surface. The
/// ratio of any two weights is then at most 1e100 (no separate ratio bound
/// is needed, see above), and w P stays within 1e150. Weights that matter
/// in design lie within 1e-3..1e3; a weight of 1e-320 is positive but
/// subnormal, and 1/w overflows. Dimensionless.
inline constexpr double kMinWeight = 1e-50;
inline constexpr double kMaxWeight = 1e50;

/// Largest gap allowed where two curves or Bézier pieces are joined end to
/// start (join, from_bezier_pieces), relative to the larger of their scales
/// (scale_of of the control points, at least kScaleFloor so that curves at
/// the origin compare absolutely). Pieces produced by casteljau (decomposition,
/// splitting) meet to a few ulps, about 1e-15 relative; 1e-9 accepts data
/// rounded to 9 significant digits (files, other programs) and refuses any
/// visible gap. Unit: fraction of the scale.
inline constexpr double kJointRelativeGap = 1e-9;

/// Relative agreement under which the left and right k-th derivatives at a
/// knot count as equal when measuring continuity (continuity_at_knots, join).
/// Each side is computed by the basis derivatives of its own span, with a
/// rounding error of about p^k ulps of the derivative scale
/// s (p/h)^k (s the control points' scale, h the shorter adjacent span);
/// 1e-9 of that scale is far above the noise for degrees up to 10 and far
/// below a real jump. Unit: fraction of the derivative scale.
inline constexpr double kContinuityRelative = 1e-9;

/// Angle, in radians, under which the unit tangents on both sides of a knot
/// count as the same direction (G^1). 1e-7 rad is about sqrt of the rounding
/// of a normalized difference of two O(1) tangents (1e-14 relative): what
/// a tangent computed to ~1e-14 can certify.
inline constexpr double kTangentAngle = 1e-7;

// --- Fitting (interpolation/fit.hpp) --------------------------------------------

/// Smallest pivot D_i of the banded LDLᵀ factorization of a fit's normal
/// equations, relative to the diagonal entry A_ii it came from, below which
/// the system counts as singular (dimensionless). For a symmetric positive
/// definite matrix D_i / A_ii >= 1 / cond(A); the rounding of D_i is about
/// (p+1) ulps of A_ii, so a ratio under 1e-13 (500 ulps) cannot be told
/// from zero: the data do not determine the control points (too few
/// parameters in some knot span, λ = 0 with more control points than points).
inline constexpr double kFitSingularPivot = 1e-13;

/// The range of λ that GCV searches, in decades around the scale
/// λ₀ = tr(BᵀB) / tr(Ω) where data term and penalty weigh alike: from
/// λ₀ 10^-10 (the fit all but interpolates: 1 − tr H/(m+1) is at the level
/// of rounding and GCV is noise) to λ₀ 10^6 (heavily smoothed, nearly the
/// least-squares straight line: tr H = 3.3 effective degrees of freedom on
/// the 102 points of examples/noisy.csv, where the line has 2 and GCV's
/// choice 12.3; the line itself is only the limit λ → ∞).
inline constexpr double kGcvSearchDecadesBelow = 10.0;
inline constexpr double kGcvSearchDecadesAbove = 6.0;

/// Step of the GCV grid over log10 λ, in decades: 4 values per decade find
/// the basin of the minimum (GCV changes smoothly over a fraction of a decade
/// and its minima are broad); golden-section search then refines within it.
inline constexpr double kGcvGridStepDecades = 0.25;

/// Width of the final golden-section bracket of log10 λ, in decades: 1e-6
/// decades is a relative change of 2.3e-6 in λ, far below any visible change
/// of the curve, and a few dozen GCV evaluations from the grid's bracket.
inline constexpr double kGcvRefinementDecades = 1e-6;

/// Smallest n − tr H (residual degrees of freedom) at which GCV is trusted.
/// Near interpolation GCV = n RSS / (n − tr H)² is 0/0: both factors come
/// from cancellation, and rounding made it spuriously small (4e-4 against
/// its true limit 0.035 on 41 noisy points over x in [0, 6]). A thousandth
/// of a degree of freedom is far from any fit GCV should choose. Unit:
/// degrees of freedom.
inline constexpr double kGcvNearInterpolation = 1e-3;

// --- Size limits for untrusted input -----------------------------------------
// "Huge sizes" are refused with a clear error instead of exhausting memory or
// running for hours.

/// Highest degree of one Bézier curve accepted from outside (BezierCurve::make).
/// Evaluation costs O(n^2) per point: at n = 10^4 that is already 10^8
/// operations per point (tens of milliseconds), and no design needs more: long
/// point sets are interpolated or split into pieces, not made one polynomial.
inline constexpr int kMaxBezierDegree = 10'000;

/// Highest degree of one B-spline or NURBS curve accepted from outside
/// (BSplineCurve::make). The same bound as a Bézier curve's, so that every
/// Bézier curve converts (to_bspline); evaluation is O(p^2) per point and the
/// basis derivatives (basis_function_derivatives) take (p+1)^2 doubles.
inline constexpr int kMaxBSplineDegree = kMaxBezierDegree;

/// Most control points in one model (all pieces together), and most points
/// in one CSV point set. 10^7 points in 3D are 240 MB as doubles and about
/// 1 GB as parsed JSON: beyond any drawing or machining need, still inside
/// memory.
inline constexpr std::size_t kMaxControlPoints = 10'000'000;

/// Deepest nesting of elements in an SVG drawing, <use> references counted
/// as a level each (the reader walks the tree recursively). Hand-made and
/// exported drawings nest a few tens of groups; 256 keeps the walk's stack
/// small on every thread and still reads any drawing a person made.
inline constexpr int kMaxSvgDepth = 256;

/// Most elements one SVG drawing may draw, each instance of a <use> counted
/// (a chain of <use> that doubles at each level would otherwise expand to
/// 2^40 elements from a file of a few kilobytes). A 10 MB drawing holds at
/// most a few hundred thousand elements; the walk visits 10^6 in well under
/// a second.
inline constexpr std::size_t kMaxSvgElements = 1'000'000;

// --- Files for other programs (io/svg_writer, io/cad_exchange) ---------------

/// Default distance of the cubics `convert --to svg` puts in place of pieces
/// SVG cannot hold (rational, degree > 3), relative to the drawing's size (the
/// diagonal of its control points' box): far below what a screen or a plotter
/// resolves (1e-6 of a metre-wide drawing is a micrometre), while a circle
/// still needs only tens of cubics.
inline constexpr double kDefaultSvgCubicRelativeTolerance = 1e-6;

/// The resolution an IGES file states (global parameter 19, "minimum
/// user-intended resolution") and the uncertainty of a STEP file's context,
/// relative to the model's size: the numbers are written exactly (shortest
/// round-trip form), so the file claims the accuracy they keep; above double
/// rounding (1e-16 of the size) and below every CAD tolerance (OpenCASCADE's
/// confusion distance is 1e-7).
inline constexpr double kExchangeResolutionRelative = 1e-12;

/// Most values in one input file: JSON values (numbers, arrays, objects,
/// strings...) of a model JSON text, numbers of a CSV file. Exactly what
/// kMaxControlPoints points in 3D with weights need in JSON (10^7 point
/// arrays + 3*10^7 coordinates + 10^7 weights). A parsed JSON document takes
/// about 16 bytes per value and a CSV table 8 bytes per number, so this caps
/// their memory near 1 GB whatever the shape of the file.
inline constexpr std::size_t kMaxInputValues = 50'000'000;

/// Most parameters one `eval` may evaluate (--samples N, and all --at,
/// --params and sample parameters of all models together). The CSV output is
/// built in memory before it is written (nothing half-written), about 70 bytes
/// per 2D point: 10^7 points stay under 1 GB.
inline constexpr std::size_t kMaxEvaluationParameters = 10'000'000;

/// Highest degree of a Lagrange (barycentric) interpolant, and so at most
/// kMaxLagrangeDegree + 1 nodes (interpolate_lagrange, chebyshev_parameters).
/// The weights cost O(n^2) operations: 10^8 at this bound, a fraction of a
/// second; evaluation is O(n) per point. On Chebyshev nodes the barycentric
/// form stays accurate at this degree (Berrut & Trefethen 2004 §7).
inline constexpr int kMaxLagrangeDegree = 10'000;

/// Highest degree of a Lagrange interpolant converted to a Bézier curve
/// (to_bezier in interpolation/lagrange.hpp). The conversion solves a
/// Bernstein-Vandermonde system whose condition number grows like 2^n;
/// measured on Runge's function, the Bézier curve misses the interpolant by
/// 3e-11 (n = 30) and 5e-9 (n = 40) of its size on Chebyshev nodes, 4e-10
/// and 3e-7 on equispaced ones (tests/interpolation/lagrange_test.cpp),
/// about 100x more per 10 degrees. Above 40 the Bézier form would no longer
/// represent the polynomial to single-precision accuracy: refused.
inline constexpr int kMaxLagrangeBezierDegree = 40;

/// Highest derivative order the front ends accept. A polynomial curve's
/// derivatives of order > n vanish, and n!/(n-k)! overflows a double once
/// k > 170 for any n, so larger orders only make sense as zeros; rational
/// derivatives cost O(k^2) per point (NURBS Book A4.2). 1000 keeps every
/// request cheap.
inline constexpr int kMaxDerivativeOrder = 1000;

/// Highest total order k + l of a surface partial derivative d^(k+l)S/du^k dv^l
/// the front ends accept. A NURBS surface's derivative needs every lower pair
/// (NURBS Book A4.4): O(k^2 l^2) point operations, 50^4 ≈ 6e6 at k = l = 50,
/// while k = l = 300 already took 28 s. Polynomial derivatives above the
/// degree vanish, so the limit costs nothing real.
inline constexpr int kMaxSurfaceDerivativeOrder = 100;

/// Highest order q accepted by interpolate_natural (degree 2q - 1). The
/// natural end conditions are derivatives of orders q..2q-2 at the ends,
/// whose basis values grow like (2q-1)!/(q-1)! / h^j; past q = 8 (degree 15,
/// derivatives up to order 14) the collocation system loses most of double
/// precision on ordinary data, and no use of natural splines needs more
/// (q = 2, 3 are the common ones). Dimensionless.
inline constexpr int kMaxNaturalSplineOrder = 8;

/// Largest input file read, in bytes (1 GiB). Every text format casteljau
/// reads is parsed in memory, and a model or point set of the largest
/// accepted size takes well under 1 GiB of text; anything larger is refused
/// before a byte is read.
inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{1} << 30;

/// Most symbolic links followed from an output path to the file it names
/// (write_file_atomically replaces the link's target, not the link). 40 is
/// Linux's own limit (MAXSYMLINKS): past it the kernel answers ELOOP, and so
/// do we, for a link chain or a loop. A count of links, no unit.
inline constexpr int kMaxSymbolicLinks = 40;

// --- Tessellation and meshes (ops/tessellate.hpp, ops/mesh.hpp) ---------------

/// Smallest tessellation tolerance accepted, in ulps (2^-52) of the patches'
/// scale (their largest absolute coordinate, sampled). The tessellator
/// compares surface points with points interpolated on triangles; both carry
/// rounding of a few dozen ulps of the scale (a tensor-product evaluation, a
/// barycentric combination), so a tolerance of 10^4 ulps (about 2e-12
/// relative) is the smallest whose check still means something. Below it the
/// request is refused, not refined down to rounding noise.
inline constexpr double kMeshSmallestToleranceFactor = 1e4;

/// Most triangles one tessellation may produce. 10^7 triangles with their
/// vertices and normals take about 0.6 GB (indices 12 bytes, vertex and
/// normal 48 bytes, about half a vertex per triangle, plus the quadtree):
/// the edge of what fits in memory and far beyond what a viewer needs.
inline constexpr std::size_t kMaxMeshTriangles = 10'000'000;

/// The tessellator checks a candidate triangulation by sampling the surface
/// at interior parameters (a 7 x 7 grid per quadtree cell, the edge midpoints,
/// centroid and third points of each final triangle) and accepts it when the
/// largest sampled deviation is at most this fraction of the tolerance. The
/// deviation of a smooth surface from a triangle is close to a quadratic in
/// the parameters, vanishing at the vertices, and those samples catch the
/// maximum of such a quadratic to within about 25 %; 0.75 keeps the true
/// maximum below the tolerance with that margin (measured in
/// tests/ops/tessellate_test.cpp: the densely measured maximum stays below
/// the tolerance). Dimensionless.
inline constexpr double kMeshSampledDeviationFraction = 0.75;

/// Largest angle, in radians, between the unit normals at the corners of one
/// quadtree cell of a tessellation (60 degrees). Sampling can only be trusted
/// where the surface turns by a bounded amount over the cell; the bound also
/// keeps the triangles' own normals close to the surface normals at their
/// vertices, so that shading and orientation agree, even at a loose tolerance.
inline constexpr double kMeshMaxNormalTurn = 1.0471975511965976;

/// Deepest subdivision of one knot-span cell of a tessellation's quadtree, in
/// halvings per direction. Cells are addressed by integers (2^40 steps per
/// knot span) so that neighbours agree exactly on shared vertices; a cell at
/// this depth is accepted as it is (2^-40 of a span is below any tolerance
/// that kMeshSmallestToleranceFactor and kMaxMeshTriangles leave possible).
inline constexpr int kMeshMaxDepth = 40;

/// Two patch edges count as the same curve (so the tessellation shares their
/// vertices and is watertight across them) when their points at a few
/// normalized parameters, in the same or in opposite directions, are within
/// this fraction of the patches' scale; an edge whose samples are all within
/// it of one point is collapsed (a pole). Edges meant to be shared (written
/// by casteljau, or data rounded to 9 significant digits) agree to 1e-15 to
/// 1e-9 relative, like curves joined end to start (kJointRelativeGap); edges
/// that merely pass near each other differ by far more. Unit: fraction of the
/// scale.
inline constexpr double kMeshSharedEdgeRelative = 1e-9;

/// Two vertices of shared edges coming from different patches are one
/// vertex when their normalized edge parameters differ by at most this
/// (dimensionless): both patches then put the same point there, to rounding.
/// Vertices of one edge are never merged with each other.
inline constexpr double kMeshSameEdgeParameter = 1e-12;

/// Subcells (in all patches together) whose second differences estimate, before
/// any refinement, how many cells a tessellation needs at least
/// (src/ops/tessellate_estimate.hpp): each knot span gets m x m of them, m =
/// max(1, floor(sqrt(4096 / spans))), and costs one grid batch of (2m + 1)^2
/// points. 4096 subcells resolve the curvature of smooth surfaces far finer
/// than the 10^6 and more cells at which the estimate can refuse a request,
/// for about 2 x 10^4 surface points: milliseconds, a few per cent of the
/// smallest tessellation. Unit: subcells.
inline constexpr std::size_t kMeshEstimateSubcells = 4096;

/// How far below the limit the up-front estimate of a tessellation must stay
/// for the tolerance it suggests to fit (a refused request names the
/// tolerance at which the estimate is kMaxMeshTriangles / 8). The estimate
/// counts two triangles a cell where a fan has four, and the ideal cell size
/// where the quadtree's halving gives cells down to half that size each way,
/// so the real count is 2 to 8 times the estimate: measured 3.3 to 7.9 on a
/// sphere, two tori, a bicubic patch, a paraboloid and a bicubic B-spline
/// with a bump, from 0.01 to 3e-5 (tests/ops/tessellate_estimate_test.cpp
/// records the ratios).
/// Dimensionless.
inline constexpr double kMeshEstimateMargin = 8.0;

/// Most progress reports of one tessellation (ops/tessellate.hpp): a report
/// whenever the fraction done has grown by 1/200, a half per cent, which a
/// terminal line shows as smooth progress at a negligible cost. Unit: calls.
inline constexpr int kMeshProgressReports = 200;

// --- Surface figures (render/surface_plots.hpp) -------------------------------

/// Distance tolerance of the shaded image of `plot` and the gallery, relative
/// to the diagonal of the surfaces' control-point box (dimensionless): 1/500
/// of the figure's extent is about one pixel in a 700-pixel panel, so the
/// facets of the mesh do not show in the shading.
inline constexpr double kShadedSurfaceRelativeTolerance = 2e-3;

// --- Figures (render/layout.hpp, render/plots.hpp) ------------------------------

/// A flattened curve deviates from the true curve by at most this many pixels
/// on screen: below what anti-aliasing can show, so curves look smooth.
inline constexpr double kCurveTolerancePixels = 0.25;

/// Flattening tolerance of a curve in a panel with a logarithmic axis,
/// where a model distance is no fixed number of pixels, relative to the
/// curve's control box (a Bernstein graph's: to its height, at most 1): one
/// ten-thousandth, invisible at any canvas size a figure has. Dimensionless.
inline constexpr double kLogAxisRelativeTolerance = 1e-4;

/// Largest Bernstein degree plotted (n + 1 curves of degree n in one figure;
/// beyond this the figure is an unreadable black area and the work is wasted).
inline constexpr int kMaxPlottedBasisDegree = 1000;

/// Largest degree of a curve piece a figure draws. Certifying a segment of a
/// degree-n piece costs two de Casteljau triangles, O(n^2), per trial step
/// (ops/flatten.hpp), and a curve of random control points needs about
/// 50 n^0.4 segments at a quarter pixel (124 at n = 100, 473 at n = 2000),
/// so the time grows like n^2.4 to n^3: measured 0.5 s at degree 500, 1.4 s
/// at 1000, 12 s at 2000 (one core, random control points, 2026-12-01);
/// degree 10,000 (what model JSON accepts) would take many minutes. Beyond
/// 1000, the limit of the Bernstein figures too, figures refuse the curve at
/// once (render/layout.hpp, check_plotted_degree).
inline constexpr int kMaxPlottedCurveDegree = 1000;

/// Largest degree whose de Casteljau construction (plot --construction) a
/// figure draws: its n levels hold n(n+1)/2 segments and n(n-1)/2 points,
/// 20,100 segments at degree 200 (an SVG of about 1.5 MB, already a dark
/// tangle); degree 500 wrote 9 MB, degree 1000 took 6 s of CPU for a PNG.
inline constexpr int kMaxConstructionDegree = 200;

/// Largest width, height or diagonal of the data one figure shows, in model
/// units (about 4.4e304): a range is widened by 5 % margins and, for equal
/// aspect, stretched by up to the plot area's aspect ratio (at most 16384 / 10
/// pixels), and 2^-12 of the largest double keeps all of that finite.
inline constexpr double kMaxPlottedWidth = std::numeric_limits<double>::max() / 4096.0;

}  // namespace tolerances
}  // namespace casteljau
