#include "casteljau/io/file.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <vector>

#include "text.hpp"

#include "casteljau/io/tolerance.hpp"

namespace casteljau {
namespace {

namespace fs = std::filesystem;

/// The path in quotes, control characters escaped (error messages are one line).
std::string in_quotes(const fs::path& path) { return io_detail::in_quotes(path.string(), 4096); }

std::string errno_text(int error) { return std::strerror(error); }

/// Closes a file descriptor on scope exit (the read and write paths have
/// several early returns).
class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  ~FileDescriptor() { close(); }
  int get() const { return fd_; }
  /// Closes now and reports close's error (it can report a failed write on NFS).
  int close() {
    if (fd_ < 0) return 0;
    const int result = ::close(fd_);
    fd_ = -1;
    return result;
  }

 private:
  int fd_;
};

std::string size_text(std::uintmax_t bytes) {
  return fmt::format("{:.1f} GiB", static_cast<double>(bytes) / static_cast<double>(std::uintmax_t{1} << 30));
}


/// Writes all of `contents` to `fd` (a write may be partial or interrupted);
/// 0 or the errno of the failure.
int write_all(int fd, std::string_view contents) {
  const char* data = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t wrote = ::write(fd, data, left);
    if (wrote < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    data += wrote;
    left -= static_cast<std::size_t>(wrote);
  }
  return 0;
}

/// A FIFO or a device: opened as it is (no O_CREAT, no rename) and written.
/// No fsync: a pipe or a terminal has no disk to flush to (fsync says EINVAL).
template <class Failed>
Status write_in_place(const fs::path& path, std::string_view contents, const Failed& failed) {
  const int raw = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
  if (raw < 0) return failed(errno);
  FileDescriptor fd(raw);
  if (const int error = write_all(fd.get(), contents); error != 0) return failed(error);
  if (fd.close() != 0) return failed(errno);
  return {};
}

/// Replaces `path` by the file it names once the symbolic links of its last
/// component are followed (a link to a link...), whether or not that file
/// exists yet: a dangling link gives the name it points to, which is then
/// created. A relative link is read from the link's own folder. Returns 0, or
/// ELOOP after tolerances::kMaxSymbolicLinks links, or lstat's or readlink's errno.
int follow_links(fs::path& path) {
  for (int links = 0; links <= tolerances::kMaxSymbolicLinks; ++links) {
    struct stat info {};
    if (::lstat(path.c_str(), &info) != 0) return errno == ENOENT ? 0 : errno;  // ENOENT: a new name
    if (!S_ISLNK(info.st_mode)) return 0;
    std::error_code ec;
    const fs::path next = fs::read_symlink(path, ec);
    if (ec) return ec.value();
    path = next.is_absolute() ? next : path.parent_path() / next;
  }
  return ELOOP;
}

/// The temporary file's name pattern beside `name` (for mkstemp): hidden,
/// and short enough for NAME_MAX (255 bytes) whatever the target's length.
std::string temporary_name(const std::string& name) {
  constexpr std::size_t kKept = 200;  // bytes of the target's name kept: 1 + 200 + 11 < 255
  return "." + name.substr(0, kKept) + ".tmp-XXXXXX";
}
}  // namespace

std::string display_name(const fs::path& path) { return io_detail::printable(path.string(), 4096); }

