#pragma once
// The ops layer's own tolerances and limits: flattening, arc length,
// intersections, arc fitting, closest points, curvature features and
// tessellation (core/tolerance.hpp says why each layer keeps its tolerances
// beside its code).

#include <cstddef>

namespace casteljau::tolerances {

// --- Flattening and arc length (ops/flatten.hpp, ops/arc_length.hpp) ---------

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

/// Largest number of quadrature intervals one arc-length computation may use
/// (15 evaluations each). A curve that needs more at the requested accuracy
/// (a tolerance tiny against a long, wildly varying curve) is refused rather
/// than computed for minutes.
inline constexpr long kMaxArcLengthIntervals = 1L << 22;

/// A rational piece whose weights, in standard form (the end weights made 1 by
/// a Möbius reparameterization, Farin §13.5), differ by more than this ratio
/// is halved until they do not, before quadrature (ops/arc_length): weights
/// (1, 1e20, 1) put the whole curve but its corner within 1e-10 of the
/// parameter's ends, where 15 nodes see only the corner (the length came out
/// 0). Each halving takes about the square root of the ratio; the NURBS
/// circle's sqrt(2) and every conic of moderate weights stay one piece.
inline constexpr double kArcLengthWeightRatio = 16.0;

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

/// An arc whose sagitta is at most this fraction of the curve's size is
/// written as the straight segment it is within rounding (bulge 0), when the
/// sagitta fits in what the certificate leaves of the tolerance: a straight
/// stretch fitted by a biarc comes out with bulges of 1e-15, whose centres
/// 1e15 away no reader can place (ezdxf's bulge_to_arc put such an arc of the
/// sailboat 0.49 mm off).
inline constexpr double kArcStraightSagitta = 1e-12;

// --- Many curves (ops/closest_among_curves, ops/intersections_among_curves) ---

/// A curve's tight bounding box (ops/bounds) is widened by this fraction of
/// its diagonal plus its largest |coordinate| before it prunes: its extremes
/// are exact to rounding (about 1e-16 of those), and a box cut short could
/// drop the nearest curve or a meeting.
inline constexpr double kBoxRoundingMargin = 1e-9;

// --- Intersections (ops/intersection) ----------------------------------------
// Parameters are on [0, 1] per piece, or fractions of a curve's domain width.

/// Default distance within which two curves count as meeting
/// (ops/intersection), relative to the larger curve's size: the roots of the
/// implicit equation are found to about 1e-15 of the size for simple
/// intersections and about 1e-8 of a piece for tangencies (the square root of
/// the rounding), so 1e-9 accepts every true intersection and refuses curves
/// that pass farther apart than a billionth of their size.
inline constexpr double kDefaultIntersectionRelativeTolerance = 1e-9;

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

/// Two consecutive pieces of a curve (or the two ends of a closed one) meet at
/// their joint; a meeting found within this fraction of both pieces of it is
/// that joint, found off by rounding (a smooth joint is a root of
/// multiplicity 2 of the implicit equation, known to ~1e-8 of a piece), unless
/// the curve turns back there (the cosine of the angle between the arriving
/// and leaving directions below kJointReversalCosine, within 8 degrees of a
/// reversal): elsewhere the two pieces leave the joint apart at a rate of at
/// least sin 4 degrees of their speed, and meet again only after 0.14 of the
/// radius of curvature, far outside this window for any piece whose control
/// polygon's legs differ by less than 1e5 in length.
inline constexpr double kIntersectionJointWindow = 1e-6;
inline constexpr double kJointReversalCosine = -0.99;

/// Tangent solutions within this of each other in both parameters are one
/// contact zone (zones are about sqrt(tolerance / curvature) wide); farther
/// than kIntersectionZoneReach they are two tangencies.
inline constexpr double kIntersectionContactZone = 1e-3;
inline constexpr double kIntersectionZoneReach = 5e-2;

/// Subdivision of two pieces (for parts of one algebraic curve) stops at
/// sub-curves this narrow in their parameter, where Newton takes over.
inline constexpr double kIntersectionSubdivisionWidth = 1e-6;

/// The pairs of sub-curves one subdivision search may visit, and as many
/// again outside the contact zones it found. Along a contact of order k the
/// curves stay within the tolerance over about tolerance^(1/k) of their
/// parameters, and every pair there meets (one of the corpus' contacts of
/// order 3 and 4 in space spends the first budget); a curve running back
/// along itself a few tolerances off does the same outside any zone. A search
/// that spends both, or the first with no zone found, with pairs still
/// meeting is refused (ErrorKind::limit), naming where:
/// its answer would depend on the order of the search. Issue 42's fuzzer's
/// curves of degree 10 to 14 spend it in 0.3 to 1.2 s.
inline constexpr std::size_t kIntersectionPairBudget = 200000;

/// The order of contact of a tangency (ops/intersection): the two branches'
/// curvatures (in space, curvature vectors) count as equal below this
/// fraction of the larger (or of 1 / size), and then their rates of change
/// along the arc below kIntersectionContactRate of the larger. A tangency is
/// known to about 1e-8 of a piece, its curvatures to about 1e-6 and their
/// rates, by central differences over 1e-4 of the piece, to about 1e-3 (the
/// corpus' contacts of order 2 to 4 sit orders of magnitude either side).
inline constexpr double kIntersectionContactCurvature = 1e-4;
inline constexpr double kIntersectionContactRate = 1e-2;

// --- Closest points and curvature features (ops/closest_point, ops/inflections, ops/curvature_extrema) ---

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

/// Two local minima of the distance (ops/closest_point, local_closest_points)
/// whose points are closer than this fraction of the scale (the curve's size
/// or the query's coordinates) and whose parameters are closer than this
/// fraction of the domain are one minimum found twice: a root of the slope a
/// few ulps before a knot and the knot itself. Two true minima are parted by a
/// maximum, farther apart than that in the parameter; a double point of the
/// curve is two minima at one point, far apart in the parameter. Dimensionless.
inline constexpr double kClosestPointSameMinimum = 1e-9;

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

// --- Tessellation and meshes (ops/tessellate.hpp, ops/mesh.hpp) --------------

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

/// An edge of a quadtree cell whose sampled points all fit in a box of
/// diagonal at most this fraction of the tolerance is flat at the tolerance's
/// scale: the normals at its ends are not compared (a cell all of whose edges
/// are flat is not split for its normals' turn). Along such an edge the normal
/// may flip or be undefined (a crease from a collapsed control point, a pole,
/// a side pulled to one point by a huge weight); counting it refines the cells
/// to the quadtree's finest level along the whole edge, millions of cells
/// before the triangle limit refuses them (fuzzed spheres: 51 s and 49 s).
/// The distance test still applies to every cell. Dimensionless.
inline constexpr double kMeshFlatCellFraction = 0.5;

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

}  // namespace casteljau::tolerances
