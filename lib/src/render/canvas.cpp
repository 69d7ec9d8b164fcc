// Pixels and anti-aliased shapes by signed distance (see canvas.h).
#include "impulse2d/render/canvas.h"

#include <algorithm>
#include <cmath>

namespace impulse2d::render {

namespace {

/// The half plane n·p ≥ offset, n a unit normal pointing inside the shape.
struct HalfPlane {
  Vec2 normal;
  double offset = 0.0;
  double distance(const Vec2& p) const { return normal.dot(p) - offset; }
};

/// A colour channel from a value in [0, 255], rounded to nearest.
std::uint8_t channel(double value) {
  return static_cast<std::uint8_t>(std::clamp(value, 0.0, 255.0) + 0.5);
}

Color mix(Color from, Color to, double t) {
  auto lerp = [t](std::uint8_t a, std::uint8_t b) { return channel(a + t * (b - a)); };
  return Color{lerp(from.r, to.r), lerp(from.g, to.g), lerp(from.b, to.b), lerp(from.a, to.a)};
}

/// Colours a pixel whose centre lies `inside` pixels inside the shape's edge: coverage ramps
/// over one pixel across the edge, and the outline band is the first outlineWidth pixels.
void shade(Canvas& canvas, int x, int y, double inside, Color fill, Color outline,
           double outlineWidth) {
  const double coverage = std::clamp(inside + 0.5, 0.0, 1.0);
  if (coverage <= 0.0) return;
  const double outlineShare =
      outlineWidth > 0.0 ? std::clamp(outlineWidth + 0.5 - inside, 0.0, 1.0) : 0.0;
  const Color color = outlineShare > 0.0 ? mix(fill, outline, outlineShare) : fill;
  canvas.blend(x, y, color, coverage);
}

/// The inward half planes of a convex polygon's edges, whatever its winding.
std::vector<HalfPlane> insideHalfPlanes(const std::vector<Vec2>& vertices) {
  const std::size_t count = vertices.size();
  double twiceArea = 0.0;
  for (std::size_t i = 0; i < count; ++i)
    twiceArea += cross(vertices[i], vertices[(i + 1) % count]);
  const double inward = twiceArea >= 0.0 ? 1.0 : -1.0;
  std::vector<HalfPlane> planes;
  planes.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const Vec2 edge = vertices[(i + 1) % count] - vertices[i];
    const double length = edge.norm();
    if (length < 1e-12) continue;
    const Vec2 normal = inward * leftPerpendicular(edge) / length;
    planes.push_back(HalfPlane{normal, normal.dot(vertices[i])});
  }
  return planes;
}

/// The pixel columns [first, last] of the row at centreY whose centres lie at least `inside`
/// pixels inside every edge (negative: outside by up to −inside); first > last when none do.
std::pair<int, int> rowSpan(const std::vector<HalfPlane>& planes, double centreY, double inside,
                            int width) {
  double low = 0.0;
  double high = width;
  for (const HalfPlane& plane : planes) {
    const double rest = plane.offset + inside - plane.normal.y() * centreY;  // n.x·x ≥ rest
    if (std::abs(plane.normal.x()) < 1e-12) {
      if (rest > 0.0) return {1, 0};
    } else if (plane.normal.x() > 0.0) {
      low = std::max(low, rest / plane.normal.x());
    } else {
      high = std::min(high, rest / plane.normal.x());
    }
  }
  return {std::max(0, int(std::ceil(low - 0.5))), std::min(width - 1, int(std::floor(high - 0.5)))};
}

/// Shades the pixels of one row of a convex polygon: the edge pixels by their distance, the
/// interior (an opaque fill, fully covered, clear of the outline) by a plain copy.
void fillPolygonRow(Canvas& canvas, const std::vector<HalfPlane>& planes, int y, Color fill,
                    Color outline, double outlineWidth) {
  const double centreY = y + 0.5;
  const auto [first, last] = rowSpan(planes, centreY, -0.5, canvas.width());
  auto [solidFirst, solidLast] =
      rowSpan(planes, centreY, std::max(outlineWidth, 0.0) + 0.5, canvas.width());
  if (fill.a != 255) solidFirst = last + 1;
  for (int x = first; x <= last; ++x) {
    if (x == solidFirst && solidFirst <= solidLast) {
      std::fill(&canvas.at(solidFirst, y), &canvas.at(solidLast, y) + 1, fill);
      x = solidLast;
      continue;
    }
    const Vec2 centre(x + 0.5, centreY);
    double inside = planes[0].distance(centre);
    for (std::size_t i = 1; i < planes.size(); ++i) {
      inside = std::min(inside, planes[i].distance(centre));
    }
    shade(canvas, x, y, inside, fill, outline, outlineWidth);
  }
}

}  // namespace

Color withOpacity(Color color, double opacity) {
  color.a = channel(color.a * std::clamp(opacity, 0.0, 1.0));
  return color;
}

Canvas::Canvas(int width, int height, Color background) {
  reset(width, height, background);
}

void Canvas::reset(int width, int height, Color color) {
  width_ = width;
  height_ = height;
  pixels_.assign(std::size_t(width) * std::size_t(height), color);
}

void Canvas::fill(Color color) {
  std::fill(pixels_.begin(), pixels_.end(), color);
}

void Canvas::blend(int x, int y, Color color, double coverage) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
  const double alpha = coverage * color.a / 255.0;
  Color& target = at(x, y);
  if (alpha >= 1.0) {
    target = color;
    return;
  }
  auto over = [alpha](std::uint8_t source, std::uint8_t below) {
    return channel(alpha * source + (1.0 - alpha) * below);
  };
  target = Color{over(color.r, target.r), over(color.g, target.g), over(color.b, target.b),
                 channel(255.0 * alpha + (1.0 - alpha) * target.a)};
}

