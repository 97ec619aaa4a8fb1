// Not needed for the assignment: the definitions of framework/scene/camera_settings_file.h.
#include "framework/scene/camera_settings_file.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "framework/scene/scene_error.h"

namespace pt {

namespace {

// The fields in the file's order: its element names are these, so an error can say which one.
const char* const kFields[] = {
    "hFov", "vFov", "aspect", "near", "far",
    "position.x", "position.y", "position.z", "target.x", "target.y", "target.z",
    "phi", "theta", "r", "minR", "maxR",
    "c2w[0][0]", "c2w[0][1]", "c2w[0][2]", "c2w[1][0]", "c2w[1][1]", "c2w[1][2]",
    "c2w[2][0]", "c2w[2][1]", "c2w[2][2]",
    "screenW", "screenH", "screenDist",
    "focalDistance", "lensRadius"};
constexpr int kRequired = 28;  // everything up to screenDist; the lens came later
constexpr int kAll = int(sizeof kFields / sizeof kFields[0]);

}  // namespace

Camera read_camera_settings(const std::string& path, const Camera& base) {
  std::ifstream in(path);
  if (!in) throw SceneError(path, "", "cannot open the camera settings file (-c)");
  std::vector<double> v;
  std::string word;
  while (in >> word) {
    if (int(v.size()) == kAll)
      throw SceneError(path, "", "more than the " + std::to_string(kAll) +
                                     " numbers of a camera settings file (found '" + word + "')");
    std::istringstream number(word);
    double x = 0.0;
    char rest = 0;
    if (!(number >> x) || number >> rest || !std::isfinite(x))
      throw SceneError(path, kFields[v.size()], "'" + word + "' is not a finite number");
    v.push_back(x);
  }
  if (int(v.size()) < kRequired)
    throw SceneError(path, kFields[v.size()],
                     "missing: the file ends after " + std::to_string(v.size()) + " numbers, a camera "
                     "settings file has " + std::to_string(kRequired) + " (or " +
                     std::to_string(kAll) + " with its lens)");
  if (int(v.size()) != kRequired && int(v.size()) != kAll)
    throw SceneError(path, kFields[v.size()], "missing: a lens needs both focalDistance and lensRadius");

  Camera c = base;
  if (!(v[0] > 0.0 && v[0] < 180.0))
    throw SceneError(path, "hFov", "the field of view must be between 0 and 180 degrees");
  c.hfov_degrees = float(v[0]);
  if (v[1] > 0.0 && v[1] < 180.0)
    c.aspect = float(std::tan(0.5 * v[0] * M_PI / 180.0) / std::tan(0.5 * v[1] * M_PI / 180.0));
  if (v[3] > 0.0 && v[4] > v[3]) c.znear = float(v[3]), c.zfar = float(v[4]);

  // c2w is written row by row; its columns are the camera's axes in the world.
  const glm::vec3 position(v[5], v[6], v[7]);
  glm::vec3 axis[3];
  for (int col = 0; col < 3; ++col) {
    axis[col] = glm::vec3(v[16 + col], v[19 + col], v[22 + col]);
    const float length = glm::length(axis[col]);
    if (!(length > 0.0f) || !std::isfinite(length))
      throw SceneError(path, kFields[16 + col], "the camera's axis (column " + std::to_string(col) +
                                                    " of c2w) has no length");
    axis[col] /= length;
  }
  c.camera_to_world = glm::mat4(glm::vec4(axis[0], 0.0f), glm::vec4(axis[1], 0.0f),
                                glm::vec4(axis[2], 0.0f), glm::vec4(position, 1.0f));
  if (int(v.size()) == kAll) {
    if (v[28] > 0.0) c.focal_distance = float(v[28]);
    if (!(v[29] >= 0.0)) throw SceneError(path, "lensRadius", "the lens radius must not be negative");
    c.lens_radius = float(v[29]);
  }
  return c;
}

}  // namespace pt
