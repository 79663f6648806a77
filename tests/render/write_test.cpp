// Writers: PNG and PDF files start with their magic bytes, PNGs read back by
// cairo have the figure's pixel size, PDFs the page size in points, bad
// extensions and missing folders are errors that leave no file behind. Every
// format goes through io/file's writer: the umask and an existing file's
// permissions are kept, a symbolic link stays, a FIFO stays a FIFO.
#include <cairo/cairo.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

#include "casteljau/render/plots.hpp"
#include "casteljau/render/write.hpp"

namespace casteljau::render {
namespace {

namespace fs = std::filesystem;

/// A fresh, empty folder for one test.
class WriteTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("casteljau_render_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::size_t files_in_dir() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
  }

  fs::path dir_;
};

std::string file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

Figure small_figure(int width, int height) {
  Figure figure = *bernstein_basis_figure(3);
  figure.width = width;
  figure.height = height;
  return figure;
}

TEST_F(WriteTest, PngHasMagicBytesAndTheFigureSize) {
  const fs::path path = dir_ / "basis.png";
  ASSERT_TRUE(write_png(small_figure(640, 480), path));
  const std::string bytes = file_text(path);
  ASSERT_GE(bytes.size(), 8u);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  cairo_surface_t* image = cairo_image_surface_create_from_png(path.c_str());
  ASSERT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
  EXPECT_EQ(cairo_image_surface_get_width(image), 640);
  EXPECT_EQ(cairo_image_surface_get_height(image), 480);
  // Not blank: the basis is drawn in black on white, so some pixel is dark.
  cairo_surface_flush(image);
  const unsigned char* data = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  int dark = 0;
  for (int y = 0; y < 480; ++y)
    for (int x = 0; x < 640; ++x) dark += data[y * stride + 4 * x] < 64;  // blue channel (little endian ARGB)
  EXPECT_GT(dark, 500);
  cairo_surface_destroy(image);
  EXPECT_EQ(files_in_dir(), 1u);  // no temporary file left
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::others_read, fs::perms::others_read);
}

TEST_F(WriteTest, PdfHasMagicBytesAndThePageSize) {
  const fs::path path = dir_ / "basis.pdf";
  ASSERT_TRUE(write_figure(small_figure(800, 600), path));
  const std::string bytes = file_text(path);
  EXPECT_EQ(bytes.substr(0, 5), "%PDF-");
  // 800 x 600 px at 0.75 pt per pixel.
  EXPECT_NE(bytes.find("/MediaBox [ 0 0 600 450 ]"), std::string::npos);
  EXPECT_EQ(files_in_dir(), 1u);
}

TEST_F(WriteTest, SvgByExtensionCaseInsensitive) {
  const fs::path path = dir_ / "basis.SVG";
  ASSERT_TRUE(write_figure(small_figure(300, 200), path));
  const std::string text = file_text(path);
  EXPECT_NE(text.find("width=\"300.00\" height=\"200.00\""), std::string::npos);
}

TEST_F(WriteTest, BadExtensionIsAnErrorAndWritesNothing) {
  for (const char* name : {"figure.gif", "figure", "figure.svg.txt"}) {
    const auto status = write_figure(small_figure(300, 200), dir_ / name);
    ASSERT_FALSE(status) << name;
    EXPECT_NE(status.error().message.find(name), std::string::npos) << status.error().message;
    EXPECT_NE(status.error().message.find(".svg, .png or .pdf"), std::string::npos);
  }
  EXPECT_EQ(files_in_dir(), 0u);
}

TEST_F(WriteTest, MissingFolderIsAnErrorForEveryFormat) {
  for (const char* name : {"a.svg", "a.png", "a.pdf"}) {
    const auto status = write_figure(small_figure(300, 200), dir_ / "missing" / name);
    ASSERT_FALSE(status) << name;
    EXPECT_NE(status.error().message.find("missing"), std::string::npos) << status.error().message;
  }
  EXPECT_EQ(files_in_dir(), 0u);
}

