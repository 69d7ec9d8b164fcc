// Laying out and drawing contact sheets.
#include "impulse2d/render/contact_sheet.h"

#include <algorithm>
#include <cmath>

#include "impulse2d/render/legend.h"

namespace impulse2d::render {

namespace {

/// Pixels of a strip of `lines` lines of text of `size`, with margins.
int stripHeight(double lines, double size, const RenderSettings& settings) {
  return int(std::ceil(lines * lineHeight(size) + (lines + 1.0) * settings.textMargin * size));
}

/// The number of cells per row whose sheet, scaled to fit a slide, covers the most of it.
int slideColumns(int count, int cellWidth, int cellHeight, int extraHeight,
                 const RenderSettings& settings) {
  int best = 1;
  double bestCover = 0.0;
  for (int columns = 1; columns <= count; ++columns) {
    const int rows = (count + columns - 1) / columns;
    const double width = columns * (cellWidth + settings.spacing) + settings.spacing;
    const double height = extraHeight + rows * (cellHeight + settings.spacing) + settings.spacing;
    const double scale = std::min(settings.slideAspect / width, 1.0 / height);
    const double cover = count * double(cellWidth) * cellHeight * scale * scale;
    if (cover > bestCover * (1.0 + 1e-9)) {
      best = columns;
      bestCover = cover;
    }
  }
  return best;
}

/// The camera of a scene drawn `width` pixels wide at the sheet's text size.
Camera cellCamera(const Frame& frame, int width, const RenderSettings& settings) {
  return frame.camera.resized(double(width) / frame.camera.width, settings.sheetTextSize);
}

/// One scene in its place: drawn again at the cell's size, or else its picture shrunk.
DrawnKinds drawCellScene(Drawing& drawing, const Frame& frame, const Vec2& corner,
                         const SheetLayout& layout, const RenderSettings& settings) {
  const Vec2 size(layout.thumbnailWidth, layout.thumbnailHeight);
  if (!frame.redraw) {
    drawing.placePart(frame.picture, frame.sceneCorner, frame.sceneSize, corner,
                      layout.thumbnailWidth / frame.sceneSize.x());
    return frame.drawn;
  }
  DrawnKinds drawn;
  const Camera camera = cellCamera(frame, layout.thumbnailWidth, settings);
  drawing.inside(corner, size, [&](Drawing& cell) { drawn = frame.redraw(cell, camera); });
  return drawn;
}

/// A text bar: its background, its text at the sheet's size.
void drawBar(Drawing& drawing, const Vec2& corner, const Vec2& size, const std::string& text,
             const RenderSettings& settings) {
  const double textSize = settings.sheetTextSize;
  drawing.rectangle(corner, size, settings.colours.sheetLabel);
  drawing.text(text, corner + Vec2::Constant(settings.textMargin * textSize), textSize,
               settings.colours.text);
}

/// Cell k: each panel (or the frame itself) under its label, the caption under them all.
DrawnKinds drawCell(Drawing& drawing, const SheetLayout& layout, int k, const Frame& frame,
                    const RenderSettings& settings) {
  DrawnKinds drawn;
  const Vec2 corner(layout.thumbnailX(k), layout.thumbnailY(k));
  const bool comparison = !frame.panels.empty();
  for (int p = 0; p < layout.panels; ++p) {
    const Vec2 at = corner + Vec2(p * (layout.thumbnailWidth + layout.spacing), 0.0);
    if (comparison && std::size_t(p) < frame.panels.size()) {
      drawing.setRole("panel label");
      drawBar(drawing, at - Vec2(0.0, layout.panelLabelHeight),
              Vec2(layout.thumbnailWidth, layout.panelLabelHeight),
              frame.panelLabels[std::size_t(p)], settings);
      addKinds(drawn, drawCellScene(drawing, frame.panels[std::size_t(p)], at, layout, settings));
    } else if (!comparison) {
      addKinds(drawn, drawCellScene(drawing, frame, at, layout, settings));
    }
  }
  drawing.setRole("caption");
  drawBar(drawing, corner + Vec2(0.0, layout.thumbnailHeight),
          Vec2(layout.cellWidth(), layout.labelHeight), frame.caption, settings);
  // A rim round the cell: on the print theme's white page the cells would run together.
  const Vec2 top = corner - Vec2(0.0, layout.panelLabelHeight);
  const Vec2 size(layout.cellWidth(), layout.cellHeight());
  drawing.setRole("cell rim");
  drawing.outline({top, top + Vec2(size.x(), 0.0), top + size, top + Vec2(0.0, size.y())},
                  settings.colours.outline, settings.swatchOutlineWidth);
  return drawn;
}

}  // namespace

std::vector<int> evenlySpaced(int frameCount, int count) {
  const int shown = std::min(frameCount, count);
  std::vector<int> indices;
  if (shown <= 0) return indices;
  if (shown == 1) return {0};
  if (frameCount > count) {
    // Exactly even when some count not far under the one asked for splits the frames.
    for (int n = count; n >= std::max(2, count / 2 + 1); --n) {
      if ((frameCount - 1) % (n - 1) != 0) continue;
      for (int k = 0; k < n; ++k) indices.push_back(k * ((frameCount - 1) / (n - 1)));
      return indices;
    }
  }
  for (int k = 0; k < shown; ++k) {
    indices.push_back(int(std::lround(double(k) * (frameCount - 1) / (shown - 1))));
  }
  return indices;
}

std::vector<int> chooseFrames(const std::vector<bool>& preferred, int count) {
  std::vector<int> first;
  std::vector<int> others;
  for (int i = 0; i < int(preferred.size()); ++i) (preferred[i] ? first : others).push_back(i);
  std::vector<int> chosen;
  for (const int k : evenlySpaced(int(first.size()), count)) chosen.push_back(first[k]);
  for (const int k : evenlySpaced(int(others.size()), count - int(chosen.size()))) {
    chosen.push_back(others[k]);
  }
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

int sheetFrameCount(int panels, const RenderSettings& settings) {
  return std::max(2, settings.sheetThumbnails / std::max(1, panels));
}

SheetLayout contactSheetLayout(const std::vector<int>& shown, int sceneWidth, int sceneHeight,
                               const RenderSettings& settings, int panels) {
  SheetLayout layout;
  layout.frames = shown;
  layout.panels = std::max(1, panels);
  const int count = std::max(1, int(shown.size()));
  layout.thumbnailWidth = settings.sheetCellWidth;
  layout.thumbnailHeight = std::max(
      1, int(std::lround(double(layout.thumbnailWidth) * sceneHeight / std::max(1, sceneWidth))));
  const double size = settings.sheetTextSize;
  layout.labelHeight = stripHeight(1.0, size, settings);
  layout.panelLabelHeight = panels > 1 ? layout.labelHeight : 0;
  layout.titleHeight = settings.overlays.headsUp ? stripHeight(1.0, size, settings) : 0;
  layout.legendHeight = settings.overlays.legend ? stripHeight(2.0, size, settings) : 0;
  layout.spacing = settings.spacing;
  layout.columns = slideColumns(count, layout.cellWidth(), layout.cellHeight(),
                                layout.titleHeight + layout.legendHeight, settings);
  layout.rows = (count + layout.columns - 1) / layout.columns;
  layout.width = layout.columns * (layout.cellWidth() + layout.spacing) + layout.spacing;
  layout.height = layout.titleHeight + layout.rows * (layout.cellHeight() + layout.spacing) +
                  layout.spacing + layout.legendHeight;
  return layout;
}

Picture drawContactSheet(const SheetLayout& layout, const std::vector<Frame>& frames,
                         const RenderSettings& settings) {
  Picture sheet(layout.width, layout.height);
  Drawing drawing(sheet);
  drawing.rectangle(Vec2::Zero(), Vec2(layout.width, layout.height),
                    settings.colours.sheetBackground);
  if (layout.frames.empty()) return sheet;
  const Frame& first = frames[std::size_t(layout.frames.front())];
  if (layout.titleHeight > 0) {
    drawing.setRole("heads-up");
    drawBar(drawing, Vec2::Zero(), Vec2(layout.width, layout.titleHeight), first.title, settings);
  }
  DrawnKinds drawn;
  for (std::size_t k = 0; k < layout.frames.size(); ++k) {
    addKinds(drawn,
             drawCell(drawing, layout, int(k), frames[std::size_t(layout.frames[k])], settings));
  }
  if (layout.legendHeight > 0) {
    const Frame& scene = first.panels.empty() ? first : first.panels.front();
    drawLegend(drawing, layout.height - layout.legendHeight, layout.width, layout.height, drawn,
               scene.forces, cellCamera(scene, layout.thumbnailWidth, settings), settings);
  }
  return sheet;
}

}  // namespace impulse2d::render
