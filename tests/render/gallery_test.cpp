// The gallery: the seed data it draws (cycle(n) against the shipped spiral
// files, which were computed independently in Python from the notebook's
// formula), the measured numbers (seeds.md: the semicircle's radial error is
// about 0.055), and that every figure lays out.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

#include "casteljau/io/csv.hpp"
#include "casteljau/render/gallery.hpp"
#include "casteljau/render/layout.hpp"

namespace casteljau::render {
namespace {

TEST(Gallery, NotebookCycleMatchesTheSpiralFiles) {
  for (int n : {5, 8, 10, 20}) {
    auto file = read_points_csv(default_examples_dir() / ("spiral_" + std::to_string(n) + ".csv"));
    ASSERT_TRUE(file) << file.error().message;
    const PointArray computed = notebook_cycle(n);
    ASSERT_EQ(file->size(), computed.size());
    for (std::size_t k = 0; k < computed.size(); ++k)
      for (int j = 0; j < 2; ++j) EXPECT_NEAR((*file)[k][j], computed[k][j], 4e-16) << "n " << n << " k " << k;
  }
}

TEST(Gallery, SemicircleRadialError) {
  const auto points = *PointArray::make({{-3, 0}, {-3, 4}, {3, 4}, {3, 0}});
  const RadialError e = radial_error(points, 3.0, 20001);
  // seeds.md: "its largest radial error is about 0.055 (1.8 % of the radius)".
  EXPECT_GT(e.maximum, 0.054);
  EXPECT_LT(e.maximum, 0.056);
  // Exact at the ends and in the middle: C(0) = A, C(1) = D, C(1/2) = (0, 3).
  EXPECT_NEAR(e.errors.front(), 0.0, 1e-15);
  EXPECT_NEAR(e.errors[10000], 0.0, 1e-15);
  EXPECT_NEAR(e.errors.back(), 0.0, 1e-15);
}

TEST(Gallery, EveryFigureLaysOutWithATitleAndAnExplanation) {
  auto figures = gallery_figures(default_examples_dir());
  ASSERT_TRUE(figures) << figures.error().message;
  EXPECT_GE(figures->size(), 15u);
  std::set<std::string> names;
  for (const auto& f : *figures) {
    EXPECT_TRUE(names.insert(f.name).second) << "duplicate " << f.name;
    EXPECT_FALSE(f.figure.title.empty()) << f.name;
    EXPECT_FALSE(f.explanation.empty()) << f.name;
    EXPECT_EQ(f.explanation.find('\n'), std::string::npos) << f.name;
    auto scene = layout(f.figure);
    EXPECT_TRUE(scene) << f.name << ": " << (scene ? "" : scene.error().message);
  }
  const std::string html = gallery_index_html(*figures);
  for (const auto& f : *figures) {
    EXPECT_NE(html.find("src=\"" + f.name + ".svg\""), std::string::npos);
    EXPECT_NE(html.find("href=\"" + f.name + ".png\""), std::string::npos);
  }
}

TEST(Gallery, SectionsDescribeExactlyTheFiguresBuilt) {
  // gallery --help prints gallery_contents(): its sections must cover the
  // figures' numbers 1..N in order, each section holding at least one figure.
  auto figures = gallery_figures(default_examples_dir());
  ASSERT_TRUE(figures) << figures.error().message;
  const auto sections = gallery_sections();
  ASSERT_FALSE(sections.empty());
  EXPECT_EQ(sections.front().first, 1);
  for (std::size_t i = 1; i < sections.size(); ++i) EXPECT_EQ(sections[i].first, sections[i - 1].last + 1);
  EXPECT_EQ(sections.back().last, static_cast<int>(figures->size()));
  for (std::size_t i = 0; i < figures->size(); ++i)
    EXPECT_EQ(std::stoi((*figures)[i].name.substr(0, 2)), static_cast<int>(i) + 1) << (*figures)[i].name;
  const std::string contents = gallery_contents();
  for (const auto& section : sections) EXPECT_NE(contents.find(section.topics), std::string::npos);
  EXPECT_NE(contents.find("30-34 surfaces"), std::string::npos);
}

TEST(Gallery, MissingExamplesFolderIsAnError) {
  auto figures = gallery_figures("/nonexistent/examples");
  ASSERT_FALSE(figures);
  EXPECT_NE(figures.error().message.find("notebook_polygon.csv"), std::string::npos) << figures.error().message;
}

}  // namespace
}  // namespace casteljau::render
