#include "app/command_line.h"
#include "app/cli_parse.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <filesystem>
#include <ostream>
#include <vector>

#include <CLI/CLI.hpp>
#include <unistd.h>

#include "framework/image/image.h"

namespace pt {
namespace {

constexpr int kMaxResolution = 16384;
constexpr int kMaxThreads = 1024;
constexpr float kMaxLength = 1e18f;

std::string quoted(const std::string& s) { return "'" + s + "'"; }

std::string number(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

/// CLI11's help, except that an option taking several values shows its own names for them
/// ("-r W H") instead of "W H x 2".
class HelpFormatter : public CLI::Formatter {
 public:
  std::string make_option_opts(const CLI::Option* opt) const override {
    if (opt->get_type_size() == 0) return {};
    std::string out;
    if (!opt->get_type_name().empty()) out += " " + get_label(opt->get_type_name());
    if (!opt->get_default_str().empty()) out += "=" + opt->get_default_str();
    if (opt->get_required()) out += " " + get_label("REQUIRED");
    return out;
  }
};

/// --seed as a whole number from 0 to 2^64 - 1: CLI11 would wrap "-1" around and saturate a
/// number too large, each a seed nobody asked for.
uint64_t parse_seed(const std::string& text) {
  uint64_t v = 0;
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, v);
  if (text.empty() || r.ec != std::errc() || r.ptr != end)
    throw UsageError("--seed must be a whole number from 0 to 18446744073709551615 (got " +
                     quoted(text) + ")");
  return v;
}

// Everything that can be checked from the command line alone.
void check_settings(const CommandLine& c, const std::vector<int>& resolution,
                    const std::vector<int>& cell, const std::vector<double>& adaptive,
                    bool focal_given) {
  const RenderSettings& s = c.settings;
  if (s.samples_per_pixel < 1)
    throw UsageError("-s/--samples must be at least 1 (got " + std::to_string(s.samples_per_pixel) + ")");
  if (s.light_samples < 1)
    throw UsageError("-l/--light-samples must be at least 1 (got " + std::to_string(s.light_samples) + ")");
  if (s.threads < 0 || s.threads > kMaxThreads)
    throw UsageError("-t/--threads must be between 0 (every core) and " + std::to_string(kMaxThreads) +
                     " (got " + std::to_string(s.threads) + ")");
  if (s.max_depth < 0)
    throw UsageError("-m/--max-depth must be at least 0 (got " + std::to_string(s.max_depth) + ")");
  if (!resolution.empty())
    for (int v : resolution)
      if (v < 1 || v > kMaxResolution)
        throw UsageError("-r/--resolution: width and height must be between 1 and " +
                         std::to_string(kMaxResolution) + " (got " + std::to_string(resolution[0]) +
                         " " + std::to_string(resolution[1]) + ")");
  if (!cell.empty() && (cell[2] < 1 || cell[3] < 1))
    throw UsageError("-p/--cell: the cell's width and height must be at least 1 (got " +
                     std::to_string(cell[2]) + " " + std::to_string(cell[3]) + ")");
  if (!adaptive.empty()) {
    if (!(adaptive[0] >= 1.0 && adaptive[0] <= 1e9) || adaptive[0] != std::floor(adaptive[0]))
      throw UsageError("-a/--adaptive: BATCH must be a whole number of at least 1 (got " +
                       number(adaptive[0]) + ")");
    if (!(adaptive[1] > 0.0) || !std::isfinite(adaptive[1]))
      throw UsageError("-a/--adaptive: TOL must be a positive number (got " + number(adaptive[1]) + ")");
  }
  // Past kMaxLength the squares the ray tests take of the camera rays' coordinates overflow
  // float: every ray would miss (a lens of 1e38 crashed the wide BVH with its NaN rays).
  if (!(s.lens_radius >= 0.0f && s.lens_radius <= kMaxLength))
    throw UsageError("-b/--aperture: the lens radius must be from 0 to " + number(kMaxLength) +
                     " (got " + number(s.lens_radius) + ")");
  if (focal_given && !(s.focal_distance > 0.0f && s.focal_distance <= kMaxLength))
    throw UsageError("-d/--focal-distance must be positive and at most " + number(kMaxLength) +
                     " (got " + number(s.focal_distance) + ")");
  if (s.bvh_leaf_size < 1 || s.bvh_leaf_size > 255)
    throw UsageError("--leaf-size must be between 1 and 255 (got " + std::to_string(s.bvh_leaf_size) + ")");
  if (!c.output_path.empty() && !is_supported_image_extension(c.output_path))
    throw UsageError("-f/--file " + quoted(c.output_path) +
                     ": unknown image extension; use .png (8-bit sRGB) or .exr (linear float)");
}

}  // namespace

int parse_command_line(int argc, char** argv, CommandLine* command, std::ostream& out,
                       std::ostream& err) {
  CommandLine& c = *command;
  RenderSettings& s = c.settings;
  CLI::App app{"Renders a COLLADA scene (.dae) with the path tracer and writes the image.",
               "pathtracer"};
  app.formatter(std::make_shared<HelpFormatter>());
  app.footer(
      "Without -f the image goes to <scene name>.png in the current folder.\n"
      "An .exr output holds linear float R, G, B plus each pixel's sample variance\n"
      "(varR, varG, varB) and sample count (n).\n"
      "Exit codes: 0 done, 1 a scene or image file could not be read or written,\n"
      "2 a command line that cannot be honoured.");
  std::vector<int> resolution, cell;
  std::vector<double> adaptive;
  std::string bvh = "sah";
  bool normals = false;

  app.add_option("scene", c.scene_path, "The scene to render (COLLADA .dae)")->required();
  app.add_option("-s,--samples", s.samples_per_pixel, "Camera rays per pixel (the maximum with -a)")
      ->capture_default_str();
  app.add_option("-l,--light-samples", s.light_samples, "Samples per area light")->capture_default_str();
  app.add_option("-t,--threads", s.threads, "Render threads; 0 uses every core")->capture_default_str();
  app.add_option("-m,--max-depth", s.max_depth,
                 "Maximum ray depth: 0 emitted light only, 1 direct light, 2 one bounce, ...")
      ->capture_default_str();
  app.add_option("-r,--resolution", resolution,
                 "Image width and height (default: 480 wide, the scene camera's aspect)")
      ->expected(2)->allow_extra_args(false)->type_name("W H");
  app.add_option("-f,--file", c.output_path, "Render to FILE (.png or .exr) and exit")->type_name("FILE");
  app.add_flag("-H,--hemisphere", s.hemisphere_sampling,
               "Direct light by uniform hemisphere sampling instead of light sampling");
  app.add_option("-a,--adaptive", adaptive,
                 "Adaptive sampling: check convergence every BATCH samples, stop at tolerance TOL")
      ->expected(2)->allow_extra_args(false)->type_name("BATCH TOL");
  std::string stopping_rule = stopping_rule_name(s.stopping_rule);
  app.add_option("--stopping-rule", stopping_rule,
                 "With -a: which samples decide when a pixel stops (split: one in four decides, the "
                 "others form the value, unbiased; course: every sample does both, the course's "
                 "rule). Default: the assignment's (reference/manifest.json)")
      ->check(CLI::IsMember({"split", "course"}))->capture_default_str();
  app.add_option("-e,--env", s.environment_map, "Environment map (image-based infinite light)")
      ->type_name("FILE");
  app.add_option("-b,--aperture", s.lens_radius, "Thin-lens aperture radius (0: pinhole)")
      ->capture_default_str();
  app.add_option("-d,--focal-distance", s.focal_distance,
                 "Distance of the plane in focus (default: the scene's)");
  app.add_option("-p,--cell", cell, "Render only the cell of DX x DY pixels at column X, row Y")
      ->expected(4)->allow_extra_args(false)->type_name("X Y DX DY");
  CLI::Option* camera_settings =
      app.add_option("-c,--camera-settings", c.camera_settings_path,
                     "Render from the view saved in the course renderer's camera settings FILE "
                     "(its field of view, placement and lens; -b and -d, when given, win)")
          ->type_name("FILE");
  int accumulate = 1;
  app.add_option("-o,--accumulate-bounces", accumulate,
                 "1 (or more): the light of every bounce up to -m, the default; 0: only the light "
                 "of bounce -m itself (as --bounce M)")
      ->type_name("INT");
  app.add_flag("--info", c.info, "Print what the scene holds and render nothing");
  std::string seed = std::to_string(s.seed);
  app.add_option("--seed", seed, "Random seed: the same seed gives the same image")
      ->type_name("UINT")->capture_default_str();
  app.add_option("--bvh", bvh, "Acceleration structure")
      ->check(CLI::IsMember({"sah", "median", "none"}))->capture_default_str();
  app.add_option("--leaf-size", s.bvh_leaf_size, "Most primitives in a BVH leaf")->capture_default_str();
  app.add_option("--bvh-width", s.bvh_width,
                 "2: trace Part 2's binary BVH; " + std::to_string(kWideBvhWidth) +
                     ": the framework's " + std::to_string(kWideBvhWidth) +
                     "-wide BVH built from it (the same hits, faster)")
      ->check(CLI::IsMember({2, kWideBvhWidth}))->capture_default_str();
  app.add_flag("--normals", normals, "Show shading normals (n * 0.5 + 0.5) instead of light");
  std::string integrator = "auto";
  app.add_option("--integrator", integrator,
                 "What answers a camera ray: normals (as --normals), direct (Part 3's direct light "
                 "alone, -m 0 or 1, no Part 4 code), path (Part 4's paths at any -m), auto "
                 "(normals with --normals, direct for -m 0 or 1 without --mis, path otherwise)")
      ->check(CLI::IsMember({"auto", "normals", "direct", "path"}))->capture_default_str();
  app.add_flag("--mis", s.mis, "Combine light and BSDF samples by multiple importance sampling");
  bool no_rr = false;
  app.add_flag("--no-rr", no_rr, "No Russian roulette: every path runs to the maximum depth");
  app.add_option("--bounce", s.only_bounce,
                 "Only the light that took exactly this many bounces (0: emitted, 1: direct)")
      ->check(CLI::NonNegativeNumber);
  CLI::Option* file_camera = app.add_flag(
      "--file-camera", c.file_camera,
      "Keep the file's camera where it is (default: centred on the scene at the file camera's "
      "distance)");
  app.add_flag("--course-view", c.course_view,
               "Frame the scene as the course's renderer does at the same -r: 1.5 x the scene's "
               "diagonal from its centre, and the pixels of its 800 x 600 window (at -r 480 360 the "
               "field of view's tangent x 0.6), so images compare with the course's")
      ->excludes(file_camera)->excludes(camera_settings);
  std::string camera;
  app.add_option("--camera", camera,
                 "Place the camera: eye px,py,pz looking at tx,ty,tz with up ux,uy,uz and a "
                 "horizontal field of view of fov degrees (the viewer's \"use this view\" writes it)")
      ->type_name("px,py,pz,tx,ty,tz,ux,uy,uz,fov")
      ->excludes(file_camera)
      ->excludes("--course-view")
      ->excludes(camera_settings);

  if (auto code = parse_or_exit(app, argc, argv, "pathtracer", "Run with --help for the options.",
                                out, err))
    return *code;

  try {
    c.resolution_given = !resolution.empty();
    if (c.resolution_given) s.width = resolution[0], s.height = resolution[1];
    if (!cell.empty()) {
      s.has_cell = true;
      s.cell_x = cell[0], s.cell_y = cell[1], s.cell_w = cell[2], s.cell_h = cell[3];
    }
    s.stopping_rule = *parse_stopping_rule(stopping_rule);
    if (app.count("--stopping-rule") && adaptive.empty())
      throw UsageError("--stopping-rule says when an adaptive pixel stops: it needs -a BATCH TOL");
    if (!adaptive.empty()) {
      s.adaptive = true;
      s.adaptive_batch = int(std::min(adaptive[0], 1e9));
      s.adaptive_tolerance = float(adaptive[1]);
    }
    s.accel = bvh == "median" ? AccelKind::bvh_median
              : bvh == "none" ? AccelKind::brute_force
                              : AccelKind::bvh_sah;
    if (normals && integrator != "auto" && integrator != "normals")
      throw UsageError("--normals and --integrator " + integrator + " ask for different images");
    if (normals || integrator == "normals") s.shading = ShadingMode::normals;
    if (integrator == "direct") {
      s.integrator = IntegratorChoice::direct;
      if (s.max_depth > 1)
        throw UsageError("--integrator direct is direct light alone: -m 0 or -m 1 (got -m " +
                         std::to_string(s.max_depth) + "; paths are --integrator path)");
      if (s.mis)
        throw UsageError("--integrator direct has no --mis (multiple importance sampling is "
                         "Part 4's: --integrator path)");
    }
    if (integrator == "path") s.integrator = IntegratorChoice::path;
    if (no_rr) s.russian_roulette = false;
    s.seed = parse_seed(seed);
    if (app.count("--camera")) {
      try {
        c.camera = parse_camera_view(camera);
      } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
      }
      c.camera_given = true;
    }
    if (app.count("--bounce") && s.only_bounce < 0)
      throw UsageError("--bounce must be 0 or more (got " + std::to_string(s.only_bounce) + ")");
    if (app.count("--accumulate-bounces")) {
      if (accumulate < 0)
        throw UsageError("-o/--accumulate-bounces must be 0 or more (got " + std::to_string(accumulate) + ")");
      if (accumulate == 0) {
        if (app.count("--bounce") && s.only_bounce != s.max_depth)
          throw UsageError("-o 0 keeps bounce -m " + std::to_string(s.max_depth) +
                           " only, --bounce " + std::to_string(s.only_bounce) + " another");
        s.only_bounce = s.max_depth;
      }
    }
    if (app.count("--camera-settings") && c.camera_settings_path.empty())
      throw UsageError("-c/--camera-settings: the file name is empty");
    c.lens_given = app.count("--aperture") > 0;
    c.focal_distance_given = app.count("--focal-distance") > 0;
    if (app.count("--env") && s.environment_map.empty())
      throw UsageError("-e/--env: the environment map's file name is empty");
    check_settings(c, resolution, cell, adaptive, app.count("--focal-distance") > 0);
    if (c.resolution_given) check_cell(s);
  } catch (const UsageError& e) {
    err << "pathtracer: " << e.what() << "\n";
    return kExitUsage;
  }
  return -1;
}

