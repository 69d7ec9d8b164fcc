// The legend strip: swatches and words, flowed over two lines.
#include "impulse2d/render/legend.h"

#include <cmath>
#include <cstdio>

namespace impulse2d::render {

namespace {

enum class Swatch { Square, Arrow, LimitMark, Gauge, Ring };

/// One entry: a swatch of the colour, then its words. An arrow's `length` is in pixels (0: the
/// swatch's usual size): the scale bar's is its force at the run's scale.
struct Entry {
  Swatch swatch = Swatch::Square;
  Color colour;
  std::string words;
  double length = 0.0;
};

double swatchWidth(const Entry& entry, double size) {
  return entry.length > 0.0 ? entry.length : 1.6 * size;
}

double entryWidth(Drawing& drawing, const Entry& entry, double size) {
  return swatchWidth(entry, size) + 0.4 * size + drawing.textWidth(entry.words, size) + 1.2 * size;
}

void drawSwatch(Drawing& drawing, const Entry& entry, const Vec2& corner, double size,
                const RenderSettings& settings) {
  const double width = swatchWidth(entry, size);
  const double height = 0.8 * size;
  const Vec2 top = corner + Vec2(0.0, 0.2 * size);
  const Vec2 middle = top + Vec2(0.0, 0.5 * height);
  const Color outline = settings.colours.outline;
  switch (entry.swatch) {
    case Swatch::Square:
      drawing.polygon(
          {top, top + Vec2(width, 0.0), top + Vec2(width, height), top + Vec2(0.0, height)},
          entry.colour, outline, settings.swatchOutlineWidth);
      break;
    case Swatch::Arrow:
    case Swatch::LimitMark:
      drawing.arrow(middle, middle + Vec2(width, 0.0), settings.arrowWidth * size,
                    settings.arrowHeadLength * size, settings.arrowHeadWidth * size, entry.colour);
      if (entry.swatch == Swatch::LimitMark) {
        const Vec2 mark = middle + Vec2(0.7 * width, 0.0);
        const double half = 0.5 * settings.limitMarkLength * size;
        drawing.line(mark - Vec2(0.0, half), mark + Vec2(0.0, half),
                     0.5 * settings.arrowWidth * size, settings.colours.frictionLimit);
      }
      break;
    case Swatch::Gauge: {
      const Vec2 bar = middle - Vec2(0.0, 0.25 * height);
      drawing.polygon({bar, bar + Vec2(width, 0.0), bar + Vec2(width, 0.5 * height),
                       bar + Vec2(0.0, 0.5 * height)},
                      settings.colours.gaugeBackground, outline, settings.swatchOutlineWidth);
      drawing.rectangle(bar, Vec2(0.6 * width, 0.5 * height), entry.colour);
      break;
    }
    case Swatch::Ring:
      drawing.ring(middle + Vec2(0.5 * width, 0.0), 0.4 * height, entry.colour,
                   settings.highlightWidth);
      break;
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

/// The scale bar: a round force near the run's resting force, drawn to the run's scale.
Entry scaleEntry(const ForceScale& forces, const Camera& camera, const RenderSettings& settings) {
  const double pixelsPerNewton = forces.metresPerNewton * camera.scale;
  const double force = roundForce(settings.restingForceLength * camera.height / pixelsPerNewton);
  char words[64];
  std::snprintf(words, sizeof words, "%g N (force scale)", force);
  return {Swatch::Arrow, settings.colours.outline, words, force * pixelsPerNewton};
}

std::vector<Entry> arrowEntries(const DrawnKinds& drawn, const ForceScale& forces,
                                const Camera& camera, const RenderSettings& settings) {
  const Palette& colours = settings.colours;
  std::vector<Entry> entries;
  const auto add = [&](bool shown, Swatch swatch, Color colour, const char* words) {
    if (shown) entries.push_back({swatch, colour, words, 0.0});
  };
  add(drawn.loads, Swatch::Arrow, colours.load, "applied load F");
  add(drawn.weights, Swatch::Arrow, colours.load, "weight m g");
  add(drawn.normalForces, Swatch::Arrow, colours.normalForce, "normal force λ_n/Δt");
  add(drawn.staticFriction, Swatch::Arrow, colours.staticFriction, "static friction");
  add(drawn.dynamicFriction, Swatch::Arrow, colours.dynamicFriction, "dynamic friction");
  add(drawn.frictionLimits, Swatch::LimitMark, colours.staticFriction, "limit μN");
  add(drawn.gauges, Swatch::Gauge, colours.staticFriction, "|λ_t| / μλ_n");
  add(drawn.slidingVelocities, Swatch::Arrow, colours.velocity, "slip velocity");
  add(drawn.velocities, Swatch::Arrow, colours.velocity, "velocity");
  add(drawn.velocityChange, Swatch::Arrow, colours.highlight, "point velocity before → after");
  add(drawn.highlight, Swatch::Ring, colours.highlight, "contact resolved, its impulse λ/Δt");
  if (drawn.loads || drawn.weights || drawn.normalForces || drawn.staticFriction ||
      drawn.dynamicFriction) {
    entries.push_back(scaleEntry(forces, camera, settings));
  }
  return entries;
}

std::vector<Entry> allEntries(const DrawnKinds& drawn, const ForceScale& forces,
                              const Camera& camera, const RenderSettings& settings) {
  std::vector<Entry> entries = stateEntries(drawn, settings.colours);
  for (const Entry& entry : arrowEntries(drawn, forces, camera, settings)) entries.push_back(entry);
  return entries;
}

/// The line each entry goes on when flowed over lines `room` wide at text `size`; the number of
/// lines needed is the last one plus one.
std::vector<int> flow(Drawing& drawing, const std::vector<Entry>& entries, double size,
                      double room) {
  std::vector<int> lines;
  int line = 0;
  double x = 0.0;
  for (const Entry& entry : entries) {
    const double width = entryWidth(drawing, entry, size);
    if (x > 0.0 && x + width > room) {
      ++line;
      x = 0.0;
    }
    lines.push_back(line);
    x += width;
  }
  return lines;
}

}  // namespace

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

std::vector<std::string> legendWords(const DrawnKinds& drawn, const ForceScale& forces,
                                     const Camera& camera, const RenderSettings& settings) {
  std::vector<std::string> words;
  for (const Entry& entry : allEntries(drawn, forces, camera, settings))
    words.push_back(entry.words);
  return words;
}

void drawLegend(Drawing& drawing, double top, int width, int bottom, const DrawnKinds& drawn,
                const ForceScale& forces, const Camera& camera, const RenderSettings& settings) {
  drawing.setRole("legend");
  drawing.rectangle(Vec2(0.0, top), Vec2(width, bottom - top), settings.colours.stripBackground);
  std::vector<Entry> entries = allEntries(drawn, forces, camera, settings);
  if (entries.empty()) return;
  double size = camera.textSize;
  const double margin = settings.textMargin * size;
  const double room = width - 2.0 * margin;
  std::vector<int> lines = flow(drawing, entries, size, room);
  while (lines.back() > 1 && size > settings.minimumTextSize) {
    size = std::max(settings.minimumTextSize, 0.9 * size);
    lines = flow(drawing, entries, size, room);
  }
  Vec2 corner(margin, top + margin);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (lines[i] > 1) break;  // no room even at the smallest text: the rest is left out
    if (i > 0 && lines[i] != lines[i - 1])
      corner = Vec2(margin, corner.y() + lineHeight(camera.textSize) + margin);
    drawSwatch(drawing, entries[i], corner, size, settings);
    drawing.text(entries[i].words, corner + Vec2(swatchWidth(entries[i], size) + 0.4 * size, 0.0),
                 size, settings.colours.text);
    corner.x() += entryWidth(drawing, entries[i], size);
  }
}

}  // namespace impulse2d::render
