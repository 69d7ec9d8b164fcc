// PNG writing through libdeflate (the chunks by hand: signature, IHDR, IDAT, IEND) and reading
// through stb_image.
#include "impulse2d/render/png.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <system_error>

#include <libdeflate.h>
#include <stb_image.h>

namespace impulse2d::render {

namespace {

/// Fast deflate: frames are flat colours, which level 1 already packs well.
constexpr int kCompressionLevel = 1;

bool opaque(const Image& image) {
  return std::all_of(image.pixels().begin(), image.pixels().end(),
                     [](const Color& pixel) { return pixel.a == 255; });
}

void appendWord(std::vector<std::uint8_t>& bytes, std::uint32_t word) {
  for (int shift = 24; shift >= 0; shift -= 8) bytes.push_back(std::uint8_t(word >> shift));
}

/// A chunk: length, type, data, and the CRC of type and data.
void appendChunk(std::vector<std::uint8_t>& file, const char* type,
                 const std::vector<std::uint8_t>& data) {
  appendWord(file, std::uint32_t(data.size()));
  const std::size_t start = file.size();
  file.insert(file.end(), type, type + 4);
  file.insert(file.end(), data.begin(), data.end());
  appendWord(file, libdeflate_crc32(0, file.data() + start, file.size() - start));
}

/// The rows as PNG scanlines: each a filter byte (0, none) and its pixels' channels.
std::vector<std::uint8_t> scanlines(const Image& image, int channels) {
  const std::size_t stride = std::size_t(image.width()) * channels + 1;
  std::vector<std::uint8_t> raw(stride * std::size_t(image.height()));
  std::uint8_t* out = raw.data();
  for (int y = 0; y < image.height(); ++y) {
    *out++ = 0;
    for (int x = 0; x < image.width(); ++x) {
      const Color& pixel = image.at(x, y);
      *out++ = pixel.r;
      *out++ = pixel.g;
      *out++ = pixel.b;
      if (channels == 4) *out++ = pixel.a;
    }
  }
  return raw;
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

PngEncoder::PngEncoder()
    : compressor_(libdeflate_alloc_compressor(kCompressionLevel), libdeflate_free_compressor) {
  if (!compressor_) throw RenderError("cannot start compressing images: out of memory");
}

const std::vector<std::uint8_t>& PngEncoder::encode(int width, int height, int channels,
                                                    const std::vector<std::uint8_t>& scanlines) {
  std::vector<std::uint8_t> header;
  appendWord(header, std::uint32_t(width));
  appendWord(header, std::uint32_t(height));
  // 8 bits per channel; colour type 2 (RGB) or 6 (RGBA); deflate; filters by row; no interlace.
  header.insert(header.end(), {8, std::uint8_t(channels == 4 ? 6 : 2), 0, 0, 0});
  file_.assign({0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'});
  appendChunk(file_, "IHDR", header);
  // IDAT: deflated straight into the file, then its length and CRC filled in.
  const std::size_t start = file_.size();
  const std::size_t bound = libdeflate_zlib_compress_bound(compressor_.get(), scanlines.size());
  file_.resize(start + 8 + bound);
  const std::size_t packed = libdeflate_zlib_compress(
      compressor_.get(), scanlines.data(), scanlines.size(), file_.data() + start + 8, bound);
  file_.resize(start + 8 + packed);
  const std::uint8_t lengthAndType[8] = {std::uint8_t(packed >> 24),
                                         std::uint8_t(packed >> 16),
                                         std::uint8_t(packed >> 8),
                                         std::uint8_t(packed),
                                         'I',
                                         'D',
                                         'A',
                                         'T'};
  std::copy(lengthAndType, lengthAndType + 8, file_.begin() + std::ptrdiff_t(start));
  appendWord(file_, libdeflate_crc32(0, file_.data() + start + 4, packed + 4));
  appendChunk(file_, "IEND", {});
  return file_;
}

std::vector<std::uint8_t> encodePng(const Image& image) {
  const int channels = opaque(image) ? 3 : 4;
  PngEncoder encoder;
  return encoder.encode(image.width(), image.height(), channels, scanlines(image, channels));
}

void writeFileAtomically(const std::filesystem::path& path,
                         const std::vector<std::uint8_t>& bytes) {
  std::filesystem::path temporary = path;
  temporary += ".tmp";
  writeFile(temporary, bytes);
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    throw RenderError("cannot rename '" + temporary.string() + "' to '" + path.string() +
                      "': " + error.message());
  }
}

void writePng(const std::filesystem::path& path, const Image& image) {
  writeFileAtomically(path, encodePng(image));
}

Image readPng(const std::filesystem::path& path) {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> data(
      stbi_load(path.c_str(), &width, &height, &channels, 4), stbi_image_free);
  if (!data) {
    throw RenderError("cannot read image '" + path.string() + "': " + stbi_failure_reason());
  }
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const stbi_uc* pixel = data.get() + (std::size_t(y) * width + x) * 4;
      image.at(x, y) = Color{pixel[0], pixel[1], pixel[2], pixel[3]};
    }
  }
  return image;
}

}  // namespace impulse2d::render
