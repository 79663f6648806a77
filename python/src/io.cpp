// The io layer in Python: model JSON (models in and out as the bound classes
// BezierCurve, PiecewiseBezierCurve, BSplineCurve, BezierSurface,
// BSplineSurface, CoonsPatch: the run-time Model variant of io/model.hpp
// mapped to Python types), CSV point sets, the mesh formats OBJ, STL and PLY,
// and atomic file output. Paths are str or os.PathLike. Every error,
// including a missing or unreadable file, is a ValueError carrying the C++
// message, which names the file (the C++ io layer does not tell a missing
// file from other failures). Files are written atomically by the C++ layer
// (a temporary file renamed over the target): never half-written.

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <fmt/format.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "casteljau/io/csv.hpp"
#include "casteljau/io/dxf.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/gcode.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/io/model_json.hpp"
#include "casteljau/io/obj.hpp"
#include "casteljau/io/ply.hpp"
#include "casteljau/io/stl.hpp"
#include "casteljau/io/tolerance.hpp"
#include "casteljau/ops/mesh.hpp"

namespace casteljau::python {

namespace {

namespace fs = std::filesystem;

constexpr const char* kModelKinds =
    "BezierCurve, PiecewiseBezierCurve, BSplineCurve, BezierSurface, BSplineSurface or CoonsPatch";

std::string type_name_of(const py::handle& object) {
  return py::str(py::type::of(object).attr("__name__"));
}

/// A Python model object (one of the six bound classes) as a Model (a copy).
Model model_from(const py::handle& object, const std::string& what) {
  if (py::isinstance<BezierCurve>(object)) return object.cast<BezierCurve>();
  if (py::isinstance<PiecewiseBezierCurve>(object)) return object.cast<PiecewiseBezierCurve>();
  if (py::isinstance<BSplineCurve>(object)) return object.cast<BSplineCurve>();
  if (py::isinstance<BezierSurface>(object)) return object.cast<BezierSurface>();
  if (py::isinstance<BSplineSurface>(object)) return object.cast<BSplineSurface>();
  if (py::isinstance<CoonsPatch>(object)) return object.cast<CoonsPatch>();
  throw py::type_error(fmt::format("{} is a {}, expected a model: {}", what, type_name_of(object), kModelKinds));
}

std::vector<Model> models_from(const py::handle& object) {
  if (py::isinstance<py::str>(object) || !py::isinstance<py::sequence>(object)) {
    throw py::type_error(fmt::format("models must be a sequence of models ({})", kModelKinds));
  }
  const py::sequence sequence = py::reinterpret_borrow<py::sequence>(object);
  if (sequence.size() == 0) {
    // {"models": []} would not read back: parse_models_json wants at least one.
    throw py::value_error("models is empty: model JSON holds at least one model");
  }
  std::vector<Model> models;
  models.reserve(sequence.size());
  for (std::size_t k = 0; k < sequence.size(); ++k) models.push_back(model_from(sequence[k], fmt::format("models[{}]", k)));
  return models;
}

/// The Model's value as an object of its bound class.
py::object model_to_python(Model model) {
  return std::visit([](auto&& value) { return py::cast(std::move(value)); }, std::move(model));
}

py::list models_to_python(std::vector<Model> models) {
  py::list list;
  for (Model& model : models) list.append(model_to_python(std::move(model)));
  return list;
}

void write_atomically(const fs::path& path, const std::string& contents) {
  Status status;
  {
    py::gil_scoped_release release;
    status = write_file_atomically(path, contents);
  }
  unwrap(status);
}

/// Text given as str, or bytes taken as they are.
std::string text_from(const py::handle& object, const char* what) {
  if (py::isinstance<py::str>(object)) return object.cast<std::string>();
  if (py::isinstance<py::bytes>(object)) return std::string(object.cast<py::bytes>());
  throw py::type_error(fmt::format("{} is a {}, expected str or bytes", what, type_name_of(object)));
}

py::array_t<std::int64_t> lines_to_numpy(const std::vector<std::size_t>& lines) {
  py::array_t<std::int64_t> array(static_cast<py::ssize_t>(lines.size()));
  for (std::size_t k = 0; k < lines.size(); ++k) array.mutable_data()[k] = static_cast<std::int64_t>(lines[k]);
  return array;
}

/// The program of casteljau.gcode: each model a contour (docs/formats.md, "G-code").
std::string gcode_of(const py::handle& objects, double tolerance, bool lines, const std::string& units,
                     const std::string& dialect, std::optional<double> depth, double step_down,
                     std::optional<double> safe_z, std::optional<double> feed, std::optional<double> plunge_feed,
                     int decimals, const std::string& origin) {
  if (units != "mm" && units != "in") throw py::value_error(fmt::format("units '{}' is not mm or in", units));
  if (dialect != "grbl" && dialect != "linuxcnc")
    throw py::value_error(fmt::format("dialect '{}' is not grbl or linuxcnc", dialect));
  if (origin != "drawing" && origin != "lower-left" && origin != "centre")
    throw py::value_error(fmt::format("origin '{}' is not drawing, lower-left or centre", origin));
  const std::vector<Model> models = models_from(objects);
  GcodeOptions options = default_gcode_options(units == "mm" ? GcodeUnits::millimetres : GcodeUnits::inches);
  options.dialect = dialect == "grbl" ? GcodeDialect::grbl : GcodeDialect::linuxcnc;
  options.depth = depth.value_or(options.depth);
  options.step_down = step_down;
  options.safe_height = safe_z.value_or(options.safe_height);
  options.feed = feed.value_or(options.feed);
  options.plunge_feed = plunge_feed.value_or(options.plunge_feed);
  options.origin = origin == "drawing" ? GcodeOrigin::drawing
                   : origin == "lower-left" ? GcodeOrigin::lower_left : GcodeOrigin::centre;
  return unwrap(without_gil([&]() -> Expected<std::string> {
    Toolpath toolpath;
    toolpath.tolerance = Tolerance{tolerance};
    toolpath.sources = {"Python"};
    const auto digits = gcode_decimals(toolpath.tolerance, options.units, decimals);
    if (!digits) return digits.error();
    options.decimals = *digits;
    for (std::size_t k = 0; k < models.size(); ++k) {
      const std::string where = fmt::format("models[{}]", k);
      if (is_surface(models[k])) return Error{where + ": gcode cuts plane curves, this is a surface"};
      auto contour = contour_of(curve_view(models[k]), toolpath.tolerance, *digits,
                                lines ? GcodeMotion::lines : GcodeMotion::arcs);
      if (!contour) return with_context(contour.error(), where);
      toolpath.contours.push_back(std::move(*contour));
    }
    auto program = write_gcode(toolpath, options);
    if (!program) return program.error();
    return std::move(program->text);
  }));
}

}  // namespace

void bind_io(py::module_& module) {
  // --- model JSON ----------------------------------------------------------------
  module.def(
      "parse_models_json",
      [](const py::object& text, const std::string& source) {
        const std::string contents = text_from(text, "text");
        return models_to_python(
            unwrap(without_gil([&] { return parse_models_json(contents, source); })));
      },
      py::arg("text"), py::arg("source") = "<string>",
      "The models of a model JSON text (docs/formats.md, version 1: one model object, or {\"models\": [...]}) as a "
      "list of BezierCurve, PiecewiseBezierCurve, BSplineCurve, BezierSurface, BSplineSurface and CoonsPatch "
      "objects. ValueError \"<source>, <where>: <what>\" (line and column for syntax errors, the path of a bad "
      "field).");

  module.def(
      "read_models_json",
      [](const fs::path& path) {
        return models_to_python(unwrap(without_gil([&] { return read_models_json(path); })));
      },
      py::arg("path"),
      "The models of a model JSON file (str or os.PathLike) as a list (parse_models_json). ValueError names the "
      "file, also when it is missing or unreadable.");

  module.def(
      "read_models",
      [](const fs::path& path) {
        return models_to_python(unwrap(without_gil([&] { return read_models(path); })));
      },
      py::arg("path"),
      "The models of a file of any format the CLI reads (docs/formats.md): model JSON, a CSV point set (the "
      "control polygon of one BezierCurve), an SVG drawing (one PiecewiseBezierCurve per subpath, in the root's "
      "user units) or a DXF drawing (one model per entity): by the extension .json / .csv / .svg / .dxf, else by "
      "content. ValueError names the file, and for a drawing the first problem's line and element.");

  module.def(
      "read_file_models",
      [](const fs::path& path, const std::string& units) {
        if (units != "user" && units != "mm") throw py::value_error(fmt::format("units '{}' is not user or mm", units));
        FileModels file = unwrap(without_gil([&] {
          return read_file_models(path, units == "mm" ? DrawingUnits::millimetres : DrawingUnits::user);
        }));
        py::list origins;
        for (const ModelOrigin& o : file.origins)
          origins.append(py::dict(py::arg("element") = o.element, py::arg("id") = o.id, py::arg("layer") = o.layer,
                                  py::arg("line") = o.line));
        py::dict result;
        result["format"] = format_name(file.format);
        result["models"] = models_to_python(std::move(file.models));
        result["origins"] = origins;
        result["insunits"] = file.insunits;
        result["unit"] = file.insunits == 0 ? std::string() : dxf_unit_name(file.insunits);
        result["millimetres_per_unit"] = file.insunits == 0 ? py::object(py::none())
                                                            : py::object(py::float_(dxf_unit_millimetres(file.insunits)));
        result["page_bottom"] = file.page_bottom ? py::object(py::float_(*file.page_bottom)) : py::object(py::none());
        result["skipped"] = file.skipped;
        return result;
      },
      py::arg("path"), py::arg("units") = "user",
      "read_models with what the file states besides its models (casteljau info; io/model_file.hpp): a dict of "
      "format ('model JSON', 'CSV point set', 'SVG drawing', 'DXF drawing'), models, origins (one dict per model: "
      "element, id, layer, line), insunits (DXF's $INSUNITS code of the unit, 0: none stated), unit (its name, '' "
      "when none), millimetres_per_unit (None when none), page_bottom (an SVG's page bottom in its user units, "
      "else None) and skipped (what a drawing draws that was left out). units 'user' or 'mm'.");

  module.def(
      "to_json", [](const py::object& model) { return to_json(model_from(model, "model")); }, py::arg("model"),
      "The model as model JSON (one object, one line), numbers in shortest round-trip form: parse_models_json("
      "to_json(m)) == [m] exactly.");

  module.def(
      "models_to_json", [](const py::object& models) { return models_to_json(models_from(models)); },
      py::arg("models"),
      "Several models as model JSON: the single object for one model, {\"models\": [...]} for more, ending with a "
      "newline. ValueError for an empty sequence (its JSON would not read back).");

  module.def(
      "write_models_json",
      [](const py::object& models, const fs::path& path) { write_atomically(path, models_to_json(models_from(models))); },
      py::arg("models"), py::arg("path"),
      "Writes models_to_json(models) to path atomically (write_file_atomically: a temporary file renamed over the "
      "target, never half-written). Python only: the CLI writes the same text. ValueError names the file.");

  // --- what every front end asks of a model ---------------------------------------
  module.def(
      "is_surface", [](const py::object& model) { return is_surface(model_from(model, "model")); }, py::arg("model"),
      "True for the surface kinds (BezierSurface, BSplineSurface, CoonsPatch), False for the curves.");
  module.def(
      "type_name", [](const py::object& model) { return std::string(type_name(model_from(model, "model"))); },
      py::arg("model"),
      "The model's type name in model JSON: 'bezier', 'piecewise_bezier', 'bspline', 'bezier_surface', "
      "'bspline_surface' or 'coons'.");
  module.def(
      "dimension_of", [](const py::object& model) { return dimension_of(model_from(model, "model")); },
      py::arg("model"), "The dimension of the space the model (curve or surface) lives in.");
  module.def(
      "control_point_count",
      [](const py::object& model) { return control_point_count(model_from(model, "model")); }, py::arg("model"),
      "The number of control points of the model (all pieces together; rows x columns for a net; the four "
      "boundaries together for a Coons patch).");
  module.def(
      "domain_of",
      [](const py::object& model) {
        const Model value = model_from(model, "model");
        if (is_surface(value)) {
          throw py::value_error("domain_of is for curves; a surface has domain_u and domain_v");
        }
        const Interval domain = curve_view(value).domain();
        return py::make_tuple(domain.lower, domain.upper);
      },
      py::arg("model"),
      "The parameter domain of a curve model as a tuple: (0, 1) for a Bézier curve, (0, m) for m pieces, (t_p, "
      "t_{n+1}) for a B-spline. ValueError for surfaces.");
  module.def(
      "to_bspline",
      [](const py::object& model) { return model_to_python(unwrap(to_bspline(model_from(model, "model")))); },
      py::arg("model"),
      "The same model written as a B-spline (exact): a curve gives a BSplineCurve, a surface a BSplineSurface "
      "(io/model.hpp). ValueError when pieces do not meet or a Coons patch has rational boundaries.");

  // --- CSV point sets ----------------------------------------------------------------
  module.def(
      "parse_points_csv",
      [](const py::object& text, const std::string& source) {
        const std::string contents = text_from(text, "text");
        return to_numpy(unwrap(without_gil([&] { return parse_points_csv(contents, source); })));
      },
      py::arg("text"), py::arg("source") = "<string>",
      "The points of a CSV text (docs/formats.md: '#' comments, optional header, one point per line) as an (n, d) "
      "array. ValueError \"<source>, line 7, field 2: ...\".");
  module.def(
      "read_points_csv",
      [](const fs::path& path) {
        return to_numpy(unwrap(without_gil([&] { return read_points_csv(path); })));
      },
      py::arg("path"), "The points of a CSV file as an (n, d) array (parse_points_csv). ValueError names the file.");
  module.def(
      "format_points_csv",
      [](const py::object& points) { return format_points_csv(points_from(points, "points")); }, py::arg("points"),
      "The (n, d) points as CSV text, one point per line, each number in the shortest form that reads back to the "
      "same double (parse_points_csv gives the same array, bit for bit).");
  module.def(
      "write_points_csv",
      [](const py::object& points, const fs::path& path) {
        write_atomically(path, format_points_csv(points_from(points, "points")));
      },
      py::arg("points"), py::arg("path"),
      "Writes format_points_csv(points) to path atomically (Python only: format_points_csv then "
      "write_file_atomically). ValueError names the file.");
  module.def(
      "parse_number", [](const std::string& text) { return unwrap(parse_number(text)); }, py::arg("text"),
      "One number written as text, by the rules of a CSV field (whole text, optional '+', finite). ValueError "
      "\"'abc' is not a number\".");
  module.def(
      "parse_numbers_csv",
      [](const py::object& text, const std::string& source, std::size_t max_values) {
        const std::string contents = text_from(text, "text");
        const NumberColumn column =
            unwrap(without_gil([&] { return parse_numbers_csv(contents, source, max_values); }));
        return py::make_tuple(to_numpy(std::span<const double>(column.values)), lines_to_numpy(column.lines));
      },
      py::arg("text"), py::arg("source") = "<string>",
      py::arg("max_values") = tolerances::kMaxEvaluationParameters,
      "A single column of numbers (parse_points_csv's rules, one field per row) as a tuple (values (k,), lines "
      "(k,) int64: the 1-based line of each value; the C++ returns a NumberColumn).");
  module.def(
      "read_numbers_csv",
      [](const fs::path& path) {
        return to_numpy(std::span<const double>(
            unwrap(without_gil([&] { return read_numbers_csv(path); }))));
      },
      py::arg("path"),
      "A single column of numbers from a file as a (k,) array (at most tolerances.MAX_EVALUATION_PARAMETERS).");

  // --- files ---------------------------------------------------------------------------
  module.def(
      "read_text_file",
      [](const fs::path& path) { return unwrap(without_gil([&] { return read_text_file(path); })); },
      py::arg("path"),
      "The whole file as text (at most 1 GiB; a UTF-8 byte order mark kept). ValueError names the file "
      "(UnicodeDecodeError, a ValueError, when it is not UTF-8).");
  module.def(
      "display_name", [](const fs::path& path) { return display_name(path); }, py::arg("path"),
      "The path as error messages show it: control characters and bytes that are not UTF-8 written as \\xNN.");
  module.def(
      "write_file_atomically",
      [](const fs::path& path, const py::object& contents) { write_atomically(path, text_from(contents, "contents")); },
      py::arg("path"), py::arg("contents"),
      "Writes contents (str as UTF-8, or bytes) to path atomically: a temporary file in the same folder, flushed, "
      "renamed over the target; on failure the target is untouched. ValueError names the file.");

  // --- G-code ----------------------------------------------------------------------------
  module.def("gcode", &gcode_of, py::arg("models"), py::arg("tolerance"), py::kw_only(), py::arg("lines") = false,
             py::arg("units") = "mm", py::arg("dialect") = "grbl", py::arg("depth") = py::none(),
             py::arg("step_down") = 0.0, py::arg("safe_z") = py::none(), py::arg("feed") = py::none(),
             py::arg("plunge_feed") = py::none(), py::arg("decimals") = 0, py::arg("origin") = "drawing",
             "The G-code program (RS-274/NGC text) that cuts the plane curves of models, as `casteljau gcode` "
             "writes it (docs/formats.md, \"G-code\"): each curve fitted by arcs and lines (G2/G3 in the IJK form, "
             "G1; lines=True: G1 only) so that the path, the rounding of its numbers included, is within tolerance "
             "of the curves; contours ordered to shorten the rapid moves, cut down to depth in passes of at most "
             "step_down (0: one pass). units 'mm' (G21) or 'in' (G20); dialect 'grbl' or 'linuxcnc'; depth, safe_z, "
             "feed and plunge_feed default to the unit's (1, 5, 600, 200 in mm; 0.04, 0.2, 24, 8 in inches); "
             "decimals 0 picks the fewest that leave nine tenths of the tolerance to the fit; origin 'drawing', "
             "'lower-left' or 'centre' puts the drawing or its box's corner or centre at X0 Y0. ValueError for a "
             "surface or a space curve (naming models[k]), a tolerance not > 0 or finer than the decimals carry, a "
             "depth, height or feed not > 0.");

  // --- meshes ----------------------------------------------------------------------------
  module.def(
      "to_obj", [](const TriangleMesh& mesh) { return to_obj(mesh); }, py::arg("mesh"),
      "The mesh as Wavefront OBJ text: v and vn lines, then f a//a b//b c//c (1-based), numbers in shortest "
      "round-trip form.");
  module.def(
      "to_stl", [](const TriangleMesh& mesh) { return py::bytes(to_stl(mesh)); }, py::arg("mesh"),
      "The mesh as binary STL bytes (3D Systems 1989): 80-byte header, uint32 count, 50 bytes per triangle with "
      "its facet normal, float32 coordinates.");
  module.def(
      "to_ply", [](const TriangleMesh& mesh) { return py::bytes(to_ply(mesh)); }, py::arg("mesh"),
      "The mesh as binary little-endian PLY bytes (Turk 1994): double x, y, z, nx, ny, nz per vertex, uchar/uint "
      "index lists per face.");
  module.def(
      "write_obj", [](const TriangleMesh& mesh, const fs::path& path) { write_atomically(path, to_obj(mesh)); },
      py::arg("mesh"), py::arg("path"),
      "Writes to_obj(mesh) to path atomically (Python only: to_obj then write_file_atomically).");
  module.def(
      "write_stl", [](const TriangleMesh& mesh, const fs::path& path) { write_atomically(path, to_stl(mesh)); },
      py::arg("mesh"), py::arg("path"),
      "Writes to_stl(mesh) to path atomically (Python only: to_stl then write_file_atomically).");
  module.def(
      "write_ply", [](const TriangleMesh& mesh, const fs::path& path) { write_atomically(path, to_ply(mesh)); },
      py::arg("mesh"), py::arg("path"),
      "Writes to_ply(mesh) to path atomically (Python only: to_ply then write_file_atomically).");
}

}  // namespace casteljau::python
