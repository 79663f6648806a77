#pragma once
// The bezier layer's own limits (core/tolerance.hpp says why each layer keeps
// its tolerances beside its code).

namespace casteljau::tolerances {

/// Largest recursion depth accepted by subdivide_recursive: 2^24 + 1 points
/// (about 400 MB in 3D) is already far beyond any drawing need; deeper is
/// refused as a "huge size" rather than exhausting memory.
inline constexpr int kMaxSubdivisionDepth = 24;

}  // namespace casteljau::tolerances
