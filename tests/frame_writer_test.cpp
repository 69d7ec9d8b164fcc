// Frames on disk: PNG round trips, numbering every K-th step, the contact sheet's layout, clear
// errors for unwritable directories, traces (a frame per solver event) and side-by-side panels.
#include <algorithm>
#include <fstream>

#include <catch2/catch.hpp>

#include "impulse2d/render/contact_sheet.h"
#include "impulse2d/render/frame.h"
#include "impulse2d/render/frame_writer.h"
#include "impulse2d/render/panels.h"
#include "impulse2d/render/trace.h"
#include "impulse2d/render/viewer.h"
#include "render_fixtures.h"

using namespace impulse2d;
using namespace impulse2d::render;
namespace fs = std::filesystem;

namespace {

/// The colour that encodes frame `number`, so a thumbnail tells which frame it shows.
Color numberColour(int number) {
  return Color{std::uint8_t(8 * number), 90, std::uint8_t(250 - 8 * number), 255};
}

/// A solid frame of that colour.
Frame numberedFrame(int number) {
  Frame frame;
  frame.picture = Picture(160, 120);
  frame.sceneSize = Vec2(160.0, 120.0);
  frame.caption = "frame " + std::to_string(number);
  Drawing(frame.picture).rectangle(Vec2::Zero(), Vec2(160.0, 120.0), numberColour(number));
  return frame;
}

FrameRenderer boxRenderer(const test::FixedSimulation& simulation) {
  return FrameRenderer(fitCamera(simulation.bodies(), ViewDef{}, RenderSettings{}), "box");
}

}  // namespace

TEST_CASE("A frame read back from its PNG equals what was drawn", "[png]") {
  const fs::path directory = test::scratchDirectory("round_trip");
  const test::FixedSimulation simulation = test::boxOnGround();
  FrameRenderer renderer = boxRenderer(simulation);
  const Image frame = rasterise(renderer.draw(simulation).picture);
  writePng(directory / "frame.png", frame);
  const Image back = readPng(directory / "frame.png");
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
  CHECK(readPng(root / "drop" / "drop_00002.png").at(0, 0) == numberColour(6));
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
  // 61 frames (a run of 180 steps, every 3rd): 11 of them split it exactly, every 6th frame,
  // where 12 would leave gaps of 5 and 6.
  const std::vector<int> exact = evenlySpaced(61, 12);
  REQUIRE(exact.size() == 11);
  for (std::size_t k = 0; k < exact.size(); ++k) CHECK(exact[k] == 6 * int(k));
  // 13 frames: 12 by rounding would skip one (a gap of 2 among gaps of 1); 7 are every 2nd.
  CHECK(evenlySpaced(13, 12) == std::vector<int>{0, 2, 4, 6, 8, 10, 12});

  // Cells of a 4:3 scene, 480 pixels wide: 4 × 3 of them are nearest a 16:9 slide.
  const SheetLayout layout = contactSheetLayout(evenlySpaced(30, 12), 160, 120, settings);
  CHECK(layout.thumbnailWidth >= 480);
  CHECK(layout.columns == 4);
  CHECK(layout.rows == 3);
  CHECK(layout.thumbnailHeight == layout.thumbnailWidth * 120 / 160);
  CHECK(layout.width == 4 * (layout.thumbnailWidth + settings.spacing) + settings.spacing);
  CHECK(layout.titleHeight > 0);
  CHECK(layout.legendHeight > 0);
  // A comparison of two panels: each panel 480 wide, 6 frames of them.
  const SheetLayout pairs =
      contactSheetLayout(evenlySpaced(30, sheetFrameCount(2, settings)), 160, 120, settings, 2);
  CHECK(pairs.frames.size() == 6);
  CHECK(pairs.cellWidth() == 2 * pairs.thumbnailWidth + settings.spacing);
  CHECK(pairs.thumbnailWidth >= 480);
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
  const Image sheet = readPng(path);
  const SheetLayout layout = contactSheetLayout(evenlySpaced(30, 12), 160, 120, settings);
  REQUIRE(sheet.width() == layout.width);
  REQUIRE(sheet.height() == layout.height);
  for (std::size_t k = 0; k < layout.frames.size(); ++k) {
    const int x = layout.thumbnailX(int(k)) + layout.thumbnailWidth / 2;
    const int y = layout.thumbnailY(int(k)) + layout.thumbnailHeight / 2;
    CHECK(sheet.at(x, y) == numberColour(layout.frames[k]));
  }
  // One legend, in a strip under the grid.
  CHECK(sheet.at(layout.width / 2, layout.height - 2) == settings.colours.stripBackground);
}

