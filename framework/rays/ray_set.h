// Not needed for the assignment.
// Ray sets on disk (PTRAYS01) and their answers (PTHITS01), so two ray tracers can be timed
// on the very same rays. The format is the shared docs' rays-format.md.
#pragma once

#include <string>
#include <vector>

#include "framework/math/ray.h"

namespace pt {

/// Reads a PTRAYS01 file. Throws std::runtime_error naming the file and what is wrong: missing,
/// wrong magic, a count the file's size does not hold, a ray with a non-finite origin or
/// direction, or tmin/tmax that are NaN.
std::vector<Ray> read_ray_set(const std::string& path);

/// Writes rays as PTRAYS01. Throws std::runtime_error naming the file if it cannot be written.
void write_ray_set(const std::string& path, const std::vector<Ray>& rays);

/// Reads a PTHITS01 file: per ray the nearest distance (+inf for a miss), or for an occlusion set
/// 1 (occluded) and 0 (free). Throws std::runtime_error as read_ray_set does.
std::vector<float> read_hit_set(const std::string& path);

/// Writes answers as PTHITS01.
void write_hit_set(const std::string& path, const std::vector<float>& hits);

}  // namespace pt
