#pragma once
// The preview of a G-code program: what the machine will do, drawn from the
// program as read back (io/gcode.hpp's read_gcode), over the curves it was
// made from.

#include <string>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/io/gcode.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/render/figure.hpp"

namespace casteljau::render {

/// The toolpath figure (docs/cli.md, "plot" of a program): the source
/// curves beneath in light grey (plane curves, when given), rapid moves in
/// the plane dashed grey, cuts in two colours (G1 lines tab10 blue, G2/G3
/// arcs tab10 orange, exact rational arcs from the centre the program
/// gives, the radius the mean of its start and end radii), and each plunge
/// (a move down that ends below the work, Z < 0) a red disc; equal aspect,
/// axes in the program's unit; the title names the program and counts its
/// moves. Errors: a program without moves; a source that is not a plane
/// curve ("… is a surface", "… lives in R^3").
Expected<Figure> toolpath_figure(const GcodeReading& program, const std::string& name,
                                 const std::vector<Model>& source = {}, const std::string& source_name = {});

}  // namespace casteljau::render
