// PNG reading and atomic writing through stb_image and stb_image_write.
#include "impulse2d/render/png.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <system_error>
#include <vector>

#include <stb_image.h>
#include <stb_image_write.h>

namespace impulse2d::render {

namespace {

bool opaque(const Canvas& canvas) {
  return std::all_of(canvas.pixels().begin(), canvas.pixels().end(),
                     [](const Color& pixel) { return pixel.a == 255; });
}

/// The pixels as PNG bytes: RGB when every pixel is opaque (a third faster to compress and a
/// smaller file), RGBA otherwise. Returns the channel count.
int pngBytes(const Canvas& canvas, std::vector<std::uint8_t>& bytes) {
  const int channels = opaque(canvas) ? 3 : 4;
  bytes.resize(canvas.pixels().size() * channels);
  std::uint8_t* out = bytes.data();
  for (const Color& pixel : canvas.pixels()) {
    *out++ = pixel.r;
    *out++ = pixel.g;
    *out++ = pixel.b;
    if (channels == 4) *out++ = pixel.a;
  }
  return channels;
}

/// stb's write callback: appends the next encoded bytes to the vector `context`.
void appendBytes(void* context, void* data, int size) {
  auto* file = static_cast<std::vector<std::uint8_t>*>(context);
  const auto* begin = static_cast<const std::uint8_t*>(data);
  file->insert(file->end(), begin, begin + size);
}

/// The PNG file's bytes. stb's own file writer ignores write errors (a full disk would leave a
/// truncated PNG), so the file is encoded in memory and written by writeFile, which sees them.
std::vector<std::uint8_t> encodePng(const Canvas& canvas) {
  std::vector<std::uint8_t> pixels;
  const int channels = pngBytes(canvas, pixels);
  std::vector<std::uint8_t> file;
  if (stbi_write_png_to_func(appendBytes, &file, canvas.width(), canvas.height(), channels,
                             pixels.data(), canvas.width() * channels) == 0) {
    throw RenderError("cannot encode a " + std::to_string(canvas.width()) + " x " +
                      std::to_string(canvas.height()) + " image as PNG");
  }
  return file;
}

/// Writes the bytes to path; on any error removes what was written and throws naming the cause.
void writeFile(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  out.close();
  if (out) return;
  const std::string reason = std::strerror(errno);
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
  throw RenderError("cannot write image '" + path.string() + "': " + reason);
}

}  // namespace

void writePng(const std::filesystem::path& path, const Canvas& canvas) {
  std::filesystem::path temporary = path;
  temporary += ".tmp";
  writeFile(temporary, encodePng(canvas));
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    throw RenderError("cannot rename '" + temporary.string() + "' to '" + path.string() +
                      "': " + error.message());
  }
}

Canvas readPng(const std::filesystem::path& path) {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> data(
      stbi_load(path.c_str(), &width, &height, &channels, 4), stbi_image_free);
  if (!data) {
    throw RenderError("cannot read image '" + path.string() + "': " + stbi_failure_reason());
  }
  Canvas canvas(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const stbi_uc* pixel = data.get() + (std::size_t(y) * width + x) * 4;
      canvas.at(x, y) = Color{pixel[0], pixel[1], pixel[2], pixel[3]};
    }
  }
  return canvas;
}

}  // namespace impulse2d::render
