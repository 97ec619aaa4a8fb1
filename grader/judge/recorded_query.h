// The probe's side of an estimator's rays: the graded call gets its context with this query in
// place of the test's, so every ray its code traces (its own, its helpers', the light set's
// shadow rays) is a callback of the call (record.h: kQueryIntersect, kQueryOccluded). The judge
// traces the same ray with its own query and counts it (replay.h, replay_rays).
#pragma once

#include "framework/geometry/ray_query.h"
#include "framework/shading/lighting_context.h"
#include "grader/judge/record.h"

namespace pt::judge {

class RecordedQuery final : public RayQuery {
 public:
  RecordedQuery(const RayQuery& inner, Fn fn) : inner_(inner), fn_(fn) {}

  bool intersect(const Ray& ray, SurfaceHit* hit) const override {
    ProbeCallback traced(fn_, kQueryIntersect, /*any_depth=*/true);
    traced.args.put(ray);
    traced.begin();
    SurfaceHit found;  // the hit as the judge's query fills it: from the defaults
    const bool met = inner_.intersect(ray, &found);
    if (met) *hit = found;
    traced.answer.put(uint8_t(met));
    if (met) traced.answer.put(found);
    traced.end();
    return met;
  }

  bool occluded(const Ray& ray) const override {
    ProbeCallback traced(fn_, kQueryOccluded, /*any_depth=*/true);
    traced.args.put(ray);
    traced.begin();
    const bool blocked = inner_.occluded(ray);
    traced.answer.put(uint8_t(blocked));
    traced.end();
    return blocked;
  }

 private:
  const RayQuery& inner_;
  Fn fn_;
};

/// A graded call's context: the test's, with its query recorded, for a call the test made; a call
/// the student's code makes to its own functions already has the recorded one.
class RecordedContext {
 public:
  RecordedContext(const LightingContext& of, const ProbeCall& call, Fn fn)
      : of_(of), top_(call.top()), query_(of.query, fn), ctx_(of.scene, query_, of.lights, of) {}
  const LightingContext& get() const { return top_ ? ctx_ : of_; }

 private:
  const LightingContext& of_;
  bool top_;
  RecordedQuery query_;
  LightingContext ctx_;
};

}  // namespace pt::judge
