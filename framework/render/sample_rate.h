// Not needed for the assignment.
// The sample-rate image of an adaptive render: how many samples each pixel took, as colour.
#pragma once

#include "framework/image/image.h"
#include "framework/render/film.h"

namespace pt {

/// Maps the samples each pixel took, n (PixelStats::samples_taken: adaptive sampling's decision
/// samples included), to a colour from blue (n = 0) through green to red
/// (n = max_samples), as the course's write-up shows it. The PNG is sRGB-encoded on writing,
/// so the map's colours are given in linear values that encode to the intended ones.
Image sample_rate_image(const Film& film, int max_samples);

/// The colour of rate r in [0, 1] (clamped), linear RGB.
glm::vec3 sample_rate_colour(float r);

}  // namespace pt
