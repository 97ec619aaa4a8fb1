// Part 5's functions in a judge: each returns what the probe's record says the student's
// function returned for this call (record.h), so the test decides on the student's answers.
// The loop's callbacks (the test's samples and stopping rule) run here, on the arguments the
// student's loop passed them, and must answer what they answered in the probe.
#include "grader/judge/replay.h"
#include "parts/5-adaptive/adaptive_sampling.h"

namespace pt {
using judge::Cursor;
using judge::Fn;
using judge::JudgeCall;

bool pixel_converged(const IlluminanceStats&, long, float) {
  const Fn fn = Fn::pixel_converged;
  JudgeCall call(fn);
  Cursor& out = call.finish();
  bool done = judge::get_bool(fn, out);
  judge::all_read(fn, out);
  return done;
}

int sample_pixel_adaptive(const AdaptiveSettings&, const PixelSampleFn& next_sample,
                          PixelStats* estimate, const ConvergenceRule& converged) {
  const Fn fn = Fn::sample_pixel_adaptive;
  JudgeCall call(fn);
  Cursor& out = call.finish([&](int which, Cursor& args) {
    if (which == 0) {
      glm::vec3 v = next_sample();
      Cursor answer = call.callback_answer();
      judge::expect_same_answer(fn, answer, v);
      return answer;
    }
    if (which != 1) throw judge::RecordError("sample_pixel_adaptive has two callbacks");
    IlluminanceStats decision = args.get<IlluminanceStats>();
    long count = args.get<long>();
    float tolerance = args.get<float>();
    uint8_t done = converged(decision, count, tolerance) ? 1 : 0;
    Cursor answer = call.callback_answer();
    judge::expect_same_answer(fn, answer, done);
    return answer;
  });
  int taken = out.get<int>();
  if (judge::same_presence(fn, out, estimate)) *estimate = out.get<PixelStats>();
  judge::all_read(fn, out);
  return taken;
}

}  // namespace pt
