#pragma once
// Internal to tessellate (ops/tessellate.hpp): which patch edges are one
// curve, so that the mesh shares their vertices and is watertight across
// them, and which are collapsed to a point (poles).
//
// Every side of every patch is sampled once at a few normalized parameters.
// A side whose samples all coincide (within the match distance) is collapsed:
// it becomes one vertex. Two sides whose samples agree, in the same or in the
// opposite direction, are one shared edge: two faces of a box, the seam
// u = 0 / u = 1 of a surface of revolution, both seams of a torus. Corners of
// matched sides are unified (union-find), so a box corner or a pole is one
// vertex; matched sides form groups, each side with its direction relative to
// its group's first side.
#include <vector>

#include "tessellate_quadtree.hpp"

namespace casteljau::tessellation {

/// How the patches' edges relate: collapsed sides, groups of shared sides
/// (with each side's direction relative to its group) and corner classes.
struct EdgeStructure {
  std::vector<bool> degenerate;  // per side id (4 * patch + side)
  std::vector<int> group;        // per side id: the group's first side
  std::vector<bool> flipped;     // per side id: runs against its group
  std::vector<int> corner_class; // per corner id (4 * patch + corner)
};

/// The edge structure of the patches, comparing sample points within
/// `match_distance` (an absolute distance, from the patches' scale).
EdgeStructure analyse_edges(const std::vector<Patch>& patches, double match_distance);

}  // namespace casteljau::tessellation
