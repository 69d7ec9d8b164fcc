// Frames -> animated GIF through giflib, with a fixed palette so every frame shares one colour
// table and a run's GIF is the same bytes every time.
#include "impulse2d/render/animation.h"

#include <gif_lib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>

namespace impulse2d::render {

namespace {

std::uint8_t level(int index, int levels) {
  return std::uint8_t(std::lround(255.0 * index / (levels - 1)));
}

/// An open GIF file that closes itself; giflib errors become RenderErrors naming the path.
class GifFile {
 public:
  explicit GifFile(const std::filesystem::path& path) : path_(path) {
    int error = 0;
    gif_ = EGifOpenFileName(path.c_str(), false, &error);
    if (gif_ == nullptr) fail(error);
  }
  ~GifFile() {
    int error = 0;
    if (gif_ != nullptr) EGifCloseFile(gif_, &error);
  }
  GifFile(const GifFile&) = delete;
  GifFile& operator=(const GifFile&) = delete;

  void check(int result) const {
    if (result == GIF_ERROR) fail(gif_->Error);
  }
  /// Closes the file, reporting a failure to finish it.
  void close() {
    int error = 0;
    const int result = EGifCloseFile(gif_, &error);
    gif_ = nullptr;
    if (result == GIF_ERROR) fail(error);
  }
  GifFileType* get() const { return gif_; }

 private:
  [[noreturn]] void fail(int error) const {
    const char* message = GifErrorString(error);
    throw RenderError("cannot write GIF '" + path_.string() +
                      "': " + (message ? message : "unknown giflib error"));
  }

  std::filesystem::path path_;
  GifFileType* gif_ = nullptr;
};

void writeScreen(GifFile& gif, int width, int height, const std::vector<Color>& palette) {
  std::array<GifColorType, 256> colours{};
  for (std::size_t i = 0; i < palette.size(); ++i) {
    colours[i] = {palette[i].r, palette[i].g, palette[i].b};
  }
  ColorMapObject* map = GifMakeMapObject(256, colours.data());
  EGifSetGifVersion(gif.get(), true);  // GIF89a: frame delays and looping are 89a extensions
  const int result = EGifPutScreenDesc(gif.get(), width, height, 8, 0, map);
  GifFreeMapObject(map);
  gif.check(result);
  // NETSCAPE2.0 application block: loop forever.
  static const unsigned char loop[3] = {1, 0, 0};
  gif.check(EGifPutExtensionLeader(gif.get(), APPLICATION_EXT_FUNC_CODE));
  gif.check(EGifPutExtensionBlock(gif.get(), 11, "NETSCAPE2.0"));
  gif.check(EGifPutExtensionBlock(gif.get(), 3, loop));
  gif.check(EGifPutExtensionTrailer(gif.get()));
}

/// A frame's pixels as palette indices; colours seen before are looked up, not searched again.
void writeFrame(GifFile& gif, const Image& frame, int delay, const std::vector<Color>& palette,
                std::map<std::uint32_t, GifPixelType>& known) {
  GraphicsControlBlock control{DISPOSAL_UNSPECIFIED, false, delay, NO_TRANSPARENT_COLOR};
  GifByteType extension[4];
  const std::size_t length = EGifGCBToExtension(&control, extension);
  gif.check(EGifPutExtension(gif.get(), GRAPHICS_EXT_FUNC_CODE, int(length), extension));
  gif.check(EGifPutImageDesc(gif.get(), 0, 0, frame.width(), frame.height(), false, nullptr));
  std::vector<GifPixelType> row(std::size_t(frame.width()));
  for (int y = 0; y < frame.height(); ++y) {
    for (int x = 0; x < frame.width(); ++x) {
      const Color c = frame.at(x, y);
      const std::uint32_t key = (std::uint32_t(c.r) << 16) | (std::uint32_t(c.g) << 8) | c.b;
      auto entry = known.find(key);
      if (entry == known.end()) {
        entry = known.emplace(key, GifPixelType(nearestPaletteIndex(palette, c))).first;
      }
      row[std::size_t(x)] = entry->second;
    }
    gif.check(EGifPutLine(gif.get(), row.data(), frame.width()));
  }
}

}  // namespace

std::vector<Color> gifPalette() {
  std::vector<Color> palette;
  for (int r = 0; r < 6; ++r) {
    for (int g = 0; g < 7; ++g) {
      for (int b = 0; b < 6; ++b) palette.push_back({level(r, 6), level(g, 7), level(b, 6), 255});
    }
  }
  for (const std::uint8_t grey : {64, 128, 192, 240}) palette.push_back({grey, grey, grey, 255});
  return palette;
}

int nearestPaletteIndex(const std::vector<Color>& palette, Color colour) {
  int best = 0;
  int bestDistance = 1 << 30;
  for (int i = 0; i < int(palette.size()); ++i) {
    const int dr = int(palette[i].r) - colour.r;
    const int dg = int(palette[i].g) - colour.g;
    const int db = int(palette[i].b) - colour.b;
    const int distance = dr * dr + dg * dg + db * db;
    if (distance < bestDistance) {
      best = i;
      bestDistance = distance;
    }
  }
  return best;
}

std::filesystem::path writeGif(const FrameWriter& writer, double framesPerSecond) {
  if (writer.frameCount() == 0) {
    throw RenderError("no frames in '" + writer.directory().string() + "' to make a GIF of");
  }
  const std::filesystem::path path = writer.directory() / (writer.prefix() + ".gif");
  const int delay = std::max(2, int(std::lround(100.0 / framesPerSecond)));
  const std::vector<Color> palette = gifPalette();
  std::map<std::uint32_t, GifPixelType> known;
  GifFile gif(path);
  for (int index = 0; index < writer.frameCount(); ++index) {
    const Image frame = rasterise(writer.frames()[std::size_t(index)].picture);
    if (index == 0) writeScreen(gif, frame.width(), frame.height(), palette);
    writeFrame(gif, frame, delay, palette, known);
  }
  gif.close();
  // giflib creates the file readable by its owner only; a GIF is for sharing.
  using std::filesystem::perms;
  std::filesystem::permissions(
      path, perms::owner_read | perms::owner_write | perms::group_read | perms::others_read);
  return path;
}

}  // namespace impulse2d::render
