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
  // The progress line is erased (the reporter destroyed) before any message.
  auto figures = [&] {
    TerminalProgress progress("gallery");
    return render::write_gallery(options.directory, examples, progress.callback());
  }();
  if (!figures) return fail(figures.error());
  return write_standard_output(
      fmt::format("wrote {} figures (SVG and PNG) and index.html to {}\n", figures->size(), options.directory));
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
  // It writes NAME.svg, NAME.png and index.html and reads only CSV files:
  // DIR can hold no input, even when it is the examples folder.
  set_action(gallery, status, {}, [options] { return run_gallery(*options); });
}

}  // namespace casteljau::cli
