// Not needed for the assignment: the definitions of framework/image/estimate_exr.h.
#include "framework/image/estimate_exr.h"

#include "framework/image/image.h"

namespace pt {
namespace {

const char* const kChannels[] = {"R", "G", "B", "varR", "varG", "varB", "n"};

}  // namespace

ChannelImage estimate_channels(int width, int height) {
  return ChannelImage(width, height,
                      std::vector<std::string>(std::begin(kChannels), std::end(kChannels)));
}

void write_estimate_exr(const std::string& path, const RenderEstimate& estimate) {
  const size_t pixels = size_t(estimate.width) * size_t(estimate.height);
  if (estimate.mean.size() != pixels || estimate.variance.size() != pixels ||
      estimate.count.size() != pixels)
    throw ImageError(path, "the estimate's arrays do not match its size " +
                               std::to_string(estimate.width) + "x" +
                               std::to_string(estimate.height));
  ChannelImage image = estimate_channels(estimate.width, estimate.height);
  for (size_t i = 0; i < pixels; ++i) {
    float* v = &image.values[i * 7];
    for (int c = 0; c < 3; ++c) {
      v[c] = estimate.mean[i][c];
      v[3 + c] = estimate.variance[i][c];
    }
    v[6] = estimate.count[i];
  }
  write_exr(path, image);
}

RenderEstimate read_estimate_exr(const std::string& path) {
  ChannelImage image = read_channels(path);
  int index[7];
  for (int k = 0; k < 7; ++k) {
    index[k] = image.channel_index(kChannels[k]);
    if (index[k] < 0)
      throw ImageError(path, std::string("no channel '") + kChannels[k] +
                                 "': a render estimate needs R, G, B, varR, varG, varB and n");
  }
  RenderEstimate estimate;
  estimate.width = image.width;
  estimate.height = image.height;
  const size_t pixels = size_t(image.width) * size_t(image.height);
  estimate.mean.resize(pixels);
  estimate.variance.resize(pixels);
  estimate.count.resize(pixels);
  const size_t n = image.channels.size();
  for (size_t i = 0; i < pixels; ++i) {
    const float* v = &image.values[i * n];
    for (int c = 0; c < 3; ++c) {
      estimate.mean[i][c] = v[index[c]];
      estimate.variance[i][c] = v[index[3 + c]];
    }
    estimate.count[i] = v[index[6]];
  }
  return estimate;
}

}  // namespace pt