void fillConvexPolygon(Canvas& canvas, const std::vector<Vec2>& vertices, Color fill, Color outline,
                       double outlineWidth) {
  if (vertices.size() < 3) return;
  const std::vector<HalfPlane> planes = insideHalfPlanes(vertices);
  double top = vertices[0].y();
  double bottom = top;
  for (const Vec2& vertex : vertices) {
    top = std::min(top, vertex.y());
    bottom = std::max(bottom, vertex.y());
  }
  const int firstRow = std::max(0, int(std::floor(top - 0.5)));
  const int lastRow = std::min(canvas.height() - 1, int(std::ceil(bottom + 0.5)));
  for (int y = firstRow; y <= lastRow; ++y) {
    fillPolygonRow(canvas, planes, y, fill, outline, outlineWidth);
  }
}

void fillCircle(Canvas& canvas, const Vec2& centre, double radius, Color fill, Color outline,
                double outlineWidth) {
  // The one-pixel ramp across a curved edge adds π/12 pixels of area at any radius (more ramp
  // lies outside the circle than inside); drawing the edge 1/(24r) further in takes it back.
  const double edge = radius - 1.0 / (24.0 * std::max(radius, 0.5));
  const double reach = radius + 0.5;
  const int firstRow = std::max(0, int(std::floor(centre.y() - reach)));
  const int lastRow = std::min(canvas.height() - 1, int(std::ceil(centre.y() + reach)));
  for (int y = firstRow; y <= lastRow; ++y) {
    const double dy = y + 0.5 - centre.y();
    const double halfSpan = std::sqrt(std::max(0.0, reach * reach - dy * dy));
    const int first = std::max(0, int(std::floor(centre.x() - halfSpan)));
    const int last = std::min(canvas.width() - 1, int(std::ceil(centre.x() + halfSpan)));
    for (int x = first; x <= last; ++x) {
      const double dx = x + 0.5 - centre.x();
      shade(canvas, x, y, edge - std::sqrt(dx * dx + dy * dy), fill, outline, outlineWidth);
    }
  }
}

void fillRectangle(Canvas& canvas, const Vec2& corner, const Vec2& size, Color color) {
  const Vec2 end = corner + size;
  const int firstColumn = std::max(0, int(std::floor(corner.x())));
  const int lastColumn = std::min(canvas.width() - 1, int(std::ceil(end.x())) - 1);
  const int firstRow = std::max(0, int(std::floor(corner.y())));
  const int lastRow = std::min(canvas.height() - 1, int(std::ceil(end.y())) - 1);
  for (int y = firstRow; y <= lastRow; ++y) {
    const double coverY = std::min(end.y(), y + 1.0) - std::max(corner.y(), double(y));
    for (int x = firstColumn; x <= lastColumn; ++x) {
      const double coverX = std::min(end.x(), x + 1.0) - std::max(corner.x(), double(x));
      canvas.blend(x, y, color, coverX * coverY);
    }
  }
}

void drawLine(Canvas& canvas, const Vec2& from, const Vec2& to, double width, Color color) {
  const Vec2 along = to - from;
  const double length = along.norm();
  if (length < 1e-9) return;
  const Vec2 side = (0.5 * width / length) * leftPerpendicular(along);
  fillConvexPolygon(canvas, {from - side, to - side, to + side, from + side}, color, color, 0.0);
}

void drawArrow(Canvas& canvas, const Vec2& from, const Vec2& to, double width, double headLength,
               double headWidth, Color color) {
  const Vec2 along = to - from;
  const double length = along.norm();
  if (length < 1e-9) return;
  const Vec2 direction = along / length;
  const double head = std::min(headLength, length);
  const Vec2 headBase = to - head * direction;
  const Vec2 side = (0.5 * headWidth * head / headLength) * leftPerpendicular(direction);
  drawLine(canvas, from, headBase, width, color);
  fillConvexPolygon(canvas, {to, headBase + side, headBase - side}, color, color, 0.0);
}

void blit(Canvas& target, const Canvas& source, int x, int y) {
  for (int row = std::max(0, -y); row < source.height() && row + y < target.height(); ++row) {
    for (int column = std::max(0, -x); column < source.width() && column + x < target.width();
         ++column) {
      target.at(column + x, row + y) = source.at(column, row);
    }
  }
}

Canvas resized(const Canvas& source, int width, int height) {
  Canvas result(width, height);
  for (int y = 0; y < height; ++y) {
    const int top = y * source.height() / height;
    const int bottom = std::max(top + 1, (y + 1) * source.height() / height);
    for (int x = 0; x < width; ++x) {
      const int left = x * source.width() / width;
      const int right = std::max(left + 1, (x + 1) * source.width() / width);
      double sum[4] = {0.0, 0.0, 0.0, 0.0};
      for (int sy = top; sy < bottom; ++sy) {
        for (int sx = left; sx < right; ++sx) {
          const Color& pixel = source.at(sx, sy);
          sum[0] += pixel.r;
          sum[1] += pixel.g;
          sum[2] += pixel.b;
          sum[3] += pixel.a;
        }
      }
      const double count = double(bottom - top) * (right - left);
      result.at(x, y) = Color{channel(sum[0] / count), channel(sum[1] / count),
                              channel(sum[2] / count), channel(sum[3] / count)};
    }
  }
  return result;
}

}  // namespace impulse2d::render
