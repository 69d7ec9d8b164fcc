// Frames on disk: PNG round trips, numbering every K-th step, the contact sheet's layout, clear
// errors for unwritable directories, traces (a frame per solver event) and side-by-side panels.
#include <fstream>

#include <catch2/catch.hpp>

#include "impulse2d/render/contact_sheet.h"
#include "impulse2d/render/frame.h"
#include "impulse2d/render/frame_writer.h"
#include "impulse2d/render/panels.h"
#include "impulse2d/render/trace.h"
#include "render_fixtures.h"

using namespace impulse2d;
using namespace impulse2d::render;
namespace fs = std::filesystem;

namespace {

/// A solid frame whose colour encodes its number, so a thumbnail tells which frame it shows.
Canvas numberedFrame(int number) {
  return Canvas(160, 120,
                Color{std::uint8_t(10 * number), 90, std::uint8_t(250 - 10 * number), 255});
}

FrameRenderer boxRenderer(const test::FixedSimulation& simulation) {
  return FrameRenderer(fitCamera(simulation.bodies(), ViewDef{}, RenderSettings{}), "box");
}

}  // namespace

TEST_CASE("A frame read back from its PNG equals what was drawn", "[png]") {
  const fs::path directory = test::scratchDirectory("round_trip");
  const test::FixedSimulation simulation = test::boxOnGround();
  FrameRenderer renderer = boxRenderer(simulation);
  const Canvas& frame = renderer.draw(simulation);
  writePng(directory / "frame.png", frame);
  const Canvas back = readPng(directory / "frame.png");
  REQUIRE(back.width() == frame.width());
  REQUIRE(back.height() == frame.height());
  CHECK(back.pixels() == frame.pixels());
  CHECK_FALSE(fs::exists(directory / "frame.png.tmp"));  // written aside, then renamed
}

TEST_CASE("Frames are numbered from 0 without gaps, every K-th step", "[frames][numbering]") {
  const fs::path root = test::scratchDirectory("numbering");
  FrameWriter writer(root, "drop", 3);
  for (long step = 0; step <= 10; ++step) {
    if (writer.wants(step)) writer.write(step, numberedFrame(int(step)));
  }
  CHECK(writer.steps() == std::vector<long>{0, 3, 6, 9});
  for (const char* name :
       {"drop_00000.png", "drop_00001.png", "drop_00002.png", "drop_00003.png"}) {
    CHECK(fs::is_regular_file(root / "drop" / name));
  }
  CHECK_FALSE(fs::exists(root / "drop" / "drop_00004.png"));
  CHECK(readPng(root / "drop" / "drop_00002.png").at(0, 0) == numberedFrame(6).at(0, 0));
}

TEST_CASE("A new run removes the numbered frames of the last one, nothing else",
          "[frames][numbering]") {
  const fs::path root = test::scratchDirectory("stale");
  fs::create_directories(root / "drop");
  std::ofstream(root / "drop" / "drop_00007.png") << "old";
  std::ofstream(root / "drop" / "drop_step00003_00000.png") << "a trace";
  std::ofstream(root / "drop" / "notes.txt") << "keep";
  FrameWriter writer(root, "drop");
  CHECK_FALSE(fs::exists(root / "drop" / "drop_00007.png"));
  CHECK(fs::exists(root / "drop" / "drop_step00003_00000.png"));
  CHECK(fs::exists(root / "drop" / "notes.txt"));
}

TEST_CASE("The contact sheet shows evenly spaced frames, first and last, in a grid",
          "[frames][sheet]") {
  RenderSettings settings;
  CHECK(evenlySpaced(30, 12).front() == 0);
  CHECK(evenlySpaced(30, 12).back() == 29);
  const std::vector<int> indices = evenlySpaced(30, 12);
  for (std::size_t k = 1; k < indices.size(); ++k) {
    const int gap = indices[k] - indices[k - 1];
    CHECK((gap == 2 || gap == 3));  // 29 frames apart over 11 gaps: 2.64 on average
  }
  CHECK(evenlySpaced(5, 12) == std::vector<int>{0, 1, 2, 3, 4});

  const SheetLayout layout = contactSheetLayout(30, 160, 120, settings);
  CHECK(layout.columns == 4);
  CHECK(layout.rows == 3);
  CHECK(layout.thumbnailHeight == settings.sheetThumbnailWidth * 120 / 160);
  CHECK(layout.width == 4 * (settings.sheetThumbnailWidth + settings.spacing) + settings.spacing);
  const SheetLayout small = contactSheetLayout(5, 160, 120, settings);
  CHECK(small.columns == 4);
  CHECK(small.rows == 2);
}

