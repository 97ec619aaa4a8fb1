// The grading manifest (reference/manifest.json): which checks each part has, their points,
// and how each reference image was made.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace pt::grader {

/// One graded render: a scene rendered with given flags and compared with a reference.
struct RenderCheck {
  std::string name;                     ///< "part1.normals.cornell_spheres"
  int part = 0;
  std::string scene;                    ///< relative to the project (or to the course's scenes)
  bool course_scene = false;            ///< scene lies in ../shared/scenes/cs184: skipped if absent
  std::vector<std::string> args;        ///< flags of the graded render
  std::vector<std::string> reference_args;  ///< flags of the reference render
  uint64_t seed = 0;                    ///< of the graded render
  uint64_t reference_seed = 0;          ///< of the reference: different random numbers
  double points = 0.0;
  double timeout = 60.0;                ///< seconds for the graded render
  std::string reference;                ///< the reference EXR, relative to the project
  std::string checksum;                 ///< CRC-32 of the reference file, "" until it is made
};

/// A part: its CTest label's points and time limits, and its renders.
struct PartSpec {
  int part = 0;
  double test_points = 0.0;
  double test_timeout = 60.0;           ///< per test
  double build_timeout = 1200.0;
  std::vector<RenderCheck> renders;
};

/// The whole manifest; `json` keeps what was read so that a rewrite keeps unknown fields.
struct Manifest {
  int block_size = 16;
  double alpha = 0.01;
  std::vector<PartSpec> parts;
  nlohmann::ordered_json json;

  const PartSpec* find_part(int part) const;
};

/// Reads and checks the manifest; throws std::runtime_error naming the file and the entry.
Manifest read_manifest(const std::string& path);

/// Records how a reference was made (command, seconds, checksum) in the manifest file.
void record_reference(const std::string& manifest_path, const std::string& check_name,
                      const nlohmann::ordered_json& made);

/// CRC-32 of a file as 8 hex digits; throws std::runtime_error when it cannot be read.
std::string file_checksum(const std::string& path);

}  // namespace pt::grader
