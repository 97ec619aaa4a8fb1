// Part 5's probe: each graded function of Part 5, recorded as the test calls it (record.h).
#include "grader/judge/record.h"
#include "grader/judge/wrap.h"
#include "parts/5-adaptive/adaptive_sampling.h"

#define PIXEL_CONVERGED "_ZN2pt15pixel_convergedERKNS_16IlluminanceStatsElf"
#define SAMPLE_PIXEL_ADAPTIVE "_ZN2pt21sample_pixel_adaptiveERKNS_16AdaptiveSettingsERKSt8functionIFN3glm3vecILi3EfLNS4_9qualifierE0EEEvEEPNS_10PixelStatsERKS3_IFbRKNS_16IlluminanceStatsElfEE"

namespace pt::judge {
namespace real {
bool pixel_converged(const IlluminanceStats&, long, float) PT_REAL(PIXEL_CONVERGED);
int sample_pixel_adaptive(const AdaptiveSettings&, const PixelSampleFn&, PixelStats*, const ConvergenceRule&) PT_REAL(SAMPLE_PIXEL_ADAPTIVE);
}  // namespace real

bool wrap_pixel_converged(const IlluminanceStats&, long, float) PT_WRAP(PIXEL_CONVERGED);
bool wrap_pixel_converged(const IlluminanceStats& decision, long count, float tolerance) {
  ProbeCall call(Fn::pixel_converged);
  bool done = real::pixel_converged(decision, count, tolerance);
  call.out.put(uint8_t(done));
  call.returned();
  return done;
}

int wrap_sample_pixel_adaptive(const AdaptiveSettings&, const PixelSampleFn&, PixelStats*, const ConvergenceRule&) PT_WRAP(SAMPLE_PIXEL_ADAPTIVE);
int wrap_sample_pixel_adaptive(const AdaptiveSettings& settings, const PixelSampleFn& next_sample,
                               PixelStats* estimate, const ConvergenceRule& converged) {
  const Fn fn = Fn::sample_pixel_adaptive;
  ProbeCall call(fn);
  PixelSampleFn sample = [&] {
    ProbeCallback cb(fn, 0);
    cb.begin();
    glm::vec3 v = next_sample();
    cb.answer.put(v);
    cb.end();
    return v;
  };
  ConvergenceRule rule = [&](const IlluminanceStats& decision, long count, float tolerance) {
    ProbeCallback cb(fn, 1);
    cb.args.put(decision);
    cb.args.put(count);
    cb.args.put(tolerance);
    cb.begin();
    bool done = converged(decision, count, tolerance);
    cb.answer.put(uint8_t(done));
    cb.end();
    return done;
  };
  int taken = real::sample_pixel_adaptive(settings, next_sample ? sample : next_sample, estimate,
                                          converged ? rule : converged);
  call.out.put(taken);
  call.out.put(uint8_t(estimate != nullptr));
  if (estimate) call.out.put(*estimate);
  call.returned();
  return taken;
}

}  // namespace pt::judge
