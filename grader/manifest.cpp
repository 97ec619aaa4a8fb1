#include "grader/manifest.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <boost/crc.hpp>

#include "framework/text/text_file.h"

namespace pt::grader {
namespace {

[[noreturn]] void bad(const std::string& path, const std::string& where, const std::string& what) {
  throw std::runtime_error(path + ": " + where + ": " + what);
}

template <typename T>
T field(const std::string& path, const std::string& where, const nlohmann::ordered_json& j,
        const char* key) {
  if (!j.contains(key)) bad(path, where, std::string("missing \"") + key + "\"");
  try {
    return j.at(key).get<T>();
  } catch (const nlohmann::json::exception&) {
    bad(path, where, std::string("\"") + key + "\" has the wrong type");
  }
}

template <typename T>
T optional(const nlohmann::ordered_json& j, const char* key, T fallback) {
  return j.contains(key) ? j.at(key).get<T>() : fallback;
}

}  // namespace

const PartSpec* Manifest::find_part(int part) const {
  for (const PartSpec& p : parts)
    if (p.part == part) return &p;
  return nullptr;
}

Manifest read_manifest(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot be read (the grading manifest)");
  Manifest m;
  try {
    m.json = nlohmann::ordered_json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error(path + ": not valid JSON: " + e.what());
  }
  try {
    m.block_size = optional(m.json, "block_size", 16);
    m.alpha = optional(m.json, "alpha", 0.01);
    if (m.block_size < 1 || !(m.alpha > 0 && m.alpha < 1))
      bad(path, "top level", "block_size must be >= 1 and alpha in (0, 1)");
    for (const auto& pj : field<nlohmann::ordered_json>(path, "top level", m.json, "parts")) {
      PartSpec p;
      p.part = field<int>(path, "a part", pj, "part");
      std::string where = "part " + std::to_string(p.part);
      p.test_points = field<double>(path, where, pj, "test_points");
      p.test_timeout = optional(pj, "test_timeout", 60.0);
      p.build_timeout = optional(pj, "build_timeout", 1200.0);
      for (const auto& rj : optional(pj, "renders", nlohmann::ordered_json::array())) {
        RenderCheck r;
        r.part = p.part;
        r.name = field<std::string>(path, where, rj, "name");
        std::string rw = where + ", render \"" + r.name + "\"";
        r.scene = field<std::string>(path, rw, rj, "scene");
        r.course_scene = optional(rj, "course_scene", false);
        r.args = field<std::vector<std::string>>(path, rw, rj, "args");
        r.reference_args = field<std::vector<std::string>>(path, rw, rj, "reference_args");
        r.seed = field<uint64_t>(path, rw, rj, "seed");
        r.reference_seed = field<uint64_t>(path, rw, rj, "reference_seed");
        r.points = field<double>(path, rw, rj, "points");
        r.timeout = optional(rj, "timeout", 60.0);
        r.reference = field<std::string>(path, rw, rj, "reference");
        if (rj.contains("made")) r.checksum = optional(rj.at("made"), "crc32", std::string());
        if (r.seed == r.reference_seed)
          bad(path, rw, "the graded render must use other random numbers than its reference");
        p.renders.push_back(r);
      }
      m.parts.push_back(p);
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  return m;
}

void record_reference(const std::string& manifest_path, const std::string& check_name,
                      const nlohmann::ordered_json& made) {
  Manifest m = read_manifest(manifest_path);
  bool found = false;
  for (auto& pj : m.json["parts"])
    for (auto& rj : pj["renders"])
      if (rj["name"] == check_name) {
        rj["made"] = made;
        found = true;
      }
  if (!found) throw std::runtime_error(manifest_path + ": no render named " + check_name);
  std::ofstream out(manifest_path);
  out << m.json.dump(2) << "\n";
  if (!out) throw std::runtime_error(manifest_path + ": cannot be written");
}

std::string file_checksum(const std::string& path) {
  const std::string bytes = read_text_file(path);
  boost::crc_32_type crc;
  crc.process_bytes(bytes.data(), bytes.size());
  char buf[16];
  std::snprintf(buf, sizeof buf, "%08x", unsigned(crc.checksum()));
  return buf;
}

}  // namespace pt::grader
