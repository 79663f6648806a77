#pragma once
// Closure: whether a curve through points ends at its last point or comes
// back to the first. A named choice instead of a bool parameter, so a call
// says what it asks: interpolate_c1_bezier(points, 1.0, Closure::closed).

namespace casteljau {

/// An open curve runs from the first point to the last; a closed one also
/// joins the last point back to the first, with the same smoothness there
/// as everywhere else (indices taken cyclically).
enum class Closure { open, closed };

}  // namespace casteljau
