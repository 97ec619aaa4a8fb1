// Not needed for the assignment.
// A render as an estimator on disk: mean, per-pixel variance and sample count in one EXR.
#pragma once

#include <string>

#include "framework/image/image.h"
#include "framework/image/render_estimate.h"

namespace pt {

/// Writes `estimate` to an .exr with the channels R, G, B (mean), varR, varG, varB (variance of
/// one sample) and n (samples), all 32-bit float, so a reference keeps what the block t-test
/// needs. Throws ImageError.
void write_estimate_exr(const std::string& path, const RenderEstimate& estimate);

/// An image of the channels write_estimate_exr writes, in its order (R, G, B, varR, varG, varB,
/// n), zero-filled: for a writer that fills it from its own statistics and calls write_exr.
ChannelImage estimate_channels(int width, int height);

/// Reads what write_estimate_exr wrote. Throws ImageError naming the path and the channel that
/// is missing.
RenderEstimate read_estimate_exr(const std::string& path);

}  // namespace pt
