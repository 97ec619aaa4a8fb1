// Not needed for the assignment: the one door through which a render may make light samples and
// shadow rays faster than their definitions (SampledLights::make_sample, make_shadow_ray): an
// interface the framework declares and a render installs on the thread that estimates a camera
// sample.
#pragma once

#include <glm/vec2.hpp>

namespace pt {

struct LightSample;
struct Ray;
struct SurfaceHit;
class SampledLights;

/// A faster way to answer LightSet::sample and spawn_shadow_ray. Whatever is installed must give
/// every call the definition's answer to the bit (its tests hold it to that), so an estimate
/// cannot tell whether one is installed. With none installed (a student's build, every test of
/// the parts) the definitions answer.
class FasterLightSampling {
 public:
  /// set.make_sample(index, hit, u).
  virtual LightSample sample(const SampledLights& set, int index, const SurfaceHit& hit,
                             glm::vec2 u) = 0;
  /// make_shadow_ray(hit, ls).
  virtual Ray shadow_ray(const SurfaceHit& hit, const LightSample& ls) = 0;

  /// The calling thread's, or null.
  static FasterLightSampling* on_this_thread() { return installed_; }

  /// Installs `faster` on the calling thread while it lives (the one before comes back after).
  class Installed {
   public:
    explicit Installed(FasterLightSampling& faster) : before_(installed_) { installed_ = &faster; }
    ~Installed() { installed_ = before_; }
    Installed(const Installed&) = delete;
    Installed& operator=(const Installed&) = delete;

   private:
    FasterLightSampling* before_;
  };

 protected:
  ~FasterLightSampling() = default;

 private:
  static inline thread_local FasterLightSampling* installed_ = nullptr;
};

}  // namespace pt
