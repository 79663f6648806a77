/* Rust benchmark peers: kurbo 0.7.1 and lyon_geom 0.15.0 (Debian's sources)
 * behind a C ABI, built by rust_peers.cmake (target casteljau_peer_rust,
 * which defines CASTELJAU_HAVE_RUST_PEERS=1). Source: rust_peers/src/lib.rs.
 *
 * A cubic is 8 doubles, the four control points as x0,y0,x1,y1,x2,y2,x3,y3;
 * a query point or a line end is 2 doubles (x,y). "accuracy" is kurbo's
 * accuracy argument (an absolute distance). Every function catches Rust
 * panics: scalar results become NaN, counts 0, and array outputs are filled
 * with NaN (pieces with SIZE_MAX). None allocates. */
#ifndef CASTELJAU_BENCH_RUST_PEERS_H
#define CASTELJAU_BENCH_RUST_PEERS_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* kurbo::CubicBez::arclen(accuracy) (ParamCurveArclen): adaptive
 * Gauss-Legendre quadrature. */
double casteljau_kurbo_cubic_arclen(const double p[8], double accuracy);

/* ParamCurveArclen::inv_arclen(length, accuracy): the t in [0,1] whose arc
 * length from t = 0 is length (kurbo's default bisection). */
double casteljau_kurbo_cubic_inv_arclen(const double p[8], double length, double accuracy);

/* ParamCurveNearest::nearest(point, accuracy) -> (t, distance squared) for
 * each of the n queries (2n doubles). kurbo 0.7 splits the cubic into
 * quadratics within accuracy and solves each exactly, so t and the squared
 * distance are those of the approximating quadratic, not refined on the cubic. */
void casteljau_kurbo_cubic_nearest(const double p[8], const double* queries, size_t n,
                                   double accuracy, double* out_t,
                                   double* out_distance_squared);

/* Sum of arclen(accuracy) over count cubics (8 * count doubles), e.g. the
 * Bezier pieces of a B-spline. */
double casteljau_kurbo_path_arclen(const double* cubics, size_t count, double accuracy);

/* For each query, nearest() on every piece, keeping the least squared
 * distance (first piece on ties): out_piece is the piece index, out_t the
 * local parameter in that piece. count == 0 gives SIZE_MAX / NaN / NaN. */
void casteljau_kurbo_path_nearest(const double* cubics, size_t count, const double* queries,
                                  size_t n, double accuracy, size_t* out_piece, double* out_t,
                                  double* out_distance_squared);

/* lyon_geom CubicBezierSegment<f64>::cubic_intersections_t(&b), fat-line
 * (Bezier) clipping; at most 9 pairs (ta on a, tb on b), not sorted.
 * lyon reports endpoint-on-interior hits but not endpoint/endpoint ones.
 * Returns the number found; writes min(found, capacity) pairs. */
size_t casteljau_lyon_cubic_intersections(const double a[8], const double b[8], double* out_ta,
                                          double* out_tb, size_t capacity);

/* kurbo PathSeg::Cubic(p).intersect_line(Line) with the line *segment*
 * line = x0,y0,x1,y1: real roots of the cubic in the line's implicit
 * equation, t_curve within [-1e-9, 1+1e-9], t_line in [0,1]; at most 3.
 * Returns the number found; writes min(found, capacity) pairs. */
size_t casteljau_kurbo_cubic_line_intersections(const double p[8], const double line[4],
                                                double* out_t_curve, double* out_t_line,
                                                size_t capacity);

#ifdef __cplusplus
}
#endif

#endif
