// The shared option readers, the files of a command and the output of every
// subcommand (options.hpp).
#include "options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <optional>
#include <utility>

#include "casteljau/io/csv.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/model_file.hpp"
#include "progress.hpp"

namespace casteljau::cli {
namespace {

/// The checks of set_action: an empty -o, an output that is an input.
Status check_files(const CommandFiles& files) {
  if (files.output == nullptr || !given(files.output)) return {};
  for (const std::string& output : files.output->results()) {
    if (output.empty()) {
      return Error{"-o '': the file name is empty (-o - is standard output)"};
    }
    if (output == "-") continue;
    for (const CLI::Option* input : files.inputs) {
      for (const std::string& path : input->results()) {
        if (!same_regular_file(path, output)) continue;
        return Error{fmt::format("-o '{}' is the input {} '{}': writing the output would destroy it; choose "
                                 "another output file",
                                 display_name(output), input->get_name(), display_name(path))};
      }
    }
  }
  return {};
}

}  // namespace

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

bool given(const CLI::Option* option) { return option != nullptr && option->count() > 0; }

Expected<long long> whole_number(std::string_view option, std::string_view text, long long lowest, long long highest) {
  const std::string_view shown = text.substr(0, 60);
  const bool digits_only = !text.empty() && text.find_first_not_of("0123456789") == std::string_view::npos;
  if (!digits_only) return Error{fmt::format("{}: '{}' is not a whole number", option, shown)};
  long long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range || value > highest) {
    return Error{fmt::format("{}: {} is more than the limit of {}", option, shown, highest)};
  }
  if (value < lowest) return Error{fmt::format("{}: {} is outside {}..{}", option, value, lowest, highest)};
  return value;
}

Expected<double> number_option(std::string_view option, std::string_view text) {
  auto value = parse_number(text);
  if (!value) return Error{fmt::format("{}: {}", option, value.error().message)};
  return *value;
}

Expected<Point> vector_option(std::string_view option, std::string_view text) {
  Point values;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string_view field = text.substr(start, comma == std::string_view::npos ? std::string_view::npos
                                                                                      : comma - start);
    auto value = number_option(option, trimmed(field));
    if (!value) return value.error();
    values.push_back(*value);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return values;
}

Expected<std::array<double, 2>> pair_option(std::string_view option, std::string_view text, std::string_view what) {
  const auto comma = text.find(',');
  if (comma == std::string_view::npos || text.find(',', comma + 1) != std::string_view::npos) {
    return Error{fmt::format("{}: '{}' is not {}", option, text.substr(0, 60), what)};
  }
  auto values = vector_option(option, text);
  if (!values) return values.error();
  return std::array<double, 2>{(*values)[0], (*values)[1]};
}

std::string model_name(const std::vector<Model>& models, std::size_t index, const std::string& file) {
  const std::string name = display_name(file);
  if (models.size() == 1) return fmt::format("the {} model in '{}'", type_name(models[index]), name);
  return fmt::format("models[{}] ({}) in '{}'", index, type_name(models[index]), name);
}

int fail(std::string_view message) {
  erase_progress_line();
  std::fprintf(stderr, "casteljau: error: %.*s\n", static_cast<int>(message.size()), message.data());
  return 2;
}

int fail(const Error& error) { return fail(error.message); }

CLI::Option* add_param_option(CLI::App* command, std::string& param) {
  return command->add_option("--param", param, "Parameter values: uniform (default), chord or centripetal")
      ->type_name("KIND");
}

CLI::Option* add_function_flag(CLI::App* command, bool& function) {
  return command->add_flag("--function", function,
                           "The first column is x (strictly increasing) and the parameter: the curve (x, s(x)) over "
                           "[x_0, x_n]");
}

CLI::Option* add_units_option(CLI::App* command, std::string& units) {
  add_reading_options(command);
  return command
      ->add_option("--units", units,
                   "The units a drawing is read in: user (an SVG's root user units, a DXF's drawing units; the "
                   "default) or mm (through an SVG root's width, height and viewBox, a DXF's $INSUNITS)")
      ->type_name("user|mm");
}

