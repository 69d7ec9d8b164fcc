// PNG files of canvases, written so that no file is ever half-written under its final name.
#pragma once

#include <filesystem>
#include <stdexcept>

#include "impulse2d/render/canvas.h"

namespace impulse2d::render {

/// A frame, sheet or video could not be written or read; the message names the path.
class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Writes the canvas as a PNG (RGB when fully opaque, else RGBA): first to `path` + ".tmp", then
/// renamed to `path`, so a reader (or an interrupted run) never sees a half-written frame. Throws
/// RenderError.
void writePng(const std::filesystem::path& path, const Canvas& canvas);

/// Reads a PNG (any channel count) into a canvas; throws RenderError when it cannot.
Canvas readPng(const std::filesystem::path& path);

}  // namespace impulse2d::render
