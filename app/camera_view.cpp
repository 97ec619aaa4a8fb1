#include "app/camera_view.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>

namespace pt {
namespace {

const char* const kFieldNames[10] = {"px", "py", "pz", "tx", "ty", "tz", "ux", "uy", "uz", "fov"};

float parse_field(const std::string& field, int index) {
  // A field is a plain decimal number: strtof would also take leading spaces, a '+', hexadecimal
  // and "inf", so only digits, a point, an exponent and signs get that far. strtof, not
  // from_chars: libc++ (macOS's standard library) has no floating-point from_chars. It reads in
  // the C locale, which this program never changes.
  const bool plain = !field.empty() && field[0] != '+' &&
                     field.find_first_not_of("0123456789.eE+-") == std::string::npos;
  char* stop = nullptr;
  errno = 0;
  const float v = plain ? std::strtof(field.c_str(), &stop) : 0.0f;
  if (!plain || stop != field.c_str() + field.size() || (errno == ERANGE && v == 0.0f))
    throw std::invalid_argument("--camera: field " + std::to_string(index + 1) + " (" +
                                kFieldNames[index] + ") '" + field + "' is not a number");
  if (!std::isfinite(v))
    throw std::invalid_argument("--camera: field " + std::to_string(index + 1) + " (" +
                                kFieldNames[index] + ") '" + field + "' is not finite");
  return v;
}

}  // namespace

CameraView parse_camera_view(const std::string& text) {
  std::vector<std::string> fields(1);
  for (char c : text) {
    if (c == ',')
      fields.emplace_back();
    else
      fields.back() += c;
  }
  if (fields.size() != 10)
    throw std::invalid_argument("--camera needs ten numbers px,py,pz,tx,ty,tz,ux,uy,uz,fov (got " +
                                std::to_string(fields.size()) + " in '" + text + "')");
  float v[10];
  for (int i = 0; i < 10; ++i) v[i] = parse_field(fields[size_t(i)], i);
  CameraView view;
  view.eye = {v[0], v[1], v[2]};
  view.target = {v[3], v[4], v[5]};
  view.up = {v[6], v[7], v[8]};
  view.hfov_degrees = v[9];
  const glm::vec3 forward = view.target - view.eye;
  if (!(glm::length(forward) > 0.0f) || !std::isfinite(glm::length(forward)))
    throw std::invalid_argument("--camera: the eye and the target are the same point (or too far "
                                "apart to subtract): there is no direction to look in");
  if (!(glm::length(view.up) > 0.0f) || !std::isfinite(glm::length(view.up)))
    throw std::invalid_argument("--camera: the up direction (ux,uy,uz) is zero");
  const glm::vec3 side = glm::cross(glm::normalize(forward), glm::normalize(view.up));
  if (!(glm::length(side) > 1e-6f))
    throw std::invalid_argument("--camera: the up direction is along the direction of view, so "
                                "it says nothing about which way is up");
  if (!(view.hfov_degrees > 0.0f && view.hfov_degrees < 180.0f))
    throw std::invalid_argument("--camera: the field of view (fov, horizontal, in degrees) must "
                                "be between 0 and 180, not inclusive (got " + fields[9] + ")");
  return view;
}

std::string format_camera_view(const CameraView& view) {
  const float v[10] = {view.eye.x,    view.eye.y,    view.eye.z, view.target.x, view.target.y,
                       view.target.z, view.up.x,     view.up.y,  view.up.z,     view.hfov_degrees};
  std::string out;
  for (int i = 0; i < 10; ++i) {
    char buffer[32];
    // %.9g reads back as the same float.
    std::snprintf(buffer, sizeof buffer, "%.9g", double(v[i]));
    if (i) out += ',';
    out += buffer;
  }
  return out;
}

CameraView camera_view_of(const Camera& camera) {
  CameraView view;
  view.eye = glm::vec3(camera.camera_to_world[3]);
  view.target = view.eye - glm::normalize(glm::vec3(camera.camera_to_world[2]));
  view.up = glm::normalize(glm::vec3(camera.camera_to_world[1]));
  view.hfov_degrees = camera.hfov_degrees;
  return view;
}

void apply_camera_view(const CameraView& view, Camera* camera) {
  // The camera looks down its local -Z with +Y up (COLLADA): its columns are right, up, back.
  const glm::vec3 back = glm::normalize(view.eye - view.target);
  const glm::vec3 right = glm::normalize(glm::cross(view.up, back));
  const glm::vec3 up = glm::cross(back, right);
  camera->camera_to_world = glm::mat4(glm::vec4(right, 0.0f), glm::vec4(up, 0.0f),
                                      glm::vec4(back, 0.0f), glm::vec4(view.eye, 1.0f));
  camera->hfov_degrees = view.hfov_degrees;
}

}  // namespace pt