void apply_default_resolution(float camera_aspect, RenderSettings* settings) {
  settings->width = 480;
  float aspect = camera_aspect > 0.0f && std::isfinite(camera_aspect) ? camera_aspect : 4.0f / 3.0f;
  settings->height = int(std::min<long>(kMaxResolution, std::max(1L, std::lround(480.0f / aspect))));
}

void check_cell(const RenderSettings& s) {
  if (!s.has_cell) return;
  if (s.cell_x < 0 || s.cell_y < 0 || s.cell_w < 1 || s.cell_h < 1 ||
      long(s.cell_x) + s.cell_w > s.width || long(s.cell_y) + s.cell_h > s.height)
    throw UsageError("-p/--cell " + std::to_string(s.cell_x) + " " + std::to_string(s.cell_y) + " " +
                     std::to_string(s.cell_w) + " " + std::to_string(s.cell_h) +
                     " is not inside the " + std::to_string(s.width) + "x" +
                     std::to_string(s.height) + " image");
}

void check_output_path(const std::string& path) {
  if (!is_supported_image_extension(path))
    throw UsageError(quoted(path) + ": unknown image extension; use .png or .exr");
  namespace fs = std::filesystem;
  fs::path parent = fs::path(path).parent_path();
  if (parent.empty()) parent = ".";
  std::error_code ec;
  if (!fs::is_directory(parent, ec))
    throw std::runtime_error(path + ": cannot write: folder " + quoted(parent.string()) +
                             " does not exist");
  if (access(parent.c_str(), W_OK) != 0)
    throw std::runtime_error(path + ": cannot write: folder " + quoted(parent.string()) +
                             " is not writable");
  if (fs::is_directory(path, ec))
    throw std::runtime_error(path + ": cannot write: it is a folder");
}

}  // namespace pt
