#pragma once
// The nurbs layer's own tolerances: the axes of conics
// (core/tolerance.hpp says why each layer keeps its tolerances beside its code).

namespace casteljau::tolerances {

/// How far the two axes given for a circle, arc or ellipse (nurbs/conics.hpp)
/// may be from orthonormal: | |X| - 1 |, | |Y| - 1 | and |X . Y| must each be
/// at most this (dimensionless). Axes computed in double (a rotation matrix, a
/// normalized cross product) are off by a few ulps (1e-16); 1e-12 accepts those
/// and still refuses a forgotten normalization or a wrong axis. The accepted
/// axes are then re-orthonormalized (Gram-Schmidt), so the conic is as exact
/// as double allows whatever rounding the caller's axes carried.
inline constexpr double kOrthonormalAxes = 1e-12;

}  // namespace casteljau::tolerances
