#include "render/annotations/axes.hpp"

#include "render/annotations/line_drawing.hpp"
#include "render/annotations/overlay_text.hpp"

namespace amrstream::render {

void drawAxes(Image& image, const AxesLayout& layout, Rgba8 colour) {
  for (const AxisLayout& axis : layout.axes) {
    if (!axis.shown) continue;
    drawLine(image, axis.pixelStart, axis.pixelEnd, layout.lineWidth, colour, LineCap::Round);
    for (const AxisTick& tick : axis.ticks) {
      drawLine(image, tick.pixel, tick.markEnd, layout.lineWidth, colour);
      drawPlacedText(image, tick.label, colour, layout.labelPixelSize);
    }
    drawPlacedText(image, axis.name, colour, layout.labelPixelSize);
  }
}

}  // namespace amrstream::render
