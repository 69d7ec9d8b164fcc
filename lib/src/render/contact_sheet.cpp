// Laying out and drawing contact sheets.
#include "impulse2d/render/contact_sheet.h"

#include <algorithm>
#include <cmath>

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

SheetLayout contactSheetLayout(const std::vector<int>& shown, int sceneWidth, int sceneHeight,
                               const RenderSettings& settings) {
  SheetLayout layout;
  layout.frames = shown;
  const int count = int(shown.size());
  layout.thumbnailWidth = std::max(settings.sheetThumbnailWidth,
                                   int(std::lround(settings.sheetThumbnailScale * sceneWidth)));
  const int fitting = int(std::lround(double(settings.sheetColumns) * settings.sheetThumbnailWidth /
                                      layout.thumbnailWidth));
  layout.columns = std::max(1, std::min(fitting, count));
  layout.rows = (count + layout.columns - 1) / layout.columns;
  layout.thumbnailHeight =
      std::max(1, int(std::lround(double(layout.thumbnailWidth) * sceneHeight / sceneWidth)));
  const double size = settings.minimumTextSize;
  layout.labelHeight = int(std::ceil(lineHeight(size) + 2.0 * settings.textMargin * size));
  layout.spacing = settings.spacing;
  layout.width = layout.columns * (layout.thumbnailWidth + layout.spacing) + layout.spacing;
  layout.height =
      layout.rows * (layout.thumbnailHeight + layout.labelHeight + layout.spacing) + layout.spacing;
  return layout;
}

Picture drawContactSheet(const SheetLayout& layout, const std::vector<Frame>& frames,
                         const RenderSettings& settings) {
  Picture sheet(layout.width, layout.height);
  Drawing drawing(sheet);
  drawing.rectangle(Vec2::Zero(), Vec2(layout.width, layout.height),
                    settings.colours.sheetBackground);
  const double size = settings.minimumTextSize;
  for (std::size_t k = 0; k < layout.frames.size(); ++k) {
    const Frame& frame = frames[std::size_t(layout.frames[k])];
    const Vec2 corner(layout.thumbnailX(int(k)), layout.thumbnailY(int(k)));
    drawing.placePart(frame.picture, frame.sceneCorner, frame.sceneSize, corner,
                      layout.thumbnailWidth / frame.sceneSize.x());
    const Vec2 label = corner + Vec2(0.0, layout.thumbnailHeight);
    drawing.rectangle(label, Vec2(layout.thumbnailWidth, layout.labelHeight),
                      settings.colours.sheetLabel);
    drawing.text(frame.caption,
                 label + Vec2(settings.textMargin * size, settings.textMargin * size), size,
                 settings.colours.text);
  }
  return sheet;
}

}  // namespace impulse2d::render
