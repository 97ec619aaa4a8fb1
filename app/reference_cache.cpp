#include "app/reference_cache.h"

#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <xxhash.h>

#include "framework/image/estimate_exr.h"
#include "framework/stats/image_error.h"

namespace pt {
namespace {

using nlohmann::json;

/// Bumped when what a key stands for changes, so old caches are not mistaken for new ones
/// (2: the fingerprint became XXH3, so the image library is not loaded to make a key).
constexpr int kKeyVersion = 2;

uint64_t file_fingerprint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot read the file to fingerprint it");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return XXH3_64bits(bytes.data(), bytes.size());
}

std::string hex(uint64_t v) {
  char text[17];
  std::snprintf(text, sizeof text, "%016" PRIx64, v);
  return text;
}

/// Every setting that changes the image (not the thread count, nor the BVH, which change only
/// the time), by name, so the manifest says how the reference was made.
json settings_json(const RenderSettings& s) {
  return {{"width", s.width},
          {"height", s.height},
          {"samples_per_pixel", s.samples_per_pixel},
          {"light_samples", s.light_samples},
          {"max_depth", s.max_depth},
          {"seed", s.seed},
          {"hemisphere_sampling", s.hemisphere_sampling},
          {"mis", s.mis},
          {"russian_roulette", s.russian_roulette},
          {"adaptive", s.adaptive},
          {"adaptive_batch", s.adaptive_batch},
          {"adaptive_tolerance", s.adaptive_tolerance},
          {"environment_map", s.environment_map},
          {"lens_radius", s.lens_radius},
          {"focal_distance", s.focal_distance},
          {"only_bounce", s.only_bounce},
          {"normals", s.shading == ShadingMode::normals}};
}

double noise_rel_mse(const RenderEstimate& e) {
  double sum = 0.0;
  for (size_t i = 0; i < e.mean.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (e.count[i] > 0.0f)
        sum += double(e.variance[i][c]) /
               (double(e.count[i]) * (double(e.mean[i][c]) * e.mean[i][c] + kRelMseEpsilon));
  return e.mean.empty() ? 0.0 : sum / (3.0 * double(e.mean.size()));
}

Image mean_image(const RenderEstimate& e) {
  Image image(e.width, e.height);
  image.pixels() = e.mean;
  return image;
}

/// The manifest at `path` if it exists, parses and carries `key`; else null.
json matching_manifest(const std::filesystem::path& path, const std::string& key) {
  std::ifstream in(path);
  if (!in) return nullptr;
  json m = json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (m.is_discarded() || !m.is_object() || m.value("key", "") != key) return nullptr;
  return m;
}

}  // namespace

std::string reference_key(const std::string& scene_path, const RenderSettings& settings) {
  json what = {{"version", kKeyVersion},
               {"scene", hex(file_fingerprint(scene_path))},
               {"settings", settings_json(settings)}};
  if (!settings.environment_map.empty())
    what["environment_map"] = hex(file_fingerprint(settings.environment_map));
  const std::string text = what.dump();
  return hex(XXH3_64bits(text.data(), text.size()));
}

Reference load_or_make_reference(const std::string& scene_path, const RenderSettings& settings,
                                 const std::filesystem::path& dir, const ReferenceRenderer& render,
                                 bool fresh, std::ostream& log) {
  Reference ref;
  ref.key = reference_key(scene_path, settings);
  ref.exr = dir / ("reference-" + ref.key + ".exr");
  ref.manifest = dir / ("reference-" + ref.key + ".json");

  if (!fresh) {
    json m = matching_manifest(ref.manifest, ref.key);
    if (!m.is_null() && std::filesystem::exists(ref.exr)) {
      try {
        ref.estimate = read_estimate_exr(ref.exr.string());
        if (ref.estimate.width == settings.width && ref.estimate.height == settings.height) {
          ref.reused = true;
          ref.seconds = m.value("seconds", 0.0);
        } else {
          log << "reference: " << ref.exr.string() << " is " << ref.estimate.width << "x"
              << ref.estimate.height << ", not " << settings.width << "x" << settings.height
              << "; rendering it again\n";
        }
      } catch (const std::exception& e) {
        log << "reference: " << e.what() << "; rendering it again\n";
      }
    }
  }
  if (!ref.reused) {
    log << "reference: rendering " << settings.width << "x" << settings.height << " at "
        << settings.samples_per_pixel << " spp, seed " << settings.seed << " (cached as "
        << ref.exr.string() << ")\n"
        << std::flush;
    ReferenceRender made = render(settings);
    ref.estimate = std::move(made.estimate);
    ref.seconds = made.seconds;
    std::filesystem::create_directories(dir);
    write_estimate_exr(ref.exr.string(), ref.estimate);
    json m = {{"key", ref.key},
              {"made_by", "bench convergence"},
              {"scene", scene_path},
              {"scene_fingerprint", hex(file_fingerprint(scene_path))},
              {"strategy", settings.mis ? "mis"
                           : settings.hemisphere_sampling ? "hemisphere"
                                                          : "light importance"},
              {"settings", settings_json(settings)},
              {"seconds", ref.seconds},
              {"exr", ref.exr.filename().string()}};
    std::ofstream out(ref.manifest);
    out << m.dump(2) << "\n";
    if (!out) throw std::runtime_error(ref.manifest.string() + ": cannot write the manifest");
  } else {
    log << "reference: reusing " << ref.exr.string() << " (key " << ref.key << ")\n";
  }
  ref.image = mean_image(ref.estimate);
  ref.noise_rel_mse = noise_rel_mse(ref.estimate);
  return ref;
}

}  // namespace pt
