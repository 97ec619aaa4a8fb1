#include "framework/lights/light_sampler.h"

#include <algorithm>

namespace pt {

LightSample LightSampler::sample_anew(int index, const SurfaceHit& hit, glm::vec2 u) const {
  // The batch before is done: its counts are settled here, off the path of the calls it answered.
  const int answered = before_ + next_;
  answered_ahead_ += std::max(0, next_ - 1);
  if (next_ < count_) {
    // Foreseen samples the estimate did not ask for: it draws its numbers some other way, and
    // making more would only cost time. The rest of this camera sample is sampled call by call.
    made_in_vain_ += count_ - next_;
    foresee_ = false;
  }
  before_ = index == light_ && same_bits(hit.p, p_) ? answered : 0;
  light_ = index;
  p_ = hit.p;
  const int want = std::min(kBatch, light_samples_ - before_);
  if (!foresee_ || want < 2 || !set_.samples_in_batches(index)) {
    count_ = next_ = 0;
    ++before_;
    return set_.sample(index, hit, u);
  }
  u_[0] = u;
  Rng ahead = *rng_;
  for (int j = 1; j < want; ++j) u_[j] = ahead.next_2d();
  set_.sample_batch(index, hit.p, u_, want, batch_.at, &hit);
  count_ = want;
  next_ = 1;
  return copy_of(batch_.at[0]);
}

}  // namespace pt
