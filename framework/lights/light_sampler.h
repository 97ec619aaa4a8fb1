// The scene's lights as one camera sample's estimate asks them (ctx.lights): LightSet's answers,
// with an area light's samples made several at a time where the estimate's next random numbers
// are known.
#pragma once

#include <algorithm>
#include <cstring>
#if defined(__AVX__)
#include <immintrin.h>
#endif
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "framework/geometry/ray_query.h"
#include "framework/geometry/surface_hit.h"
#include "framework/lights/light_set.h"
#include "framework/math/ray.h"
#include "framework/sampling/rng.h"

namespace pt {

/// LightSet's questions, answered for one camera sample. A light sample is one chain of long
/// operations (a square root, divisions waiting on it), and the shadow ray and its walk wait on
/// it in turn, so samples made one call at a time hardly overlap. When an estimate asks for a
/// sample of a panel or mesh light, the sampler therefore also makes the ones it is about to ask
/// for (the same light, the same point, and the random numbers the camera sample's Rng will give
/// next, read from a copy of it), side by side, and answers the next calls from them.
///
/// A panel's or mesh's sample is a function of the light, the point and u alone, and a call is
/// answered from the batch only when all three are, to the bit, what its sample was made with;
/// any other call is sampled on the spot. So every answer is LightSet::sample's whatever the
/// estimate draws, and an estimate that draws its numbers otherwise (other draws between samples,
/// a generator of its own) only loses the time of one batch before the sampler stops foreseeing.
class LightSampler {
 public:
  /// The most samples made together.
  static constexpr int kBatch = LightSet::kBatchMost;

  /// `rng`: the generator the estimate draws from (read, never advanced), or null to make every
  /// sample on its own; `light_samples`: how many samples the estimate takes of each area light
  /// (-l), the most a batch makes for one light and point.
  explicit LightSampler(const LightSet& set, const Rng* rng = nullptr, int light_samples = 1)
      : set_(set), rng_(rng), light_samples_(light_samples),
        foresee_(rng != nullptr && light_samples > 1) {}
  // Copyable, as the set was (`auto lights = ctx.lights;` compiles and answers the same): a copy
  // keeps its own batch.

  /// The set itself, for code that takes a LightSet.
  const LightSet& set() const { return set_; }
  operator const LightSet&() const { return set_; }

  const std::vector<SampledLight>& lights() const { return set_.lights(); }
  bool empty() const { return set_.empty(); }
  glm::vec3 environment_radiance(const glm::vec3& dir) const { return set_.environment_radiance(dir); }
  /// LightSet::sample's answer, bit for bit (see above).
  LightSample sample(int index, const SurfaceHit& hit, glm::vec2 u) const {
    if (next_ < count_ && index == light_ && same_bits(hit.p, p_) && same_bits(u, u_[next_]))
      return copy_of(batch_.at[next_++]);  // the counts are settled when the batch is done
    if (!foresee_) return set_.sample(index, hit, u);
    return sample_anew(index, hit, u);
  }
  float pdf(int index, const SurfaceHit& hit, const glm::vec3& wi, const SurfaceHit* on_light) const {
    return set_.pdf(index, hit, wi, on_light);
  }
  int light_of_primitive(uint32_t primitive) const { return set_.light_of_primitive(primitive); }
  glm::vec3 emitted(int index, const SurfaceHit& on_light, const glm::vec3& wi) const {
    return set_.emitted(index, on_light, wi);
  }
  bool unoccluded(const RayQuery& query, const Ray& ray, int index) const {
    return set_.unoccluded(query, ray, index);
  }

  /// How many calls were answered from a batch, and how many samples were made in one but never
  /// asked for (tests; the sampler's own judgement of whether foreseeing pays).
  int answered_ahead() const { return answered_ahead_ + std::max(0, next_ - 1); }
  int made_in_vain() const { return made_in_vain_; }

 private:
  static bool same_bits(const glm::vec3& a, const glm::vec3& b) {
    return std::memcmp(&a, &b, sizeof(glm::vec3)) == 0;
  }
  static bool same_bits(glm::vec2 a, glm::vec2 b) { return std::memcmp(&a, &b, sizeof(glm::vec2)) == 0; }
  /// `ls`, copied as sample_batch writes a sample: in stores of 32 bytes, the only shape whose
  /// every field (and pair of neighbours, as the compiler merges loads) the caller's loads can
  /// take straight from a store; a copy in 16-byte pieces made the shadow ray's spawn, which
  /// reads p_error across such a seam, wait for the copy to reach the cache.
  static LightSample copy_of(const LightSample& ls) {
    LightSample out;
#if defined(__AVX__)
    // With its shadow ray and the copies that ray is checked by: seven stores of 32 bytes.
    static_assert(sizeof(LightSample) == 7 * 8 * sizeof(float), "a sample is seven 32-byte pieces");
    const float* from = reinterpret_cast<const float*>(&ls);
    float* to = reinterpret_cast<float*>(&out);
    for (int k = 0; k < 7; ++k) _mm256_storeu_ps(to + 8 * k, _mm256_loadu_ps(from + 8 * k));
#else
    out = ls;
#endif
    return out;
  }
  /// A call the batch does not answer: a new batch when foreseeing is on and pays, else one sample.
  LightSample sample_anew(int index, const SurfaceHit& hit, glm::vec2 u) const;

  const LightSet& set_;
  const Rng* rng_;
  int light_samples_;
  // The batch: samples of light_ from p_ for the numbers u_, the next to answer batch_[next_].
  mutable int light_ = -1;
  mutable glm::vec3 p_{0.0f};
  mutable int count_ = 0, next_ = 0;  ///< next_: the batch's samples answered (its first at once)
  mutable int before_ = 0;  ///< samples of light_ from p_ answered before this batch
  mutable bool foresee_;  ///< a generator to read, several samples a light, no misprediction yet
  mutable int answered_ahead_ = 0, made_in_vain_ = 0;
  mutable glm::vec2 u_[kBatch];
  /// The batch's samples, left unwritten until a batch fills them: a sampler is made for every
  /// camera sample, and clearing eight samples each time cost a -l 1 render 2% of its instructions.
  union Batch {
    Batch() {}
    LightSample at[kBatch];
  };
  mutable Batch batch_;
};

}  // namespace pt
