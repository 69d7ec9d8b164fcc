// Composing frames in a grid.
#include "impulse2d/render/panels.h"

#include <algorithm>
#include <cmath>

namespace impulse2d::render {

int panelLabelHeight(const RenderSettings& settings, double textSize) {
  return int(std::ceil(lineHeight(textSize) + 2.0 * settings.textMargin * textSize));
}

int panelColumns(int count, int width, int height, const RenderSettings& settings) {
  // The grid whose panels cover the most of a slide when the grid is scaled to fit it.
  int best = 1;
  double bestCover = 0.0;
  for (int columns = 1; columns <= count; ++columns) {
    const int rows = (count + columns - 1) / columns;
    const double gridWidth = columns * (width + settings.spacing) + settings.spacing;
    const double gridHeight = rows * (height + settings.spacing) + settings.spacing;
    const double scale = std::min(settings.slideAspect / gridWidth, 1.0 / gridHeight);
    const double cover = count * double(width) * height * scale * scale;
    if (cover > bestCover) {
      best = columns;
      bestCover = cover;
    }
  }
  return best;
}

Frame composePanels(const std::vector<Panel>& panels, const RenderSettings& settings) {
  const Picture& first = panels.front().frame->picture;
  const double size =
      std::max(settings.minimumTextSize, settings.textPerFrameHeight * first.height());
  const int label = panelLabelHeight(settings, size);
  const int cellWidth = first.width();
  const int cellHeight = first.height() + label;
  const int count = int(panels.size());
  const int columns = panelColumns(count, cellWidth, cellHeight, settings);
  const int rows = (count + columns - 1) / columns;
  const int gap = settings.spacing;
  Picture image(columns * (cellWidth + gap) + gap, rows * (cellHeight + gap) + gap);
  Drawing drawing(image);
  drawing.rectangle(Vec2::Zero(), Vec2(image.width(), image.height()),
                    settings.colours.sheetBackground);
  for (int k = 0; k < count; ++k) {
    const Vec2 corner(gap + (k % columns) * (cellWidth + gap),
                      gap + (k / columns) * (cellHeight + gap));
    drawing.setRole("panel label");
    drawing.rectangle(corner, Vec2(cellWidth, label), settings.colours.sheetLabel);
    drawing.text(panels[std::size_t(k)].label,
                 corner + Vec2(settings.textMargin * size, settings.textMargin * size), size,
                 settings.colours.text);
    drawing.place(panels[std::size_t(k)].frame->picture, corner + Vec2(0.0, label));
  }
  Frame composed;
  composed.picture = image;
  composed.sceneSize = Vec2(image.width(), image.height());
  composed.caption = panels.front().frame->caption;
  // The scene's name, without the first panel's solver.
  const std::string& title = panels.front().frame->title;
  composed.title = title.substr(0, title.find("  ·  "));
  for (const Panel& panel : panels) {
    composed.panels.push_back(*panel.frame);
    composed.panelLabels.push_back(panel.label);
    addKinds(composed.drawn, panel.frame->drawn);
  }
  return composed;
}

}  // namespace impulse2d::render
