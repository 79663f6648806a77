// Files in and out (io/file.hpp): reading whole files with clear errors and
// the size limit; atomic writing that never leaves a half-written file, and
// never replaces a FIFO or a device by a regular file; symbolic links
// followed to their target; file identity; extensions.
#include "casteljau/io/file.hpp"
#include "casteljau/io/tolerance.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <thread>

#include "io_test_support.hpp"

namespace casteljau {
namespace {

namespace fs = std::filesystem;

std::size_t entries_in(const fs::path& folder) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder), fs::directory_iterator{}));
}

TEST(ReadTextFile, ReadsEveryByte) {
  test::TemporaryFolder folder;
  const std::string text("a\r\nb\0c\xff\n", 8);
  test::write_text(folder / "f", text);
  EXPECT_EQ(*read_text_file(folder / "f"), text);
  test::write_text(folder / "empty", "");
  EXPECT_EQ(*read_text_file(folder / "empty"), "");
}

TEST(ReadTextFile, ErrorsNameTheFile) {
  test::TemporaryFolder folder;
  EXPECT_EQ(read_text_file(folder / "missing.csv").error().message,
            "cannot open '" + (folder / "missing.csv").string() + "': No such file or directory");
  EXPECT_EQ(read_text_file(folder.path()).error().message,
            "'" + folder.path().string() + "' is a directory, not a file");
}

TEST(ReadTextFile, RefusesFilesLargerThanTheLimitBeforeReading) {
  test::TemporaryFolder folder;
  const fs::path big = folder / "big.json";
  test::write_text(big, "");
  // A sparse file: 1 GiB + 1 byte of size, no disk used, nothing read.
  fs::resize_file(big, tolerances::kMaxInputFileBytes + 1);
  EXPECT_EQ(read_text_file(big).error().message,
            "'" + big.string() + "' is 1.0 GiB, larger than the 1 GiB limit for input files");
}

TEST(ReadTextFile, ReadsPipesToo) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  ASSERT_EQ(::write(fds[1], "0,1\n", 4), 4);
  ::close(fds[1]);
  EXPECT_EQ(*read_text_file("/dev/fd/" + std::to_string(fds[0])), "0,1\n");
  ::close(fds[0]);
}

TEST(WriteFileAtomically, WritesAndReplaces) {
  test::TemporaryFolder folder;
  const fs::path out = folder / "out.csv";
  ASSERT_TRUE(write_file_atomically(out, "1,2\n").has_value());
  EXPECT_EQ(test::read_text(out), "1,2\n");
  ASSERT_TRUE(write_file_atomically(out, "3\n").has_value());
  EXPECT_EQ(test::read_text(out), "3\n");
  ASSERT_TRUE(write_file_atomically(out, "").has_value());
  EXPECT_EQ(test::read_text(out), "");
  EXPECT_EQ(entries_in(folder.path()), 1u);  // no temporary file left behind
}

