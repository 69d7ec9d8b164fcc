// The camera frames the action: in every shipped demo scene and every scene of the tutorial, each
// dynamic body stays inside the world rectangle the run's summary names as its view, at every
// step the run's CSV records. The body's extent at a row comes from its shape in the scene, placed
// at the row's centre of mass and angle.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "doc_blocks.h"
#include "i2d_process.h"
#include "impulse2d/scene/scene.h"
#include "impulse2d/scene/scene_file.h"

namespace {

using impulse2d::Aabb;
using impulse2d::Body;
using impulse2d::Vec2;
using namespace i2d_process;

/// Runs longer than this many body steps take only their first kStepsOfLargeScenes steps, so the
/// test stays cheap under the sanitizers; the camera fits whatever the run records.
constexpr long kMostBodySteps = 20000;
constexpr int kStepsOfLargeScenes = 60;
/// m: what the summary's three decimals can hide.
constexpr double kPrinted = 1e-3;

/// The rectangle of the summary's line "view         X0 .. X1 m, Y0 .. Y1 m".
Aabb viewOf(const std::string& summary) {
  const std::size_t line = summary.find("\nview ");
  REQUIRE(line != std::string::npos);
  Aabb view;
  const int read = std::sscanf(summary.c_str() + line + 6, " %lf .. %lf m, %lf .. %lf m",
                               &view.lower.x(), &view.upper.x(), &view.lower.y(), &view.upper.y());
  REQUIRE(read == 4);
  return view;
}

/// The world extent of `body` with its centre of mass at `position`, turned by `angle`.
Aabb extentAt(const Body& body, const Vec2& position, double angle) {
  if (body.shape.type == impulse2d::ShapeType::Circle) {
    const Vec2 radius = Vec2::Constant(body.shape.radius);
    return Aabb{position - radius, position + radius};
  }
  const Eigen::Rotation2Dd turn(angle);
  Aabb extent{position, position};
  for (const Vec2& vertex : body.shape.vertices) {
    const Vec2 corner = position + turn * vertex;
    extent.lower = extent.lower.cwiseMin(corner);
    extent.upper = extent.upper.cwiseMax(corner);
  }
  return extent;
}

/// Runs the scene, reads its view and CSV, and checks every dynamic body at every row.
void checkFramed(const std::string& path, const Scratch& scratch) {
  INFO("scene " << path);
  const impulse2d::SceneFile scene = impulse2d::loadSceneFile(path);
  std::map<std::string, Body> bodies;
  for (const Body& body : impulse2d::buildBodies(scene)) bodies.emplace(body.name, body);
  const long steps = long(bodies.size()) * scene.steps > kMostBodySteps
                         ? std::min(scene.steps, kStepsOfLargeScenes)
                         : scene.steps;
  const Outcome run = i2d("run " + path + " --steps " + std::to_string(steps) +
                              " --every 5 --csv " + (scratch / "run.csv"),
                          scratch);
  REQUIRE(run.exitCode == 0);
  const Aabb view = viewOf(run.out);
  std::istringstream rows(readFile(scratch / "run.csv"));
  std::string row;
  std::getline(rows, row);  // the header
  int checked = 0;
  while (std::getline(rows, row)) {
    std::vector<std::string> fields;
    std::istringstream cells(row);
    for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
    REQUIRE(fields.size() >= 6);
    const Body& body = bodies.at(fields[2]);
    if (body.isStatic()) continue;
    const Aabb extent =
        extentAt(body, Vec2(std::stod(fields[3]), std::stod(fields[4])), std::stod(fields[5]));
    INFO("body " << fields[2] << " at step " << fields[0]);
    CHECK(extent.lower.x() >= view.lower.x() - kPrinted);
    CHECK(extent.upper.x() <= view.upper.x() + kPrinted);
    CHECK(extent.lower.y() >= view.lower.y() - kPrinted);
    CHECK(extent.upper.y() <= view.upper.y() + kPrinted);
    ++checked;
  }
  CHECK(checked > 0);
}

}  // namespace

TEST_CASE("every shipped demo keeps its dynamic bodies inside the view it names",
          "[render][camera]") {
  const Scratch scratch;
  for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
    if (entry.path().extension() == ".toml") checkFramed(entry.path().string(), scratch);
  }
}

TEST_CASE("the tutorial's scenes keep their dynamic bodies inside the view", "[render][camera]") {
  const Scratch scratch;
  int scenes = 0;
  for (const doc_blocks::Block& block : doc_blocks::readBlocks("docs/tutorial.md")) {
    if (block.language != "toml" || block.name.empty()) continue;
    writeFile(scratch / block.name, block.text);
    checkFramed(scratch / block.name, scratch);
    ++scenes;
  }
  CHECK(scenes > 0);
}

TEST_CASE("a followed body is at the centre of the view, which moves with it", "[render][camera]") {
  const Scratch scratch;
  const std::string path = kScenes + "pushed_box.toml";
  const Outcome fitted = i2d("run " + path + " --steps 300 --every 50", scratch);
  const Outcome followed =
      i2d("run " + path + " --steps 300 --every 50 --set render.follow=box --set render.zoom=2",
          scratch);
  REQUIRE(fitted.exitCode == 0);
  REQUIRE(followed.exitCode == 0);
  const Aabb whole = viewOf(fitted.out);
  const Aabb moving = viewOf(followed.out);
  // At twice the scale each frame shows less, but the union of the frames still spans the slide
  // of the box, which moves 5.5 m along x and none along y.
  CHECK(moving.upper.y() - moving.lower.y() < 0.75 * (whole.upper.y() - whole.lower.y()));
  CHECK(moving.upper.x() - moving.lower.x() > 5.0);
}