Expected<DrawingUnits> drawing_units_option(const std::string& units) {
  if (units == "mm") return DrawingUnits::millimetres;
  if (units.empty() || units == "user") return DrawingUnits::user;
  return Error{fmt::format("--units: '{}' is not user or mm", units.substr(0, 40)), ErrorKind::invalid_argument};
}

namespace {
// The reading options of the subcommand that runs.
bool strict_drawings = false;
std::string selected_model, selected_id, selected_layer;
// Each subcommand has its own options bound to these values: given when one of them was.
std::vector<const CLI::Option*> selected_model_options, selected_id_options, selected_layer_options;

bool any_given(const std::vector<const CLI::Option*>& options) {
  return std::any_of(options.begin(), options.end(), [](const CLI::Option* option) { return given(option); });
}

/// The models of `file` that --model, --id and --layer select (all of them
/// when none is given); an error names what matched nothing.
Status select_models(const std::string& path, FileModels& file) {
  const bool by_index = any_given(selected_model_options);
  const bool by_id = any_given(selected_id_options);
  const bool by_layer = any_given(selected_layer_options);
  if (!by_index && !by_id && !by_layer) return {};
  std::optional<std::size_t> index;
  if (by_index) {
    auto n = whole_number("--model", selected_model, 0, 1LL << 40);
    if (!n) return n.error();
    if (*n >= static_cast<long long>(file.models.size()))
      return Error{fmt::format("--model {}: '{}' holds {} model{} (models[0] to models[{}])", *n, display_name(path),
                               file.models.size(), file.models.size() == 1 ? "" : "s", file.models.size() - 1),
                   ErrorKind::invalid_argument};
    index = static_cast<std::size_t>(*n);
  }
  FileModels kept;
  for (std::size_t m = 0; m < file.models.size(); ++m) {
    const ModelOrigin& origin = file.origins[m];
    if ((index && m != *index) || (by_id && origin.id != selected_id) || (by_layer && origin.layer != selected_layer))
      continue;
    kept.models.push_back(std::move(file.models[m]));
    kept.origins.push_back(origin);
  }
  if (kept.models.empty()) {
    // Name what the file holds, so that the next try can succeed.
    std::vector<std::string> names;
    for (const ModelOrigin& origin : file.origins) {
      const std::string& name = by_layer && !by_id ? origin.layer : origin.id;
      if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    std::string wanted;
    if (index) wanted += fmt::format("models[{}]", *index);
    if (by_id) wanted += fmt::format("{}id '{}'", wanted.empty() ? "" : " with ", selected_id.substr(0, 60));
    if (by_layer) wanted += fmt::format("{}layer '{}'", wanted.empty() ? "" : " on ", selected_layer.substr(0, 60));
    const char* kind = by_layer && !by_id ? "layers" : file.format == ModelFileFormat::dxf ? "handles" : "ids";
    return Error{fmt::format("'{}' has no {} ({}: {})", display_name(path), wanted, kind,
                             names.empty() ? std::string("none") : listed(names, 10)),
                 ErrorKind::invalid_argument};
  }
  file.models = std::move(kept.models);
  file.origins = std::move(kept.origins);
  return {};
}
}  // namespace

std::string listed(const std::vector<std::string>& names, std::size_t shown) {
  std::string out;
  for (std::size_t i = 0; i < names.size() && i < shown; ++i) out += (i == 0 ? "" : ", ") + names[i];
  if (names.size() > shown) out += fmt::format(" and {} more", names.size() - shown);
  return out;
}

bool models_selected() {
  return any_given(selected_model_options) || any_given(selected_id_options) || any_given(selected_layer_options);
}

void add_reading_options(CLI::App* command) {
  command->add_flag("--strict", strict_drawings,
                    "Refuse a drawing that draws what casteljau leaves out (text, images, clip paths, block "
                    "references...) instead of noting it on stderr");
  selected_model_options.push_back(
      command->add_option("--model", selected_model, "Read only models[N] of the file (from 0, as errors name them)")
          ->type_name("N"));
  selected_id_options.push_back(
      command->add_option("--id", selected_id, "Read only the models of the SVG element with this id, or of the DXF "
                                               "entity with this handle")
          ->type_name("ID"));
  selected_layer_options.push_back(
      command->add_option("--layer", selected_layer, "Read only the models of the DXF entities on this layer")
          ->type_name("NAME"));
}

Status skipped_elements(const std::string& path, const std::vector<std::string>& skipped) {
  if (skipped.empty()) return {};
  const std::string count =
      fmt::format("{} element{} {} not read ({})", skipped.size(), skipped.size() == 1 ? "" : "s",
                  skipped.size() == 1 ? "is" : "are", skipped_summary(skipped));
  if (strict_drawings)
    return Error{fmt::format("{}: {}, and --strict refuses them: {}", display_name(path), count, skipped.front()),
                 ErrorKind::invalid_argument};
  erase_progress_line();
  std::fprintf(stderr, "casteljau: note: %s: %s; casteljau info %s lists them\n", display_name(path).c_str(),
               count.c_str(), display_name(path).c_str());
  return {};
}

Expected<std::vector<Model>> read_model_file(const std::string& path, const std::string& units) {
  auto file = read_model_file_with_unit(path, units);
  if (!file) return file.error();
  return std::move(file->models);
}

Expected<FileModels> read_model_file_with_unit(const std::string& path, const std::string& units,
                                               bool report_skipped) {
  auto drawing_units = drawing_units_option(units);
  if (!drawing_units) return drawing_units.error();
  auto file = read_file_models(path, *drawing_units);
  if (!file) return file.error();
  if (Status ok = select_models(path, *file); !ok) return ok.error();
  if (report_skipped)
    if (Status ok = skipped_elements(path, file->skipped); !ok) return ok.error();
  return file;
}

Error in_file(const std::string& path, const Error& error) {
  return Error{fmt::format("{}: {}", display_name(path), error.message)};
}

void set_action(CLI::App* command, int& status, CommandFiles files, std::function<int()> run) {
  command->callback([&status, files = std::move(files), run = std::move(run)] {
    if (auto checked = check_files(files); !checked) {
      status = fail(checked.error());
      return;
    }
    status = run();
  });
}

bool is_standard_output(std::string_view path) { return path.empty() || path == "-"; }

int write_standard_output(std::string_view text) {
  erase_progress_line();  // standard output may be the same terminal
  if ((!text.empty() && std::fwrite(text.data(), 1, text.size(), stdout) != text.size()) || std::fflush(stdout) != 0) {
    // SIGPIPE is ignored (main.cpp): a closed pipe is this EPIPE, not a death by signal.
    const int error = errno;
    std::clearerr(stdout);
    if (error != EPIPE) {
      std::fprintf(stderr, "casteljau: error: cannot write to standard output: %s\n", std::strerror(error));
    }
    return 1;
  }
  return 0;
}

int write_output(const std::string& path, std::string_view text) {
  if (is_standard_output(path)) return write_standard_output(text);
  if (auto written = write_file_atomically(path, text); !written) return fail(written.error());
  return 0;
}

Expected<render::FigureFormat> figure_output_format(const std::string& path) {
  if (path == "-") return render::FigureFormat::svg;
  return render::figure_format_of(path);
}

int write_figure_output(const std::string& path, const render::Figure& figure, render::FigureFormat format,
                        Progress progress) {
  auto bytes = render::figure_document(figure, format, progress);
  if (!bytes) return fail(bytes.error());
  return write_output(path, *bytes);
}

int write_summary(const std::string& output, std::string_view line) {
  const std::string text = line.ends_with('\n') ? std::string(line) : std::string(line) + '\n';
  if (!is_standard_output(output)) return write_standard_output(text);
  erase_progress_line();  // the summary takes the line on standard error
  std::fwrite(text.data(), 1, text.size(), stderr);
  return 0;
}

}  // namespace casteljau::cli
