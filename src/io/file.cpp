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

}  // namespace

std::string display_name(const fs::path& path) { return io_detail::printable(path.string(), 4096); }

Expected<std::string> read_text_file(const fs::path& path) {
  const int raw = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (raw < 0) return Error{"cannot open " + in_quotes(path) + ": " + errno_text(errno)};
  FileDescriptor fd(raw);
  struct stat info {};
  if (::fstat(fd.get(), &info) != 0) return Error{"cannot read " + in_quotes(path) + ": " + errno_text(errno)};
  if (S_ISDIR(info.st_mode)) return Error{in_quotes(path) + " is a directory, not a file"};
  std::string text;
  if (S_ISREG(info.st_mode)) {
    const auto size = static_cast<std::uintmax_t>(info.st_size);
    if (size > tolerances::kMaxInputFileBytes) {
      return Error{in_quotes(path) + " is " + size_text(size) + ", larger than the 1 GiB limit for input files"};
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
      return Error{"cannot read " + in_quotes(path) + ": " + errno_text(errno)};
    }
    if (got == 0) break;
    if (text.size() + static_cast<std::size_t>(got) > tolerances::kMaxInputFileBytes) {
      return Error{in_quotes(path) + " is larger than the 1 GiB limit for input files"};
    }
    text.append(chunk.data(), static_cast<std::size_t>(got));
  }
  return text;
}

Status write_file_atomically(const fs::path& path, std::string_view contents) {
  const Error cannot_write{"cannot write " + in_quotes(path)};
  auto failed = [&](int error) { return Error{cannot_write.message + ": " + errno_text(error)}; };

  // Follow a symbolic link so that the file it points to is replaced, not the link.
  fs::path target = path;
  std::error_code ec;
  if (fs::is_symlink(path, ec)) {
    target = fs::weakly_canonical(path, ec);
    if (ec) return failed(ec.value());
  }
  struct stat existing {};
  const bool exists = ::stat(target.c_str(), &existing) == 0;
  if (exists && S_ISDIR(existing.st_mode)) return Error{in_quotes(path) + " is a directory, not a file"};

  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string temporary = (folder / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
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

  const char* data = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t wrote = ::write(fd.get(), data, left);
    if (wrote < 0) {
      if (errno == EINTR) continue;
      return abandon(errno);
    }
    data += wrote;
    left -= static_cast<std::size_t>(wrote);
  }
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
