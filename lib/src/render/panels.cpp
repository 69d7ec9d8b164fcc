// Composing frames side by side.
#include "impulse2d/render/panels.h"

#include <algorithm>
#include <cmath>

namespace impulse2d::render {

int panelLabelHeight(const RenderSettings& settings) {
  return int(std::ceil(textHeight(settings.textScale) + 2.0 * settings.textMargin));
}

Canvas composePanels(const std::vector<Panel>& panels, const RenderSettings& settings) {
  const int labelHeight = panelLabelHeight(settings);
  int width = settings.spacing;
  int height = 0;
  for (const Panel& panel : panels) {
    width += panel.frame->width() + settings.spacing;
    height = std::max(height, panel.frame->height());
  }
  Canvas image(width, height + labelHeight + 2 * settings.spacing,
               settings.colours.sheetBackground);
  int x = settings.spacing;
  for (const Panel& panel : panels) {
    const Vec2 labelCorner(x, settings.spacing);
    fillRectangle(image, labelCorner, Vec2(panel.frame->width(), labelHeight),
                  settings.colours.sheetLabel);
    drawText(image, panel.label, labelCorner + Vec2(settings.textMargin, settings.textMargin),
             settings.textScale, settings.colours.text);
    blit(image, *panel.frame, x, settings.spacing + labelHeight);
    x += panel.frame->width() + settings.spacing;
  }
  return image;
}

}  // namespace impulse2d::render
