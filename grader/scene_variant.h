// A graded render's scene as no submission can know it in advance: the camera moved and turned a
// little, the free objects moved and the lights' colours changed, by amounts drawn for each
// submission. The reference is
// rendered from the same variant at grading time, so an image made beforehand matches neither.
#pragma once

#include <cstdint>
#include <string>

namespace pt::grader {

/// What a variant changed, for the grader's own log.
struct SceneVariant {
  std::string description;
};

/// Writes `scene` (a COLLADA file) to `out` with its camera moved by about 3% of its distance
/// from the origin and turned by up to 2 degrees, every object that has room around it (not an
/// emitter) moved by up to 2% of the scene's size without leaving the room, and every light's
/// colour scaled by a factor per channel in [0.75, 1.25], all drawn from `key`. Throws with the file's name on a scene it
/// cannot read or a camera it cannot find.
SceneVariant write_scene_variant(const std::string& scene, uint64_t key, const std::string& out);

/// 64 random bits from the system's random device: a submission's variant key.
uint64_t draw_variant_key();

/// The key of one render of a submission: `key` mixed with the render's name.
uint64_t variant_key_for(uint64_t key, const std::string& render);

}  // namespace pt::grader
