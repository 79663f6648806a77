// casteljau tessellate: the surfaces of a model JSON file as one triangle
// mesh within a distance tolerance (ops/tessellate.hpp), written as OBJ,
// binary STL or binary PLY (io/obj.hpp, io/stl.hpp, io/ply.hpp) chosen by the
// output's extension. Several surfaces in one file ({"models": [...]}) give
// one mesh, welded where they share edges. The command only translates:
// every check runs before anything is written; the mesh is built in memory and
// written atomically; one summary line goes to standard output. A long
// tessellation shows its progress on a terminal's standard error (progress.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/io/csv.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_json.hpp"
#include "casteljau/io/obj.hpp"
#include "casteljau/io/ply.hpp"
#include "casteljau/io/stl.hpp"
#include "casteljau/ops/mesh.hpp"
#include "casteljau/ops/tessellate.hpp"
#include "commands.hpp"
#include "progress.hpp"

namespace casteljau::cli {
namespace {

struct TessellateOptions {
  std::string model;
  std::string tolerance;
  std::string output;
};

enum class MeshFormat { obj, stl, ply };

/// The format named by the output's extension, any case; OBJ, the text
/// format, for standard output (-o -).
Expected<MeshFormat> format_of(const std::string& path) {
  const std::string extension = lowercase_extension(path);
  if (extension == ".obj" || path == "-") return MeshFormat::obj;
  if (extension == ".stl") return MeshFormat::stl;
  if (extension == ".ply") return MeshFormat::ply;
  return Error{fmt::format("-o: '{}' does not end in .obj, .stl or .ply (the mesh format comes from the extension)",
                           display_name(path))};
}

std::string summary_of(const TriangleMesh& mesh) {
  const MeshTopology topology = mesh_topology(mesh);
  std::string line = fmt::format("tessellate: {} triangles, {} vertices, ", mesh.triangles.size(),
                                 mesh.vertices.size());
  if (topology.watertight()) {
    line += "watertight\n";
  } else {
    line += fmt::format("not watertight ({} boundary edges, {} non-manifold edges, {} inconsistently oriented "
                        "edges, {} degenerate triangles)\n",
                        topology.boundary_edges, topology.non_manifold_edges,
                        topology.inconsistently_oriented_edges, topology.degenerate_triangles);
  }
  return line;
}

int run_tessellate(const TessellateOptions& options) {
  auto format = format_of(options.output);
  if (!format) return fail(format.error());
  auto tolerance = number_option("--tolerance", options.tolerance);
  if (!tolerance) return fail(tolerance.error());
  if (!(*tolerance > 0.0)) return fail(fmt::format("--tolerance: {} is not > 0", *tolerance));
  auto models = read_models_json(options.model);
  if (!models) return fail(models.error());
  std::vector<SurfaceView> views;
  for (std::size_t i = 0; i < models->size(); ++i) {
    const Model& model = (*models)[i];
    if (!is_surface(model)) {
      return fail(fmt::format("{} is a curve; tessellate needs surfaces", model_name(*models, i, options.model)));
    }
    const SurfaceView view = surface_view(model);
    if (view.dimension() != 3) {
      return fail(fmt::format("{} is in R^{}; tessellate needs surfaces in 3D",
                              model_name(*models, i, options.model), view.dimension()));
    }
    views.push_back(view);
  }
  // The progress line is erased (the reporter destroyed) before any message.
  auto mesh = [&] {
    TerminalProgress progress("tessellate");
    return tessellate(views, Tolerance{*tolerance}, progress.callback());
  }();
  if (!mesh) return fail(in_file(options.model, mesh.error()));
  std::string bytes;
  switch (*format) {
    case MeshFormat::obj: bytes = to_obj(*mesh); break;
    case MeshFormat::stl: bytes = to_stl(*mesh); break;
    case MeshFormat::ply: bytes = to_ply(*mesh); break;
  }
  if (const int status = write_output(options.output, bytes); status != 0) return status;
  return write_summary(options.output, summary_of(*mesh));
}

}  // namespace

void add_tessellate_command(CLI::App& app, int& status) {
  auto options = std::make_shared<TessellateOptions>();
  CLI::App* command = app.add_subcommand(
      "tessellate",
      "A triangle mesh of the surfaces in SURFACE.json (bezier_surface, bspline_surface, coons; several in "
      "{\"models\": [...]} give one mesh, welded where they share an edge) such that every point of a triangle "
      "is within E of the surface at the linearly interpolated parameters (docs/surfaces.md). Adaptive: flat "
      "regions get large triangles. Per-vertex normals are the surface's. Written to MESH as Wavefront OBJ, "
      "binary STL or binary little-endian PLY, by its extension (any case). One summary line on standard "
      "output (standard error with -o -): triangles, vertices, and whether the mesh is watertight.");
  CLI::Option* surface =
      command->add_option("SURFACE", options->model, "Model JSON file with one or more surfaces in 3D")->required();
  command->add_option("--tolerance", options->tolerance, "Largest distance E > 0 from the mesh to the surface")
      ->type_name("E")
      ->required();
  CLI::Option* output = command
                            ->add_option("-o,--output", options->output,
                                         "MESH.obj, MESH.stl or MESH.ply (written atomically; a FIFO or a device in "
                                         "place); - writes OBJ to standard output")
                            ->type_name("FILE")
                            ->required();
  set_action(command, status, {{surface}, output}, [options] { return run_tessellate(*options); });
}

}  // namespace casteljau::cli
