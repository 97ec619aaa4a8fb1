// Reads the course's COLLADA 1.4 dialect (Blender export plus <extra><technique profile="CGL">).
#pragma once

#include <functional>
#include <string>

#include "framework/scene/scene.h"

namespace pt {

/// Where the loader reports what it skipped or changed (unknown elements, a texture replaced by
/// grey, a default camera). Materials that no part renders yet are not its business: see
/// materials_falling_back() in scene/scene_summary.h. The default writes "warning: ..." lines
/// to stderr.
using WarningSink = std::function<void(const std::string&)>;

/// Loads a .dae file into a Scene in world space. Throws SceneError naming the file and the
/// element for anything it cannot make sense of: a missing or unreadable file, XML that does
/// not parse, an index out of range, a url="#id" that points nowhere, a number that is not one
/// (NaN, text), a scene with nothing to render. Messages read "FILE: <element id=...> (line N):
/// what is wrong".
///
/// Every mesh vertex gets a shading normal (the file's, through the inverse transpose, or the
/// face normal where the file has none), so Scene::normals is the size of Scene::positions.
/// Corners that name the same position in the file get bit-identical floats.
Scene load_collada(const std::string& path, const WarningSink& warn = {});

/// The same, from a string in memory; `name` stands in for the file name in messages.
Scene load_collada_string(const std::string& xml, const std::string& name,
                          const WarningSink& warn = {});

}  // namespace pt
