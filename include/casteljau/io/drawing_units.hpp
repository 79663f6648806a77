#pragma once
// The units in which a drawing (SVG, DXF) is read.

namespace casteljau {

/// The units of the coordinates read from a drawing: the drawing's own
/// (an SVG's root user units: the numbers in the file, the root's
/// viewBox-to-viewport map not applied), or millimetres (an SVG through its
/// root's width, height and viewBox).
enum class DrawingUnits { user, millimetres };

}  // namespace casteljau
