#pragma once
// Binary STL (3D Systems' StereoLithography Interface Specification, 1989):
// the format of 3D printing and CNC pipelines.

#include <string>

#include "casteljau/ops/mesh.hpp"

namespace casteljau {

/// The mesh as binary STL, returned as bytes in a std::string: an 80-byte
/// header (text naming casteljau, padded with spaces; it never starts with
/// "solid", which readers take for ASCII STL), the triangle count as a
/// little-endian uint32, then per triangle 50 bytes: the facet normal and its
/// three vertices as little-endian IEEE 754 float32 triples and a zero uint16
/// attribute. The facet normal is the unit cross product of the triangle's
/// edges (b - a) x (c - a), which is how STL readers orient facets, and zero
/// for a degenerate triangle; the per-vertex normals are not stored (STL has
/// none). Coordinates are rounded to float (about 7 significant digits).
/// Size 84 + 50 t bytes, O(t).
std::string to_stl(const TriangleMesh& mesh);

}  // namespace casteljau