TEST_F(WriteTest, ExistingFileIsReplacedWhole) {
  const fs::path path = dir_ / "basis.png";
  { std::ofstream(path) << "old contents"; }
  ASSERT_TRUE(write_png(small_figure(320, 240), path));
  EXPECT_EQ(file_text(path).substr(1, 3), "PNG");
  EXPECT_EQ(files_in_dir(), 1u);
}

TEST_F(WriteTest, LayoutErrorsWriteNothing) {
  Figure empty;  // no panel
  for (const char* name : {"a.svg", "a.png", "a.pdf"}) EXPECT_FALSE(write_figure(empty, dir_ / name));
  EXPECT_EQ(files_in_dir(), 0u);
}


TEST(FigureDocument, EncodesEveryFormatInMemory) {
  const Figure figure = small_figure(320, 240);
  EXPECT_EQ(figure_document(figure, FigureFormat::svg).value().substr(0, 5), "<?xml");
  EXPECT_EQ(figure_document(figure, FigureFormat::png).value().substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(figure_document(figure, FigureFormat::pdf).value().substr(0, 5), "%PDF-");
  EXPECT_FALSE(figure_document(Figure{}, FigureFormat::png));  // layout error: no panel
}

TEST(FigureFormatOf, ComesFromTheExtensionInAnyCase) {
  EXPECT_EQ(*figure_format_of("a/b.SVG"), FigureFormat::svg);
  EXPECT_EQ(*figure_format_of("b.Png"), FigureFormat::png);
  EXPECT_EQ(*figure_format_of("b.pdf"), FigureFormat::pdf);
  EXPECT_EQ(figure_format_of("f.gif").error().message,
            "cannot write 'f.gif': unknown figure format '.gif' (use .svg, .png or .pdf)");
  EXPECT_EQ(figure_format_of("f").error().message,
            "cannot write 'f': the file name has no extension (use .svg, .png or .pdf)");
}

TEST_F(WriteTest, EveryFormatTakesTheUmaskAndKeepsExistingPermissions) {
  // cairo.cpp had its own writer that made every figure 0644.
  const mode_t old_mask = ::umask(077);
  for (const char* name : {"new.svg", "new.png", "new.pdf"}) {
    ASSERT_TRUE(write_figure(small_figure(100, 80), dir_ / name)) << name;
    struct stat info {};
    ASSERT_EQ(::stat((dir_ / name).c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 0777, 0600u) << name;
  }
  ::umask(old_mask);
  { std::ofstream(dir_ / "kept.png") << "old"; }
  ::chmod((dir_ / "kept.png").c_str(), 0640);
  ASSERT_TRUE(write_png(small_figure(100, 80), dir_ / "kept.png"));
  struct stat info {};
  ASSERT_EQ(::stat((dir_ / "kept.png").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0640u);
}

TEST_F(WriteTest, ALinkStaysAndItsTargetIsReplaced) {
  // cairo.cpp renamed over the link itself.
  { std::ofstream(dir_ / "target.pdf") << "old"; }
  fs::create_symlink("target.pdf", dir_ / "link.pdf");
  ASSERT_TRUE(write_figure(small_figure(100, 80), dir_ / "link.pdf"));
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.pdf"));
  EXPECT_EQ(file_text(dir_ / "target.pdf").substr(0, 5), "%PDF-");
  EXPECT_EQ(files_in_dir(), 2u);
}

TEST_F(WriteTest, AFifoStaysAFifo) {
  const fs::path fifo = dir_ / "figure.png";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = file_text(fifo); });
  const auto status = write_figure(small_figure(100, 80), fifo);
  reader.join();
  ASSERT_TRUE(status);
  EXPECT_EQ(received.substr(1, 3), "PNG");
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
}

}  // namespace
}  // namespace casteljau::render
