// Text in stb_easy_font's bitmap font: it turns a string into axis-aligned quads, which are drawn
// as rectangles scaled up by the text scale.
#include <cstring>

#include <stb_easy_font.h>

#include "impulse2d/render/canvas.h"

namespace impulse2d::render {

namespace {

/// stb_easy_font's quads: four vertices of x, y, z (floats) and an RGBA colour, 16 bytes each.
constexpr int bytesPerVertex = 16;
constexpr int bytesPerQuad = 4 * bytesPerVertex;
/// stb_easy_font uses about 270 bytes of vertices per character; this leaves room.
constexpr std::size_t bufferBytesPerCharacter = 400;
/// Height of capitals plus descenders in font pixels: the ink of one line.
constexpr double fontInkHeight = 9.0;

/// The text with everything stb_easy_font has no glyph for replaced by '?'.
std::string printable(const std::string& text) {
  std::string result = text;
  for (char& c : result) {
    if (c != '\n' && (c < 32 || c > 126)) c = '?';
  }
  return result;
}

Vec2 vertexPosition(const std::vector<char>& buffer, int quad, int vertex) {
  float xy[2];
  std::memcpy(xy, buffer.data() + quad * bytesPerQuad + vertex * bytesPerVertex, sizeof xy);
  return Vec2(xy[0], xy[1]);
}

}  // namespace

void drawText(Canvas& canvas, const std::string& text, const Vec2& corner, double scale,
              Color color) {
  std::string glyphs = printable(text);
  std::vector<char> buffer(glyphs.size() * bufferBytesPerCharacter + bytesPerQuad);
  const int quads =
      stb_easy_font_print(0.0f, 0.0f, glyphs.data(), nullptr, buffer.data(), int(buffer.size()));
  for (int quad = 0; quad < quads; ++quad) {
    const Vec2 low = vertexPosition(buffer, quad, 0);
    const Vec2 high = vertexPosition(buffer, quad, 2);
    fillRectangle(canvas, corner + scale * low, scale * (high - low), color);
  }
}

double textWidth(const std::string& text, double scale) {
  std::string glyphs = printable(text);
  return scale * stb_easy_font_width(glyphs.data());
}

double textHeight(double scale) {
  return scale * fontInkHeight;
}

}  // namespace impulse2d::render
