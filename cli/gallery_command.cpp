// casteljau gallery: every seed figure as SVG and PNG plus index.html
// (docs/cli.md, "gallery"; docs/gallery.md lists the figures).
#include <fmt/format.h>

#include <cstdio>
#include <memory>
#include <string>

#include "casteljau/render/gallery.hpp"
#include "commands.hpp"
#include "progress.hpp"

namespace casteljau::cli {
namespace {

struct GalleryOptions {
  std::string directory = "out/gallery";
  std::string examples;
};

int run_gallery(const GalleryOptions& options) {
  const std::filesystem::path examples =
      options.examples.empty() ? render::default_examples_dir() : std::filesystem::path(options.examples);
  Expected<std::vector<render::GalleryFigure>> figures = Error{""};
  {  // the progress line is erased before any message
    TerminalProgress progress("gallery");
    figures = render::write_gallery(options.directory, examples, progress.callback());
  }
  if (!figures) return fail(figures.error());
  fmt::print("wrote {} figures (SVG and PNG) and index.html to {}\n", figures->size(), options.directory);
  return 0;
}

}  // namespace

void add_gallery_command(CLI::App& app, int& status) {
  auto options = std::make_shared<GalleryOptions>();
  CLI::App* gallery = app.add_subcommand(
      "gallery", fmt::format("Renders every seed figure into DIR as SVG and PNG, with an index.html showing each one "
                             "with a line of explanation: {}.",
                             render::gallery_contents()));
  gallery->add_option("DIR", options->directory, "Output folder, created if needed (default: out/gallery)");
  gallery->add_option("--examples", options->examples,
                      "Folder with the seeds' CSV files (default: the examples/ folder casteljau was built from)")
      ->type_name("DIR");
  gallery->callback([options, &status] { status = run_gallery(*options); });
}

}  // namespace casteljau::cli
