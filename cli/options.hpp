#pragma once
// What every subcommand shares: reading option values the same way, the
// error line and exit status, the files a command reads and writes, and
// writing its output. One place each, so that `casteljau eval --samples x`
// and `casteljau fit --degree x` say the same thing in the same words, and
// so that every command refuses `-o ''` and an output that is one of its
// inputs the same way (docs/cli.md, "General rules").

#include <CLI/CLI.hpp>
#include <array>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/io/drawing_units.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/render/write.hpp"

namespace casteljau::cli {

/// Whether `option` was given on the command line (an empty value, `--x ''`,
/// counts as given: it is then checked, not silently taken for the default).
bool given(const CLI::Option* option);

/// A whole number in [lowest, highest] written in decimal digits only (no
/// sign, no exponent, no blanks): "--samples: '2.5' is not a whole number",
/// "--degree: 0 is outside 1..10000", "--derivative: 1001 is more than the
/// limit of 1000" (also for digits beyond 64 bits).
Expected<long long> whole_number(std::string_view option, std::string_view text, long long lowest, long long highest);

/// A finite number by the CSV rules (io/csv.hpp's parse_number), the option
/// named in errors: "--smoothing: 'x' is not a number".
Expected<double> number_option(std::string_view option, std::string_view text);

/// One or more numbers separated by commas, blanks around each allowed:
/// "1,0" or "1, 0, 2" ("--start-tangent: 'a' is not a number").
Expected<Point> vector_option(std::string_view option, std::string_view text);

/// Exactly two numbers "a,b" (vector_option); `what` names the pair in the
/// error: "--at: '0.5' is not a parameter pair u,v", "--view: '30' is not a
/// pair azimuth,elevation in degrees".
Expected<std::array<double, 2>> pair_option(std::string_view option, std::string_view text, std::string_view what);

/// Text without the blanks and tabs around it.
std::string_view trimmed(std::string_view text);

/// "the bezier model in 'm.json'" (a file with one model) or "models[1]
/// (piecewise_bezier) in 'm.json'": a model as messages name it.
std::string model_name(const std::vector<Model>& models, std::size_t index, const std::string& file);

/// --units user|mm: the units a drawing is read in: its own (an SVG's root
/// user units, a DXF's drawing units; the default) or millimetres (through an
/// SVG root's width, height and viewBox, a DXF's $INSUNITS); and the options
/// of add_reading_options, which every command reading drawings takes with it.
CLI::Option* add_units_option(CLI::App* command, std::string& units);

/// The value of --units ("" is user units): "--units: 'cm' is not user or mm".
Expected<DrawingUnits> drawing_units_option(const std::string& units);

/// The models of a MODEL file (io/model_file.hpp's read_models: model JSON,
/// CSV point set or SVG drawing) in the --units given ("" is user units):
/// "--units: 'cm' is not user or mm".
Expected<std::vector<Model>> read_model_file(const std::string& path, const std::string& units);
/// read_model_file with what the file states besides its models (io/model_file.hpp).
/// Both report what a drawing left out (report_skipped): one note on stderr,
/// "casteljau: note: d.svg: 3 elements are not read (2 text, 1 image); casteljau
/// info d.svg lists them", or with --strict an error (skipped_elements).
Expected<FileModels> read_model_file_with_unit(const std::string& path, const std::string& units,
                                               bool report_skipped = true);

/// The note or, under --strict, the error for what a drawing left out
/// (nothing when `skipped` is empty).
Status skipped_elements(const std::string& path, const std::vector<std::string>& skipped);

/// The options of every command that reads model files, one set per process
/// (one subcommand runs): --strict (what a drawing draws and casteljau leaves
/// out, text, images, block references..., is an error, not a note), and the
/// selection of models: --model N (models[N], counted from 0 as errors name
/// them), --id ID (an SVG element's id, a DXF entity's handle), --layer NAME
/// (a DXF layer); given together, a model must match them all.
void add_reading_options(CLI::App* command);

/// "a, b, c" of at most `shown` names, then " and N more".
std::string listed(const std::vector<std::string>& names, std::size_t shown);

/// Whether --model, --id or --layer was given (read_model_file applies them).
bool models_selected();

/// The help of a MODEL argument that takes any model file.
inline constexpr const char* kModelFileHelp =
    "Model JSON, a CSV point set taken as one Bézier curve, an SVG drawing (one curve per subpath, in the "
    "root's user units, upright: y up from the page's bottom edge) or a DXF drawing (one curve per curve entity, in its units)";

/// "head.csv: <message>": a library error about a file's data, naming the file.
Error in_file(const std::string& path, const Error& error);

/// Prints "casteljau: error: <message>" on stderr and returns 2 (bad input).
/// A progress line on the terminal is erased first (cli/progress.hpp).
int fail(std::string_view message);
/// The same for an Error from the library.
int fail(const Error& error);

/// --param KIND, the points' parameter values, as fit and interpolate take it.
CLI::Option* add_param_option(CLI::App* command, std::string& param);
/// --function (the first column is x and the parameter), as fit and interpolate take it.
CLI::Option* add_function_flag(CLI::App* command, bool& function);

/// The options of a subcommand that name files: `inputs`, whose every value
/// is a file the command reads (MODEL, --params FILE, each INPUT of plot),
/// and `output`, the file it writes (-o; "-" is standard output).
struct CommandFiles {
  std::vector<const CLI::Option*> inputs;
  const CLI::Option* output = nullptr;
};

/// Makes `run` the subcommand's action; its exit status goes to `status`.
/// Before `run`, the checks every command shares, from the command line
/// alone: `-o ''` is refused (-o - is standard output), and so is an output
/// that is one of the inputs, the same regular file by device and inode
/// (through symbolic and hard links, ./ and ../ spellings: io/file.hpp's
/// same_regular_file), which writing would destroy.
void set_action(CLI::App* command, int& status, CommandFiles files, std::function<int()> run);

/// The help of an optional -o: the same words in every subcommand.
inline constexpr const char* kOutputHelp =
    "Write to FILE (atomically; a FIFO or a device in place) instead of standard output; - is standard output";

/// The help of a figure command's -o (plot, bernstein).
inline constexpr const char* kFigureOutputHelp =
    "The figure to write: FILE.svg, FILE.png or FILE.pdf (by the extension, any case); - writes SVG to standard "
    "output";

/// Whether the value of -o means standard output: -o not given (empty) or "-".
bool is_standard_output(std::string_view path);

/// Writes `text` to standard output. A failure is the environment's, not bad
/// input: status 1, with one line "casteljau: error: cannot write to standard
/// output: No space left on device" on stderr, except for a closed pipe
/// (`| head -1`), where the reader left on purpose and a message would only
/// break into its output: then status 1 alone (docs/cli.md, "Exit status").
/// 0 on success.
int write_standard_output(std::string_view text);

/// Writes a command's output: to standard output when is_standard_output(path)
/// (write_standard_output), else to the file (io/file.hpp's
/// write_file_atomically: nothing half-written, FIFOs and devices written in
/// place; a file error is bad input, status 2). 0 on success.
int write_output(const std::string& path, std::string_view text);

/// The format of a figure written to `path`: by its extension
/// (render::figure_format_of: an error naming the file before anything is
/// read), SVG, the text format, for standard output (-o -).
Expected<render::FigureFormat> figure_output_format(const std::string& path);

/// Writes the figure in `format` (render::figure_document) by write_output:
/// to the file, or to standard output for -o -; `progress` as for the
/// figure's layout. 0 on success.
int write_figure_output(const std::string& path, const render::Figure& figure, render::FigureFormat format,
                        Progress progress = {});

/// A command's summary line ("fit: 12 control points, ..."): on standard
/// output, unless the command's output goes there (no -o, or -o -), then on
/// standard error, so that the output stays exactly the file it would be.
/// The line ends with a newline (added when `line` has none).
int write_summary(const std::string& output, std::string_view line);

}  // namespace casteljau::cli
