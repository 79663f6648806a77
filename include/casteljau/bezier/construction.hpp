#pragma once
// The de Casteljau construction as data: every intermediate polygon for one
// parameter, for figures (seed 004's demo_casteljau) and the playground.

#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"

namespace casteljau {

/// Levels 0..n of the de Casteljau triangle at t: level 0 is the control
/// polygon (n+1 points), level r has n+1-r points P^r_i = (1-t) P^{r-1}_i +
/// t P^{r-1}_{i+1}, level n is the single point C(t). For a rational curve the
/// levels are the projections of the homogeneous construction (Farin §13.3).
/// The first points of the levels are the left half's control polygon and the
/// last points the right half's (split_at). O(n^2 d).
std::vector<PointArray> casteljau_construction(const BezierCurve& curve, double t);

}  // namespace casteljau
