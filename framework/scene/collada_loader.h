// Reads the course's COLLADA 1.4 dialect (Blender export plus <extra><technique profile="CGL">).
#pragma once

#include <functional>
#include <string>

#include "scene/scene.h"

namespace pt {

/// Where the loader reports what it skipped or changed (unknown elements, materials that fall
/// back to diffuse). The default writes "warning: ..." lines to stderr.
using WarningSink = std::function<void(const std::string&)>;

/// Loads a .dae file into a Scene in world space. Throws SceneError naming the file and the
/// element for anything it cannot make sense of: a missing or unreadable file, XML that does
/// not parse, an index out of range, a url="#id" that points nowhere, a number that is not one
/// (NaN, text), a scene with nothing to render.
Scene load_collada(const std::string& path, const WarningSink& warn = {});

/// The same, from a string in memory; `name` stands in for the file name in messages.
Scene load_collada_string(const std::string& xml, const std::string& name,
                          const WarningSink& warn = {});

}  // namespace pt
