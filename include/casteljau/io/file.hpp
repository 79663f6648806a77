#pragma once
// Files in and out. Nothing is half-written: output to a regular file goes to
// a temporary file in the same folder, renamed over the target only when
// complete; FIFOs and devices, which a rename would destroy, are written
// directly. The one writer of the project: the CLI, the figures (SVG, PNG,
// PDF), the gallery and Python all write through write_file_atomically.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "casteljau/core/expected.hpp"

namespace casteljau {


/// The whole file as text. Errors name the file: "cannot open 'x.csv': No such
/// file or directory", "'dir' is a directory, not a file", "'big.json' is
/// 1.5 GiB, larger than the 1 GiB limit for input files". Regular files are
/// measured before reading; pipes and devices are read up to the same limit.
/// A UTF-8 byte order mark is kept (the parsers skip it). O(size).
Expected<std::string> read_text_file(const std::filesystem::path& path);

/// The path as error messages show it: the text given, with control
/// characters and bytes that are not UTF-8 written as \xNN, so that a message
/// naming any file stays one line of valid text.
std::string display_name(const std::filesystem::path& path);

/// The extension of the path's file name with its dot, in ASCII lower case:
/// ".png" for "out/Figure.PNG", ".gz" for "m.json.gz", "" for "Makefile",
/// ".bashrc" or "-". The formats chosen by extension (figures, meshes, model
/// files) all ask this one function.
std::string lowercase_extension(const std::filesystem::path& path);

/// Whether `a` and `b` name the same existing regular file: the same device
/// and inode once every symbolic link is followed, so "m.json", "./m.json",
/// "dir/../m.json", a hard link and a symbolic link to it all match. A path
/// that does not exist, or names a folder, a FIFO or a device, matches
/// nothing (reading and writing the same pipe or terminal destroys no file).
/// Used to refuse an output that is one of the inputs before either is opened.
bool same_regular_file(const std::filesystem::path& a, const std::filesystem::path& b);

/// Writes `contents` to `path`, so that no reader ever sees half of it.
/// - A regular file or a new name: a temporary file in the same folder (so
///   the rename never crosses file systems) is written, flushed to disk
///   (fsync), given the target's permissions (0666 minus the umask for a new
///   file), then renamed over `path` (POSIX rename replaces it in one step).
///   On any failure the temporary file is removed and `path` is untouched.
/// - A symbolic link is followed (up to tolerances::kMaxSymbolicLinks links):
///   its target is replaced, or created when the link dangles; the link stays.
/// - A FIFO or a character or block device (/dev/null, /dev/stdout, a named
///   pipe; also through a link) is opened and written directly: renaming over
///   it would replace the FIFO or device by a regular file. Such a write is as
///   whole as the reader makes it; opening a FIFO waits for its reader.
/// Errors: "cannot write 'out/x.csv': No such file or directory", "'out' is a
/// directory, not a file", "cannot write '': the file name is empty".
Status write_file_atomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace casteljau
