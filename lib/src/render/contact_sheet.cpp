// Laying out and drawing contact sheets.
#include "impulse2d/render/contact_sheet.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace impulse2d::render {

std::vector<int> evenlySpaced(int frameCount, int count) {
  const int shown = std::min(frameCount, count);
  std::vector<int> indices;
  if (shown <= 0) return indices;
  if (shown == 1) return {0};
  for (int k = 0; k < shown; ++k) {
    indices.push_back(int(std::lround(double(k) * (frameCount - 1) / (shown - 1))));
  }
  return indices;
}

SheetLayout contactSheetLayout(int frameCount, int frameWidth, int frameHeight,
                               const RenderSettings& settings) {
  SheetLayout layout;
  layout.frames = evenlySpaced(frameCount, settings.sheetThumbnails);
  const int shown = int(layout.frames.size());
  layout.thumbnailWidth = std::max(settings.sheetThumbnailWidth,
                                   int(std::lround(settings.sheetThumbnailScale * frameWidth)));
  const int fitting = int(std::lround(double(settings.sheetColumns) * settings.sheetThumbnailWidth /
                                      layout.thumbnailWidth));
  layout.columns = std::max(1, std::min(fitting, shown));
  layout.rows = (shown + layout.columns - 1) / layout.columns;
  layout.thumbnailHeight =
      std::max(1, int(std::lround(double(layout.thumbnailWidth) * frameHeight / frameWidth)));
  layout.labelHeight = int(std::ceil(textHeight(settings.textScale) + 2.0 * settings.textMargin));
  layout.spacing = settings.spacing;
  layout.width = layout.columns * (layout.thumbnailWidth + layout.spacing) + layout.spacing;
  layout.height =
      layout.rows * (layout.thumbnailHeight + layout.labelHeight + layout.spacing) + layout.spacing;
  return layout;
}

Canvas drawContactSheet(const SheetLayout& layout, const std::vector<Canvas>& thumbnails,
                        const std::vector<long>& steps, const RenderSettings& settings) {
  Canvas sheet(layout.width, layout.height, settings.colours.sheetBackground);
  for (std::size_t k = 0; k < thumbnails.size() && k < steps.size(); ++k) {
    const int x = layout.thumbnailX(int(k));
    const int y = layout.thumbnailY(int(k));
    blit(sheet, resized(thumbnails[k], layout.thumbnailWidth, layout.thumbnailHeight), x, y);
    const Vec2 labelCorner(x, y + layout.thumbnailHeight);
    fillRectangle(sheet, labelCorner, Vec2(layout.thumbnailWidth, layout.labelHeight),
                  settings.colours.sheetLabel);
    drawText(sheet, "step " + std::to_string(steps[k]),
             labelCorner + Vec2(settings.textMargin, settings.textMargin), settings.textScale,
             settings.colours.text);
  }
  return sheet;
}

}  // namespace impulse2d::render
