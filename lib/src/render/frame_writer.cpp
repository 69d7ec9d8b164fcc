// Numbered frames, every K-th step, and the contact sheet of a run.
#include "impulse2d/render/frame_writer.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "impulse2d/render/contact_sheet.h"

namespace impulse2d::render {

namespace {

bool endsWith(const std::string& text, const std::string& ending) {
  return text.size() >= ending.size() &&
         text.compare(text.size() - ending.size(), ending.size(), ending) == 0;
}

/// PREFIX_ddddd.png (.svg, .pdf), or the .tmp of one that was being written.
bool isNumberedFrame(const std::string& name, const std::string& prefix) {
  const std::string head = prefix + "_";
  if (name.compare(0, head.size(), head) != 0) return false;
  std::string number = name.substr(head.size());
  for (const std::string ending : {".png", ".png.tmp", ".svg", ".svg.tmp", ".pdf", ".pdf.tmp"}) {
    if (endsWith(number, ending)) {
      number.resize(number.size() - ending.size());
      return number.size() >= 5 && std::all_of(number.begin(), number.end(), [](char c) {
               return std::isdigit(static_cast<unsigned char>(c)) != 0;
             });
    }
  }
  return false;
}

}  // namespace

std::string tracePrefix(const std::string& scene, long step) {
  char number[32];
  std::snprintf(number, sizeof number, "_step%05ld", step);
  return scene + number;
}

std::string comparePrefix(const std::string& scene) {
  return scene + "_compare";
}

FrameWriter::FrameWriter(const std::filesystem::path& root, const std::string& scene, int every,
                         const std::string& prefix, const RenderSettings& settings,
                         ImageFormat format)
    : directory_(root / scene),
      prefix_(prefix.empty() ? scene : prefix),
      every_(every),
      settings_(settings),
      format_(format) {
  if (every < 1) throw std::invalid_argument("frames every K steps needs K >= 1");
  prepareDirectory(root);
  removeEarlierFrames();
}

void FrameWriter::prepareDirectory(const std::filesystem::path& root) {
  const std::filesystem::path named = root.has_filename() ? root : root.parent_path();  // "a/b/"
  const std::filesystem::path parent = named.parent_path();
  if (!parent.empty() && !std::filesystem::is_directory(parent)) {
    throw RenderError("cannot create frame directory '" + root.string() + "': '" + parent.string() +
                      "' is not an existing directory");
  }
  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  if (error) {
    throw RenderError("cannot create frame directory '" + directory_.string() +
                      "': " + error.message());
  }
  const std::filesystem::path probe = directory_ / (prefix_ + ".probe.tmp");
  if (!std::ofstream(probe)) {
    throw RenderError("cannot write frames to '" + directory_.string() +
                      "': the directory is not writable");
  }
  std::filesystem::remove(probe, error);
}

void FrameWriter::removeEarlierFrames() const {
  for (const auto& entry : std::filesystem::directory_iterator(directory_)) {
    if (isNumberedFrame(entry.path().filename().string(), prefix_)) {
      std::filesystem::remove(entry.path());
    }
  }
}

std::filesystem::path FrameWriter::write(long step, const Frame& frame, bool preferred) {
  const std::filesystem::path path = framePath(frameCount());
  pictures_.write(path, frame.picture, format_);
  steps_.push_back(step);
  frames_.push_back(frame);
  preferred_.push_back(preferred);
  return path;
}

std::filesystem::path FrameWriter::writeContactSheet() const {
  if (steps_.empty()) {
    throw RenderError("no frames in '" + directory_.string() + "' to make a contact sheet of");
  }
  const Frame& first = frames_.front();
  const int panels = std::max(1, int(first.panels.size()));
  const Vec2& scene = first.panels.empty() ? first.sceneSize : first.panels.front().sceneSize;
  const SheetLayout layout =
      contactSheetLayout(chooseFrames(preferred_, sheetFrameCount(panels, settings_)),
                         int(scene.x()), int(scene.y()), settings_, panels);
  writePicture(sheetPath(), drawContactSheet(layout, frames_, settings_), format_);
  return sheetPath();
}

std::filesystem::path FrameWriter::framePath(int index) const {
  char number[32];
  std::snprintf(number, sizeof number, "_%05d.", index);
  return directory_ / (prefix_ + number + extensionOf(format_));
}

std::filesystem::path FrameWriter::sheetPath() const {
  return directory_ / (prefix_ + "_sheet." + extensionOf(format_));
}

}  // namespace impulse2d::render
