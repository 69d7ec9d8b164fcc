// The legend strip: swatches and words, flowed along two lines.
#include "impulse2d/render/legend.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace impulse2d::render {

namespace {

enum class Swatch { Square, Arrow, Gauge };

/// One entry: a swatch of the colour, then its words. An arrow's `length` is in pixels (0: the
/// swatch's usual size).
struct Entry {
  Swatch swatch = Swatch::Square;
  Color colour;
  std::string words;
  double length = 0.0;
};

double swatchWidth(const Entry& entry, double textScale) {
  return entry.length > 0.0 ? entry.length : 4.0 * textScale;
}

double entryWidth(const Entry& entry, double textScale) {
  return swatchWidth(entry, textScale) + textScale * 2.0 + textWidth(entry.words, textScale) +
         textScale * 5.0;
}

void drawSwatch(Canvas& canvas, const Entry& entry, const Vec2& corner, double textScale,
                const RenderSettings& settings) {
  const double width = swatchWidth(entry, textScale);
  const double height = textHeight(textScale);
  const Vec2 middle = corner + Vec2(0.0, 0.5 * height);
  switch (entry.swatch) {
    case Swatch::Square:
      fillConvexPolygon(canvas,
                        {corner, corner + Vec2(width, 0.0), corner + Vec2(width, height),
                         corner + Vec2(0.0, height)},
                        entry.colour, settings.colours.outline, settings.outlineWidth);
      break;
    case Swatch::Arrow:
      drawArrow(canvas, middle, middle + Vec2(width, 0.0), settings.arrowWidth,
                settings.arrowHeadLength, settings.arrowHeadWidth, entry.colour);
      break;
    case Swatch::Gauge: {
      const Vec2 top = middle - Vec2(0.0, 0.25 * height);
      fillConvexPolygon(canvas,
                        {top, top + Vec2(width, 0.0), top + Vec2(width, 0.5 * height),
                         top + Vec2(0.0, 0.5 * height)},
                        settings.colours.gaugeBackground, settings.colours.outline,
                        settings.outlineWidth);
      fillRectangle(canvas, top, Vec2(0.6 * width, 0.5 * height), entry.colour);
      break;
    }
  }
}

/// One line of entries from `top`, drawn smaller when it is wider than the canvas.
void drawEntries(Canvas& canvas, const std::vector<Entry>& entries, double top,
                 const RenderSettings& settings) {
  double scale = frameTextScale(settings, canvas.width());
  double width = 0.0;
  for (const Entry& entry : entries) width += entryWidth(entry, scale);
  const double room = canvas.width() - 2.0 * settings.textMargin;
  if (width > room) scale *= room / width;
  Vec2 corner(settings.textMargin, top + settings.textMargin);
  for (const Entry& entry : entries) {
    drawSwatch(canvas, entry, corner, scale, settings);
    const Vec2 words = corner + Vec2(swatchWidth(entry, scale) + 2.0 * scale, 0.0);
    drawText(canvas, entry.words, words, scale, settings.colours.text);
    corner.x() += entryWidth(entry, scale);
  }
}

std::vector<Entry> stateEntries(const DrawnKinds& drawn, const Palette& colours) {
  std::vector<Entry> entries;
  for (int k = 0; k < kBodyStateCount; ++k) {
    if (!drawn.states[std::size_t(k)]) continue;
    const BodyState state = BodyState(k);
    entries.push_back({Swatch::Square, colourOf(state, colours), nameOf(state), 0.0});
  }
  return entries;
}

/// The sample arrow: a round force near the run's resting force, drawn to the run's scale.
Entry scaleEntry(const ForceScale& forces, const Camera& camera, const RenderSettings& settings) {
  const double pixelsPerNewton = forces.metresPerNewton * camera.scale;
  const double force = roundForce(settings.restingForceLength * camera.height / pixelsPerNewton);
  char words[64];
  std::snprintf(words, sizeof words, "= %g N", force);
  return {Swatch::Arrow, settings.colours.normalImpulse, words, force * pixelsPerNewton};
}

std::vector<Entry> arrowEntries(const DrawnKinds& drawn, const ForceScale& forces,
                                const Camera& camera, const RenderSettings& settings) {
  const Palette& colours = settings.colours;
  std::vector<Entry> entries;
  if (drawn.normalForces) entries.push_back({Swatch::Arrow, colours.normalImpulse, "normal", 0.0});
  if (drawn.staticFriction) {
    entries.push_back({Swatch::Arrow, colours.staticFriction, "static fr.", 0.0});
  }
  if (drawn.dynamicFriction) {
    entries.push_back({Swatch::Arrow, colours.dynamicFriction, "dynamic fr.", 0.0});
  }
  if (drawn.velocities) entries.push_back({Swatch::Arrow, colours.velocity, "velocity", 0.0});
  if (drawn.gauges) {
    entries.push_back({Swatch::Gauge, colours.staticFriction, "|ft|/(mu fn)", 0.0});
  }
  if (drawn.normalForces || drawn.staticFriction || drawn.dynamicFriction) {
    entries.push_back(scaleEntry(forces, camera, settings));
  }
  return entries;
}

}  // namespace

int legendHeight(const RenderSettings& settings, int frameWidth) {
  return int(std::ceil(2.0 * headsUpHeight(settings, frameWidth)));
}

double roundForce(double force) {
  if (!(force > 0.0) || !std::isfinite(force)) return 1.0;
  const double decade = std::pow(10.0, std::floor(std::log10(force)));
  double nearest = decade;
  for (const double step : {2.0, 5.0, 10.0}) {
    if (std::abs(std::log(step * decade / force)) < std::abs(std::log(nearest / force))) {
      nearest = step * decade;
    }
  }
  return nearest;
}

void drawLegend(Canvas& canvas, int top, const DrawnKinds& drawn, const ForceScale& forces,
                const Camera& camera, const RenderSettings& settings) {
  fillRectangle(canvas, Vec2(0.0, top), Vec2(canvas.width(), canvas.height() - top),
                settings.colours.legendBackground);
  drawEntries(canvas, stateEntries(drawn, settings.colours), top, settings);
  const double second = top + headsUpHeight(settings, canvas.width());
  std::vector<Entry> arrows = arrowEntries(drawn, forces, camera, settings);
  if (arrows.empty())
    arrows.push_back({Swatch::Square, settings.colours.legendBackground, "no contact forces", 0.0});
  drawEntries(canvas, arrows, second, settings);
}

}  // namespace impulse2d::render
