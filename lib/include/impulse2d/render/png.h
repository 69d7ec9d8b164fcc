// PNG files of images, written so that no file is ever half-written under its final name.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <vector>

#include "impulse2d/render/image.h"

struct libdeflate_compressor;

namespace impulse2d::render {

/// A frame, sheet or video could not be written or read; the message names the path.
class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The image as PNG bytes (RGB when fully opaque, else RGBA), deflated by libdeflate with no
/// row filter at compression level 1: a fraction of stb_image_write's time, for a smaller file
/// (benchmarks/render_benchmark prints the time).
std::vector<std::uint8_t> encodePng(const Image& image);
/// Encodes PNGs, keeping its compressor and output buffer from one image to the next: a run's
/// frames then reuse memory instead of faulting in fresh pages for every frame.
class PngEncoder {
 public:
  PngEncoder();
  /// The PNG bytes of rows already laid out as PNG scanlines: each row a filter byte (0) and its
  /// pixels' `channels` (3: RGB, 4: RGBA) bytes. Valid until the next call.
  const std::vector<std::uint8_t>& encode(int width, int height, int channels,
                                          const std::vector<std::uint8_t>& scanlines);

 private:
  std::unique_ptr<libdeflate_compressor, void (*)(libdeflate_compressor*)> compressor_;
  std::vector<std::uint8_t> file_;
};
/// Writes bytes to `path` + ".tmp", then renames it to `path`; on failure removes what was
/// written and throws RenderError naming the cause.
void writeFileAtomically(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes);

/// Writes the image as a PNG: first to `path` + ".tmp", then renamed to `path`, so a reader (or
/// an interrupted run) never sees a half-written frame. Throws RenderError.
void writePng(const std::filesystem::path& path, const Image& image);

/// Reads a PNG (any channel count) into an image; throws RenderError when it cannot.
Image readPng(const std::filesystem::path& path);

}  // namespace impulse2d::render