Expected<std::string> read_text_file(const fs::path& path) {
  const int raw = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (raw < 0) return Error{"cannot open " + in_quotes(path) + ": " + errno_text(errno), ErrorKind::io};
  FileDescriptor fd(raw);
  struct stat info {};
  if (::fstat(fd.get(), &info) != 0) return Error{"cannot read " + in_quotes(path) + ": " + errno_text(errno), ErrorKind::io};
  if (S_ISDIR(info.st_mode)) return Error{in_quotes(path) + " is a directory, not a file", ErrorKind::io};
  std::string text;
  if (S_ISREG(info.st_mode)) {
    const auto size = static_cast<std::uintmax_t>(info.st_size);
    if (size > tolerances::kMaxInputFileBytes) {
      return Error{in_quotes(path) + " is " + size_text(size) + ", larger than the 1 GiB limit for input files", ErrorKind::limit};
    }
    text.reserve(static_cast<std::size_t>(size));
  }
  // Read to the end (a regular file may grow or shrink meanwhile; pipes have
  // no size), never past the limit.
  std::vector<char> chunk(1 << 16);
  for (;;) {
    const ssize_t got = ::read(fd.get(), chunk.data(), chunk.size());
    if (got < 0) {
      if (errno == EINTR) continue;
      return Error{"cannot read " + in_quotes(path) + ": " + errno_text(errno), ErrorKind::io};
    }
    if (got == 0) break;
    if (text.size() + static_cast<std::size_t>(got) > tolerances::kMaxInputFileBytes) {
      return Error{in_quotes(path) + " is larger than the 1 GiB limit for input files", ErrorKind::limit};
    }
    text.append(chunk.data(), static_cast<std::size_t>(got));
  }
  return text;
}

std::string lowercase_extension(const fs::path& path) {
  std::string extension = path.filename().extension().string();
  for (char& c : extension)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return extension;
}

bool same_regular_file(const fs::path& a, const fs::path& b) {
  struct stat first {}, second {};
  if (::stat(a.c_str(), &first) != 0 || ::stat(b.c_str(), &second) != 0) return false;
  return S_ISREG(first.st_mode) && S_ISREG(second.st_mode) && first.st_dev == second.st_dev &&
         first.st_ino == second.st_ino;
}

Status write_file_atomically(const fs::path& path, std::string_view contents) {
  const Error cannot_write{"cannot write " + in_quotes(path)};
  auto failed = [&](int error) { return Error{cannot_write.message + ": " + errno_text(error), ErrorKind::io}; };
  if (path.empty()) return Error{"cannot write '': the file name is empty", ErrorKind::io};

  // What the path names once links are followed (stat follows them all,
  // /dev/stdout's /proc links included): a FIFO or a device is written in
  // place, a folder refused, a regular file or nothing replaced below.
  struct stat existing {};
  bool exists = ::stat(path.c_str(), &existing) == 0;
  if (!exists && errno != ENOENT) return failed(errno);  // ELOOP, ENOTDIR, EACCES...
  if (exists && S_ISDIR(existing.st_mode)) return Error{in_quotes(path) + " is a directory, not a file", ErrorKind::io};
  if (exists && !S_ISREG(existing.st_mode)) return write_in_place(path, contents, failed);

  fs::path target = path;
  if (const int error = follow_links(target); error != 0) return failed(error);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string temporary = (folder / temporary_name(target.filename().string())).string();
  const int raw = ::mkstemp(temporary.data());
  if (raw < 0) return failed(errno);
  FileDescriptor fd(raw);
  auto abandon = [&](int error) {
    fd.close();
    ::unlink(temporary.c_str());
    return failed(error);
  };

  // mkstemp creates the file 0600; give it what a plain open(O_CREAT, 0666)
  // would (0666 minus the umask), or the replaced file's own permissions.
  mode_t mode = 0;
  if (exists) {
    mode = existing.st_mode & 07777;
  } else {
    const mode_t mask = ::umask(0);  // umask can only be read by setting it
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  if (::fchmod(fd.get(), mode) != 0) return abandon(errno);
  if (const int error = write_all(fd.get(), contents); error != 0) return abandon(error);
  // On disk before the rename: otherwise a crash could leave an empty file
  // under the final name on some file systems.
  if (::fsync(fd.get()) != 0) return abandon(errno);
  if (fd.close() != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    return failed(error);
  }
  if (::rename(temporary.c_str(), target.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    return failed(error);
  }
  return {};
}

}  // namespace casteljau
