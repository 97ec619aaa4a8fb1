// One camera sample's light samples and shadow rays, made several at a time where the estimate's
// next random numbers are known: the instructor's build's FasterLightSampling.
// SOLUTION-ONLY FILE: not in the student handout, since it is the instructor's build's speed.
#pragma once

#include <cstring>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "framework/geometry/surface_hit.h"
#include "framework/lights/faster_light_sampling.h"
#include "framework/lights/sampled_lights.h"
#include "framework/math/ray.h"
#include "framework/sampling/rng.h"

namespace pt {

/// A way to ask whether several shadow rays are blocked at once: the render's ray query's, which
/// walks rays that leave one point together. occluded(query, rays, offered, &answered) answers
/// at least the first ray of `offered` (bit k for rays[k]), and sets `answered` to the rays it
/// answered; bit k of its answer is RayQuery::occluded(rays[k]) for each of them, to the bit.
struct ShadowRayTracer {
  const void* query = nullptr;
  unsigned (*occluded)(const void* query, const Ray* rays, unsigned offered,
                       unsigned* answered) = nullptr;
};

/// SampledLights::make_sample and make_shadow_ray's answers, bit for bit, for one camera sample. A
/// light sample is one chain of long operations (a square root, divisions waiting on it), and the
/// shadow ray and its walk wait on it in turn, so samples made one call at a time hardly overlap.
/// When an estimate asks for a sample of a panel or mesh light, this therefore also makes the ones
/// it is about to ask for (the same light, the same point, and the numbers the camera sample's Rng
/// will give next, read from a copy of it), side by side: a quad panel's in eight AVX lanes, with
/// each sample's shadow ray. The next calls are answered from them.
///
/// A panel's or mesh's sample is a function of the light, the point and u alone, and a call is
/// answered from the batch only when all three are, to the bit, what its sample was made with;
/// a shadow ray only when the sample and the point asking are, to the bit, those it was made
/// from. Any other call is answered anew (in SSE lanes, lane_rays.h). So every answer is the
/// definition's whatever the estimate draws, and an estimate that draws its numbers otherwise
/// only loses the time of one batch before this stops foreseeing.
class LightBatches final : public FasterLightSampling {
 public:
  /// The most samples made together.
  static constexpr int kBatch = 8;

  /// `rng`: the generator the camera sample's estimate draws from (read, never advanced), or null
  /// to make every sample on its own; `light_samples`: how many samples the estimate takes of
  /// each area light (-l), the most a batch makes for one light and point.
  /// `tracer`: where the batch's shadow rays may be traced together (occluded_answer), or none.
  explicit LightBatches(const Rng* rng = nullptr, int light_samples = 1,
                        ShadowRayTracer tracer = {})
      : rng_(rng),
        light_samples_(light_samples),
        foresee_(rng != nullptr && light_samples > 1),
        tracer_(tracer) {}

  LightSample sample(const SampledLights& set, int index, const SurfaceHit& hit,
                     glm::vec2 u) override {
    if (next_ < count_ && &set == set_ && index == light_ && same_bits(hit.p, p_) &&
        same_bits(u, u_[next_])) {
      last_ = next_;
      return copy_of(batch_.at[next_++]);  // the counts are settled when the batch is done
    }
    last_ = -1;
    if (!foresee_) return set.make_sample(index, hit, u);
    return sample_anew(set, index, hit, u);
  }

  /// The ray made with the sample last answered from the batch, if this is that sample (every
  /// field through n, and delta) asked from the point it was made for; else one made anew. Here,
  /// not in light_batches.cpp, so a link-time optimised build can inline it where it is called.
  Ray shadow_ray(const SurfaceHit& hit, const LightSample& ls) override {
    if (last_ >= 0 && (rays_made_ >> last_ & 1) && same_as_made(hit, ls, batch_.at[last_], from_)) {
      ++rays_handed_out_;
      return rays_.at[last_];
    }
    return shadow_ray_anew(hit, ls);
  }

