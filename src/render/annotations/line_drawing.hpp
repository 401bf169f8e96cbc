#pragma once
// Straight lines blended over an image: anti-aliased, of any width, clipped to the image.
// Positions are in pixels from the image's top-left corner with pixel centres at half-integers,
// as projectToImage gives them.

#include <glm/vec2.hpp>

#include "render/image/image.hpp"

namespace amrstream::render {

enum class LineCap {
  Butt,   // the line ends at its end points
  Round,  // a half-disc beyond each end point, so that lines meeting there join cleanly
};

// Blends `colour`, its alpha times each pixel's coverage, over the pixels that the line of
// `width` pixels centred on from..to covers. Coverage falls from 1 to 0 over the pixel across
// the line's outline. Draws nothing for a width that is not positive or ends that are not
// finite; a butt line of zero length is nothing, a round one a dot.
void drawLine(Image& image, glm::vec2 from, glm::vec2 to, float width, Rgba8 colour,
              LineCap cap = LineCap::Butt);

}  // namespace amrstream::render