TEST_CASE("The contact sheet file puts each chosen frame in its cell", "[frames][sheet]") {
  const fs::path root = test::scratchDirectory("sheet");
  RenderSettings settings;
  FrameWriter writer(root, "drop", 2, "", settings);
  for (long step = 0; step < 60; ++step) {
    if (writer.wants(step)) writer.write(step, numberedFrame(int(step / 2)));
  }
  const fs::path path = writer.writeContactSheet();
  CHECK(path == root / "drop" / "drop_sheet.png");
  const Canvas sheet = readPng(path);
  const SheetLayout layout = contactSheetLayout(30, 160, 120, settings);
  REQUIRE(sheet.width() == layout.width);
  REQUIRE(sheet.height() == layout.height);
  for (std::size_t k = 0; k < layout.frames.size(); ++k) {
    const int x = layout.thumbnailX(int(k)) + layout.thumbnailWidth / 2;
    const int y = layout.thumbnailY(int(k)) + layout.thumbnailHeight / 2;
    CHECK(sheet.at(x, y) == numberedFrame(layout.frames[k]).at(0, 0));
  }
}

TEST_CASE("An unwritable frame directory gives one error naming the path", "[frames][errors]") {
  const fs::path root = test::scratchDirectory("unwritable");
  std::ofstream(root / "a_file") << "not a directory";
  const fs::path underFile = root / "a_file" / "frames";
  CHECK_THROWS_WITH(FrameWriter(underFile, "drop"), Catch::Contains(underFile.string()));
  const fs::path missingParent = root / "missing" / "frames";
  CHECK_THROWS_AS(FrameWriter(missingParent, "drop"), RenderError);
  CHECK_THROWS_WITH(FrameWriter(missingParent, "drop"), Catch::Contains(missingParent.string()));
  CHECK_FALSE(fs::exists(root / "missing"));
  CHECK_NOTHROW(FrameWriter(root.string() + "/fresh/", "drop"));  // a new root, parent exists
  CHECK(fs::is_directory(root / "fresh" / "drop"));
}

TEST_CASE("A trace writes one frame per solver event, the contact highlighted", "[trace]") {
  const fs::path root = test::scratchDirectory("trace");
  test::FixedSimulation simulation = test::boxOnGround();
  for (int i = 0; i < 3; ++i) {
    SolverEvent event;
    event.iteration = i;
    event.manifold = 0;
    event.point = i % 2;
    event.desiredChange = 0.1;
    event.normalImpulse = 0.3;
    simulation.events.push_back(event);
  }
  const FrameRenderer renderer = boxRenderer(simulation);
  const FrameWriter writer = traceStep(simulation, 4, renderer, root);
  CHECK(simulation.stepCount() == 4);
  CHECK(writer.frameCount() == 3);  // only the fourth step is traced
  CHECK(writer.steps() == std::vector<long>{4, 4, 4});
  CHECK(writer.framePath(0) == root / "box" / "box_step00004_00000.png");
  CHECK(fs::exists(writer.sheetPath()));
  const Canvas first = readPng(writer.framePath(0));
  const Vec2 ring = renderer.camera().toPixels(Vec2(-0.5, 0.0)) +
                    Vec2(renderer.settings().highlightRadius - 1.0, 0.0);
  CHECK(first.at(int(ring.x()), int(ring.y())) == renderer.settings().colours.highlight);
}

TEST_CASE("Panels sit side by side under their labels", "[panels]") {
  RenderSettings settings;
  const Canvas red(100, 80, Color{255, 0, 0, 255});
  const Canvas blue(100, 80, Color{0, 0, 255, 255});
  const Canvas image = composePanels({{&red, "micro"}, {&blue, "sequential"}}, settings);
  const int label = panelLabelHeight(settings);
  CHECK(image.width() == 200 + 3 * settings.spacing);
  CHECK(image.height() == 80 + label + 2 * settings.spacing);
  const int y = settings.spacing + label + 40;
  CHECK(image.at(settings.spacing + 50, y) == red.at(0, 0));
  CHECK(image.at(2 * settings.spacing + 150, y) == blue.at(0, 0));
  CHECK(image.at(settings.spacing + 1, settings.spacing + 1) == settings.colours.sheetLabel);
}
