// scene_gen: writes the project's own COLLADA scenes (the small ones are committed in scenes/).
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "scenes/generator/collada_writer.h"
#include "scenes/generator/cornell_scenes.h"

int main(int argc, char** argv) {
  std::vector<std::string> names;
  std::string out_dir = ".";
  bool list = false;
  CLI::App app{
      "Writes the project's COLLADA scenes. With no SCENE, writes the committed ones; to refresh "
      "them run it with -o pointing at the repository's scenes/ folder."};
  std::vector<std::string> known;
  for (const auto& e : scenegen::scene_entries()) known.push_back(e.name);
  app.add_option("scene", names, "scenes to write, by name (see --list)")->check(CLI::IsMember(known));
  app.add_option("-o,--out-dir", out_dir, "folder to write NAME.dae into (created if missing)");
  app.add_flag("--list", list, "print the scenes it knows and exit");
  CLI11_PARSE(app, argc, argv);

  if (list) {
    for (const auto& e : scenegen::scene_entries())
      std::printf("%-22s %s%s\n", e.name.c_str(), e.summary.c_str(), e.committed ? "" : " (not committed)");
    return 0;
  }
  if (names.empty())
    for (const auto& e : scenegen::scene_entries())
      if (e.committed) names.push_back(e.name);

  try {
    std::filesystem::create_directories(out_dir);
    for (const std::string& name : names) {
      auto start = std::chrono::steady_clock::now();
      scenegen::Document doc = scenegen::build_scene(name);
      size_t triangles = 0;
      for (const auto& m : doc.meshes) triangles += m.mesh.triangles.size();
      std::string path = (std::filesystem::path(out_dir) / (name + ".dae")).string();
      scenegen::write_collada(doc, path);
      double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf("%s: %zu triangles, %zu spheres, %ju bytes, %.2f s\n", path.c_str(), triangles,
                  doc.spheres.size(), std::uintmax_t(std::filesystem::file_size(path)), seconds);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "scene_gen: %s\n", e.what());
    return 1;
  }
  return 0;
}