TEST(WriteFileAtomically, GivesNewFilesTheUmaskPermissionsAndKeepsExistingOnes) {
  test::TemporaryFolder folder;
  const mode_t old_mask = ::umask(022);
  ASSERT_TRUE(write_file_atomically(folder / "new", "x").has_value());
  struct stat info {};
  ASSERT_EQ(::stat((folder / "new").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0644u);

  test::write_text(folder / "kept", "old");
  ::chmod((folder / "kept").c_str(), 0640);
  ASSERT_TRUE(write_file_atomically(folder / "kept", "new").has_value());
  ASSERT_EQ(::stat((folder / "kept").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0640u);
  ::umask(old_mask);
}

TEST(WriteFileAtomically, FollowsASymbolicLink) {
  test::TemporaryFolder folder;
  test::write_text(folder / "target", "old");
  fs::create_symlink("target", folder / "link");
  ASSERT_TRUE(write_file_atomically(folder / "link", "new").has_value());
  EXPECT_TRUE(fs::is_symlink(folder / "link"));
  EXPECT_EQ(test::read_text(folder / "target"), "new");
}

TEST(WriteFileAtomically, FailsCleanlyWithoutTouchingTheTarget) {
  test::TemporaryFolder folder;
  EXPECT_EQ(write_file_atomically(folder / "no" / "such" / "out.csv", "x").error().message,
            "cannot write '" + (folder / "no" / "such" / "out.csv").string() + "': No such file or directory");
  fs::create_directory(folder / "dir");
  EXPECT_EQ(write_file_atomically(folder / "dir", "x").error().message,
            "'" + (folder / "dir").string() + "' is a directory, not a file");
  EXPECT_EQ(entries_in(folder.path()), 1u);
}

TEST(WriteFileAtomically, AFailedWriteLeavesTheOldFileWhole) {
  // Make the write itself fail half-way: a file size limit of 4 KiB (the
  // kernel refuses the rest with EFBIG instead of SIGXFSZ when that signal is ignored).
  test::TemporaryFolder folder;
  const fs::path out = folder / "out.csv";
  test::write_text(out, "the old contents\n");
  const auto old_handler = ::signal(SIGXFSZ, SIG_IGN);
  rlimit old_limit{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  rlimit small = old_limit;
  small.rlim_cur = 4096;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  const auto status = write_file_atomically(out, std::string(100000, 'x'));
  ::setrlimit(RLIMIT_FSIZE, &old_limit);
  ::signal(SIGXFSZ, old_handler);
  ASSERT_FALSE(status.has_value());
  EXPECT_EQ(status.error().message, "cannot write '" + out.string() + "': File too large");
  EXPECT_EQ(test::read_text(out), "the old contents\n");
  EXPECT_EQ(entries_in(folder.path()), 1u);
}


/// What a FIFO's reader received, read on its own thread while the writer
/// writes (opening a FIFO for writing waits for its reader).
class FifoReader {
 public:
  explicit FifoReader(const fs::path& fifo) : thread_([this, fifo] { received_ = test::read_text(fifo); }) {}
  std::string received() {
    thread_.join();
    return received_;
  }

 private:
  std::string received_;
  std::thread thread_;
};

/// Whether the file opens for writing (a device node on a nodev mount does not).
bool opens_for_writing(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) return false;
  ::close(fd);
  return true;
}

bool names_a_fifo(const fs::path& path) {
  struct stat info {};
  return ::lstat(path.c_str(), &info) == 0 && S_ISFIFO(info.st_mode);
}

TEST(WriteFileAtomically, WritesAFifoInPlace) {
  // Issue 15: `-o n` on a FIFO replaced it by a regular file.
  test::TemporaryFolder folder;
  const fs::path fifo = folder / "n";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  FifoReader reader(fifo);
  ASSERT_TRUE(write_file_atomically(fifo, "2.25,1.5\n").has_value());
  EXPECT_EQ(reader.received(), "2.25,1.5\n");
  EXPECT_TRUE(names_a_fifo(fifo));
  EXPECT_EQ(entries_in(folder.path()), 1u);  // no temporary file beside it
}

TEST(WriteFileAtomically, WritesACharacterDeviceInPlace) {
  // As root, a writer that renames would replace the system's /dev/null:
  // then the test makes a null device of its own (a user cannot replace
  // /dev/null, the rename would only fail).
  test::TemporaryFolder folder;
  fs::path device = "/dev/null";
  if (::geteuid() == 0 && ::mknod((folder / "null").c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0 &&
      opens_for_writing(folder / "null")) {
    device = folder / "null";
  }
  ASSERT_TRUE(write_file_atomically(device, "x").has_value());
  struct stat info {};
  ASSERT_EQ(::lstat(device.c_str(), &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode));
}

TEST(WriteFileAtomically, ALinkToAFifoWritesTheFifoAndKeepsTheLink) {
  test::TemporaryFolder folder;
  ASSERT_EQ(::mkfifo((folder / "n").c_str(), 0600), 0);
  fs::create_symlink("n", folder / "link");
  FifoReader reader(folder / "n");
  ASSERT_TRUE(write_file_atomically(folder / "link", "through the link").has_value());
  EXPECT_EQ(reader.received(), "through the link");
  EXPECT_TRUE(fs::is_symlink(folder / "link"));
  EXPECT_TRUE(names_a_fifo(folder / "n"));
}

TEST(WriteFileAtomically, ADanglingLinkCreatesItsTargetAndStays) {
  test::TemporaryFolder folder;
  fs::create_directory(folder / "sub");
  fs::create_symlink("../made.csv", folder / "sub" / "link");  // relative to the link's folder
  ASSERT_TRUE(write_file_atomically(folder / "sub" / "link", "new").has_value());
  EXPECT_TRUE(fs::is_symlink(folder / "sub" / "link"));
  EXPECT_EQ(test::read_text(folder / "made.csv"), "new");
  EXPECT_EQ(entries_in(folder / "sub"), 1u);
}

TEST(WriteFileAtomically, FollowsAChainOfLinksAndRefusesALoop) {
  test::TemporaryFolder folder;
  test::write_text(folder / "target", "old");
  fs::create_symlink("target", folder / "one");
  fs::create_symlink(folder / "one", folder / "two");  // absolute
  ASSERT_TRUE(write_file_atomically(folder / "two", "new").has_value());
  EXPECT_EQ(test::read_text(folder / "target"), "new");
  EXPECT_TRUE(fs::is_symlink(folder / "one"));
  EXPECT_TRUE(fs::is_symlink(folder / "two"));

  fs::create_symlink("loop_b", folder / "loop_a");
  fs::create_symlink("loop_a", folder / "loop_b");
  EXPECT_EQ(write_file_atomically(folder / "loop_a", "x").error().message,
            "cannot write '" + (folder / "loop_a").string() + "': Too many levels of symbolic links");
  EXPECT_TRUE(fs::is_symlink(folder / "loop_a"));
}

TEST(WriteFileAtomically, RefusesAnEmptyName) {
  EXPECT_EQ(write_file_atomically("", "x").error().message, "cannot write '': the file name is empty");
}

TEST(WriteFileAtomically, TakesNamesUpToTheSystemLimit) {
  // The temporary name must fit in NAME_MAX (255 bytes) too.
  test::TemporaryFolder folder;
  const std::string name(255, 'n');
  ASSERT_TRUE(write_file_atomically(folder / name, "x").has_value());
  EXPECT_EQ(test::read_text(folder / name), "x");
  EXPECT_EQ(entries_in(folder.path()), 1u);
}

TEST(SameRegularFile, MatchesEverySpellingOfOneFile) {
  test::TemporaryFolder folder;
  test::write_text(folder / "m.json", "{}");
  test::write_text(folder / "other.json", "{}");
  fs::create_directory(folder / "sub");
  fs::create_symlink("../m.json", folder / "sub" / "link");
  fs::create_hard_link(folder / "m.json", folder / "hard.json");
  const fs::path m = folder / "m.json";
  EXPECT_TRUE(same_regular_file(m, m));
  EXPECT_TRUE(same_regular_file(m, folder / "." / "m.json"));
  EXPECT_TRUE(same_regular_file(m, folder / "sub" / ".." / "m.json"));
  EXPECT_TRUE(same_regular_file(m, folder / "sub" / "link"));
  EXPECT_TRUE(same_regular_file(folder / "hard.json", m));
  EXPECT_FALSE(same_regular_file(m, folder / "other.json"));
  EXPECT_FALSE(same_regular_file(m, folder / "missing.json"));
  EXPECT_FALSE(same_regular_file(folder / "missing.json", folder / "missing.json"));
  EXPECT_FALSE(same_regular_file(folder / "sub", folder / "sub"));
  EXPECT_FALSE(same_regular_file("/dev/null", "/dev/null"));
  ASSERT_EQ(::mkfifo((folder / "n").c_str(), 0600), 0);
  EXPECT_FALSE(same_regular_file(folder / "n", folder / "n"));
}

TEST(LowercaseExtension, IsTheLastExtensionOfTheFileName) {
  EXPECT_EQ(lowercase_extension("out/Figure.PNG"), ".png");
  EXPECT_EQ(lowercase_extension("m.json.GZ"), ".gz");
  EXPECT_EQ(lowercase_extension("dir.d/Makefile"), "");
  EXPECT_EQ(lowercase_extension(".bashrc"), "");
  EXPECT_EQ(lowercase_extension("-"), "");
  EXPECT_EQ(lowercase_extension("a."), ".");
}

}  // namespace
}  // namespace casteljau