  /// Whether `ray` is blocked, where it is, to the bit, the shadow ray the batch last handed out:
  /// the first time one of the batch's rays is asked, it and the batch's rays after it that leave
  /// the same point (the samples the estimate is about to trace) are traced as one packet
  /// through the tracer. False when the batch cannot say (the caller traces the ray itself). A
  /// ray's answer is a function of its bits alone, so an answer from the packet is the query's.
  bool occluded_answer(const Ray& ray, bool* occluded) {
    if (!tracer_.occluded || last_ < 0 || !(rays_made_ >> last_ & 1) ||
        std::memcmp(&ray, &rays_.at[last_], sizeof(Ray)) != 0)
      return false;
    if (!(traced_ >> last_ & 1)) trace_packet();
    *occluded = (occluded_ >> last_ & 1) != 0;
    return true;
  }

  /// How many packets of shadow rays were traced, with how many rays in all, and how many of
  /// those rays were then asked for (bench's packet occupancy).
  int packets_traced() const { return packets_; }
  int packet_rays() const { return packet_rays_; }

  /// How many calls were answered from a batch, how many samples were made in one but never asked
  /// for, and how many shadow rays were handed out as made in a batch (tests).
  int answered_ahead() const { return answered_ahead_ + (next_ > 1 ? next_ - 1 : 0); }
  int made_in_vain() const { return made_in_vain_; }
  int rays_handed_out() const { return rays_handed_out_; }

 private:
  static bool same_bits(const glm::vec3& a, const glm::vec3& b) {
    return std::memcmp(&a, &b, sizeof(glm::vec3)) == 0;
  }
  static bool same_bits(glm::vec2 a, glm::vec2 b) { return std::memcmp(&a, &b, sizeof(glm::vec2)) == 0; }
  /// Whether `ls` is, in every field through n and delta, `made`, and `hit`'s p, p_error and ng
  /// are `from`, to the bit.
  static bool same_as_made(const SurfaceHit& hit, const LightSample& ls, const LightSample& made,
                           const float from[9]);
  /// make_shadow_ray's ray for a sample the batch did not make, in SSE lanes (lane_rays.h).
  [[gnu::noinline]] static Ray shadow_ray_anew(const SurfaceHit& hit, const LightSample& ls);
  /// `ls`, copied as the batch writes a sample (light_batches.cpp says why).
  static LightSample copy_of(const LightSample& ls);
  /// A call the batch does not answer: a new batch when foreseeing is on and pays, else one sample.
  /// Never inlined into sample(): its frame (eight-lane locals, saved registers) would be paid by
  /// every call the batch answers.
  /// Traces the batch's ray last_ with its rays after it that leave the same point.
  [[gnu::noinline]] void trace_packet();
  [[gnu::noinline]] LightSample sample_anew(const SampledLights& set, int index,
                                            const SurfaceHit& hit, glm::vec2 u);

  const Rng* rng_;
  int light_samples_;
  bool foresee_;  ///< a generator to read, several samples a light, no misprediction yet
  // The batch: samples of light_ of set_ from p_ for the numbers u_, the next to answer
  // batch_[next_], the last answered batch_[last_] (-1: the last answer was not the batch's).
  const SampledLights* set_ = nullptr;
  int light_ = -1;
  glm::vec3 p_{0.0f};
  int count_ = 0, next_ = 0, last_ = -1;
  int before_ = 0;  ///< samples of light_ from p_ answered before this batch
  int answered_ahead_ = 0, made_in_vain_ = 0, rays_handed_out_ = 0;
  glm::vec2 u_[kBatch];
  /// Which of the batch's samples carry their shadow ray (a bit each), made from the point whose
  /// p, p_error and ng are from_.
  int rays_made_ = 0;
  /// Which of the batch's rays were traced, and which of those found something in the way.
  unsigned traced_ = 0, occluded_ = 0;
  ShadowRayTracer tracer_;
  int packets_ = 0, packet_rays_ = 0;
  float from_[9];
  /// The batch's samples and rays, left unwritten until a batch fills them: one of these is made
  /// for every camera sample, and clearing them each time would cost a render that never batches.
  union Batch {
    Batch() {}
    LightSample at[kBatch];
  };
  union Rays {
    Rays() {}
    Ray at[kBatch];
  };
  Batch batch_;
  Rays rays_;
};

}  // namespace pt