TEST_CASE("A sheet draws each scene again at its cell's size, text at sheetTextSize",
          "[frames][sheet]") {
  const fs::path root = test::scratchDirectory("sheet_redraw");
  test::FixedSimulation simulation = test::boxOnGround();
  FrameRenderer renderer = boxRenderer(simulation);
  RenderSettings settings;
  FrameWriter writer(root, "box", 1, "", settings);
  const Frame frame = renderer.draw(simulation);
  REQUIRE(frame.redraw);
  writer.write(0, frame);
  writer.write(1, frame);
  const Image sheet = readPng(writer.writeContactSheet());
  const SheetLayout layout =
      contactSheetLayout({0, 1}, frame.camera.width, frame.camera.height, settings);
  CHECK(sheet.width() == layout.width);
  // Drawn again through a camera 480 / 800 the frame's, the text at the sheet's size.
  DrawingLog log;
  Picture cell(layout.thumbnailWidth, layout.thumbnailHeight);
  Drawing drawing(cell, &log);
  const Camera camera = frame.camera.resized(double(layout.thumbnailWidth) / frame.camera.width,
                                             settings.sheetTextSize);
  const DrawnKinds drawn = frame.redraw(drawing, camera);
  CHECK(drawn.normalForces == frame.drawn.normalForces);
  // The same world point at the cell's centre, at 480 / 800 the scale: the same view, smaller.
  CHECK(camera.centre == frame.camera.centre);
  CHECK(camera.scale == Approx(frame.camera.scale * layout.thumbnailWidth / frame.camera.width));
  CHECK(camera.textSize == settings.sheetTextSize);
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
  // Each frame is kept by the writer, captioned with its event for the sheet.
  REQUIRE(writer.frames().size() == 3);
  CHECK(writer.frames()[0].caption == "velocity 0: contact 0.0");
  CHECK(writer.frames()[1].caption == "velocity 1: contact 0.1");
}

TEST_CASE("A trace sheet shows every velocity event before position events", "[trace][sheet]") {
  // 4 velocity events among 20 position events, 6 places: all 4, then 2 of the others.
  std::vector<bool> velocity(24, false);
  for (const int k : {3, 9, 15, 21}) velocity[std::size_t(k)] = true;
  const std::vector<int> chosen = chooseFrames(velocity, 6);
  CHECK(chosen.size() == 6);
  for (const int k : {3, 9, 15, 21}) {
    CHECK(std::find(chosen.begin(), chosen.end(), k) != chosen.end());
  }
  CHECK(std::is_sorted(chosen.begin(), chosen.end()));
}

TEST_CASE("Panels sit in the grid that fills a 16:9 slide best, under their labels", "[panels]") {
  RenderSettings settings;
  // Scaled onto a 16:9 slide, panels cover: two side by side 0.61 of it, one above the other
  // 0.30; four 800 x 640 in 2 x 2 0.69, in 3 x 2 0.62; four tall ones in a row 0.98.
  CHECK(panelColumns(2, 800, 640, settings) == 2);
  CHECK(panelColumns(4, 800, 640, settings) == 2);
  CHECK(panelColumns(4, 400, 900, settings) == 4);
  const Frame red = numberedFrame(0);
  const Frame blue = numberedFrame(30);
  const Frame image = composePanels({{&red, "micro"}, {&blue, "sequential"}}, settings);
  const int label = panelLabelHeight(settings, settings.minimumTextSize);
  CHECK(image.panels.size() == 2);
  CHECK(image.panelLabels == std::vector<std::string>{"micro", "sequential"});
  CHECK(image.picture.width() == 2 * 160 + 3 * settings.spacing);
  CHECK(image.picture.height() == 120 + label + 2 * settings.spacing);
  const Image pixels = rasterise(image.picture);
  const int y = settings.spacing + label + 60;
  CHECK(pixels.at(settings.spacing + 80, y) == numberColour(0));
  CHECK(pixels.at(2 * settings.spacing + 240, y) == numberColour(30));
  CHECK(pixels.at(settings.spacing + 1, settings.spacing + 1) == settings.colours.sheetLabel);
}

TEST_CASE("The viewer page's script holds a scene name with a line break, quotes and a tag",
          "[frames][viewer]") {
  // The names are written into the script as JSON strings: a raw line break would end the
  // string, a quote the literal, a "<" could begin "</script>". scripts/viewer-test loads a page
  // of such a name in a browser.
  const std::string name = "two\nlines \"quoted\" <b>";
  const fs::path root = test::scratchDirectory("viewer_names");
  FrameWriter writer(root, name, 1);
  writer.write(0, numberedFrame(0));
  std::ifstream in(writeViewer(writer, name, FigureTable{}, 30.0));
  std::string line;
  std::string frames;
  while (std::getline(in, line)) {
    if (line.rfind("const frames = ", 0) == 0) frames = line;
  }
  CHECK(frames == "const frames = [\"two\\u000alines \\\"quoted\\\" \\u003cb>_00000.png\"];");
}
