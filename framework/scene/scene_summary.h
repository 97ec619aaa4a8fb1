// Not needed for the assignment.
// What a loaded scene holds, in words (pathtracer --info) and as JSON, and which materials fall back.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/scene/scene.h"

namespace pt {

/// A multi-line, human-readable summary: file, up axis, triangles, spheres, vertices, materials
/// by kind with their names, emissive primitives, lights by kind, bounds and camera.
std::string describe_scene(const Scene& scene);

/// The same facts as describe_scene, as JSON (for scripts and the write-up).
nlohmann::json describe_scene_json(const Scene& scene);

/// One warning line naming every material (name and kind) whose kind is not in `rendered`, so
/// will be drawn as diffuse; "" when every material is rendered as the file asks. The app calls
/// it with the kinds the parts built so far can draw.
std::string materials_falling_back(const Scene& scene, const std::vector<MaterialKind>& rendered);

}  // namespace pt
