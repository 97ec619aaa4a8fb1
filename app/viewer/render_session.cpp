#include "app/viewer/render_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "app/accelerator.h"
#include "app/camera_view.h"
#include "app/pixel_function.h"
#include "app/radiance.h"
#include "app/viewer/crash_witness.h"
#include "app/viewer/pixel_paths.h"
#include "framework/image/image.h"
#include "framework/render/sample_rate.h"
#include "framework/render/tile_renderer.h"
#include "framework/scene/camera_placement.h"
#include "framework/scene/collada_loader.h"
#include "framework/scene/scene_summary.h"
#include "parts/1-raygen/pixel_loop.h"

namespace pt {

namespace {

using Clock = std::chrono::steady_clock;

enum class Phase { rendering, done, cancelled, error };

const char* phase_name(Phase p) {
  switch (p) {
    case Phase::rendering: return "rendering";
    case Phase::done: return "done";
    case Phase::cancelled: return "cancelled";
    case Phase::error: return "error";
  }
  return "error";
}

/// The byte the pathtracer's PNG holds for a linear value (framework/image's write_png).
uint8_t png_byte(double linear) {
  return uint8_t(std::lround(255.0f * srgb_encode(float(linear))));
}

BvhOptions inspection_options(const RenderSettings& s) {
  BvhOptions o;
  o.split = s.accel == AccelKind::bvh_median ? BvhSplitMethod::median : BvhSplitMethod::sah;
  o.max_leaf_size = s.bvh_leaf_size;
  return o;
}

std::string shell_word(const std::string& s) {
  if (!s.empty() && s.find_first_of(" \t'\"\\$`!*?;&|<>()[]{}") == std::string::npos) return s;
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// The pathtracer command that renders what the page asked for.
std::string pathtracer_command(const std::vector<std::string>& flags, const std::string& scene) {
  std::string command = "pathtracer";
  for (const std::string& f : flags) command += " " + shell_word(f);
  return command + " " + shell_word(scene);
}

}  // namespace

ViewerRender parse_viewer_flags(const std::vector<std::string>& flags, const std::string& scene_path,
                                int threads) {
  for (const std::string& f : flags) {
    const std::string name = f.substr(0, f.find('='));
    if (name == "-f" || name == "--file" || name == "-e" || name == "--env" || name == "--info" ||
        name == "-h" || name == "--help" || name == "-t" || name == "--threads")
      throw std::invalid_argument(
          name + " is not for the viewer: it renders to the page, with the threads and the "
                 "scene it was started with");
    if (!f.empty() && f[0] != '-' && f.find(".dae") != std::string::npos)
      throw std::invalid_argument("'" + f + "': the viewer renders the scene it was started with");
  }
  ViewerRender r;
  r.flags = flags;
  std::vector<std::string> words = {"pathtracer"};
  words.insert(words.end(), flags.begin(), flags.end());
  words.push_back("-t");
  words.push_back(std::to_string(threads));
  words.push_back(scene_path);
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  std::ostringstream out, err;
  const int code = parse_command_line(int(argv.size()), argv.data(), &r.command, out, err);
  if (code >= 0) {
    std::string message = err.str();
    while (!message.empty() && message.back() == '\n') message.pop_back();
    if (message.rfind("pathtracer: ", 0) == 0) message = message.substr(12);
    throw std::invalid_argument(message.empty() ? "the flags were not understood" : message);
  }
  return r;
}

struct RenderSession::Job {
  ViewerRender render;
  Camera camera;
  std::shared_ptr<Film> film;
  PixelRect region;
  std::unique_ptr<std::atomic<uint8_t>[]> state;  ///< per pixel: 0 waiting, 1 rendered, 2 shown
  std::atomic<bool> cancel{false};
  std::atomic<long> done{0};
  std::atomic<Phase> phase{Phase::rendering};
  Clock::time_point started = Clock::now();
  std::atomic<double> first_pixel_seconds{-1.0};
  // Written by the render thread before phase leaves `rendering`; read after.
  std::string summary, error;
  nlohmann::json counts;
  double seconds = 0.0;
};

RenderSession::RenderSession(std::string scene_path, int threads)
    : scene_path_(std::move(scene_path)), threads_(threads) {}

RenderSession::~RenderSession() { cancel(); }

bool RenderSession::load(std::string* error, bool warm_up) {
  cancel();
  std::unique_lock lock(scene_mutex_);
  {
    std::lock_guard q(query_mutex_);
    query_.reset();
    bvh_.reset();
    query_key_.clear();
    bvh_key_.clear();
  }
  try {
    auto scene = std::make_unique<Scene>(load_collada(scene_path_, [](const std::string& w) {
      std::cerr << "warning: " << w << "\n";
    }));
    scene_ = std::move(scene);
    load_error_.clear();
    // The first render should not wait for what every render needs: the render's threads and
    // the tree the default flags ask for are made now, while the page loads.
    if (!warm_up) return true;
    RenderSettings defaults;
    defaults.threads = threads_;
    start_render_threads(defaults);
    render_query(defaults);
    return true;
  } catch (const std::exception& e) {
    scene_.reset();
    load_error_ = e.what();
    if (error) *error = load_error_;
    return false;
  }
}

Camera RenderSession::placed_camera(ViewerRender& render) const {
  // As pathtracer_main does: the default size from the file camera's aspect, then the placement.
  CommandLine& c = render.command;
  RenderSettings& s = c.settings;
  Camera camera = scene_->camera;
  if (!c.resolution_given) {
    apply_default_resolution(camera.aspect, &s);
    try {
      check_cell(s);
    } catch (const UsageError& e) {
      throw std::invalid_argument(e.what());
    }
  }
  try {
    if (c.camera_given)
      apply_camera_view(c.camera, &camera);
    else if (c.course_view)
      place_course_camera(scene_->bounds(), s.width, s.height, &camera);
    else if (!c.file_camera)
      centre_camera_on(scene_->bounds(), &camera);
  } catch (const std::range_error& e) {
    throw std::invalid_argument(scene_path_ + ": " + e.what());
  }
  apply_lens(s, &camera);
  return camera;
}

const RayQuery& RenderSession::render_query(const RenderSettings& s) {
  std::lock_guard q(query_mutex_);
  const std::string key = std::to_string(int(s.accel)) + "/" + std::to_string(s.bvh_leaf_size) +
                          "/" + std::to_string(s.bvh_width);
  if (!query_ || key != query_key_) {
    query_ = make_ray_query(s, *scene_);
    query_key_ = key;
  }
  return *query_;
}

const Bvh& RenderSession::inspection_bvh(const RenderSettings& s) {
  // The caller holds query_mutex_: counting primitive tests needs the tree to itself.
  const BvhOptions o = inspection_options(s);
  const std::string key = std::to_string(int(o.split)) + "/" + std::to_string(o.max_leaf_size);
  if (!bvh_ || key != bvh_key_) {
    bvh_ = std::make_unique<Bvh>(*scene_, o);
    bvh_key_ = key;
  }
  return *bvh_;
}

void RenderSession::cancel() {
  std::thread t;
  {
    std::lock_guard lock(job_mutex_);
    if (job_) job_->cancel = true;
    t = std::move(thread_);
  }
  if (t.joinable()) t.join();
}

void RenderSession::wait_for_pixels(long pixels, int limit_ms) const {
  std::shared_ptr<Job> job;
  {
    std::lock_guard lock(job_mutex_);
    job = job_;
  }
  if (!job) return;
  const long wanted = std::min<long>(pixels, job->region.area());
  const auto until = Clock::now() + std::chrono::milliseconds(limit_ms);
  // A short sleep rather than a signal from every pixel: the wait is once per render.
  while (job->phase.load() == Phase::rendering && job->done.load() < wanted && Clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
}

void RenderSession::start(const std::vector<std::string>& flags) {
  ViewerRender render = parse_viewer_flags(flags, scene_path_, threads_);
  cancel();
  auto job = std::make_shared<Job>();
  {
    std::shared_lock lock(scene_mutex_);
    if (!scene_) throw std::invalid_argument("no scene to render: " + load_error_);
    job->camera = placed_camera(render);
  }
  job->render = std::move(render);
  const RenderSettings& s = job->render.command.settings;
  std::lock_guard lock(job_mutex_);
  std::shared_ptr<Film> film = job_ ? job_->film : nullptr;
  if (!film || film->width() != s.width || film->height() != s.height || !s.has_cell) {
    film = std::make_shared<Film>(s.width, s.height);
  } else {
    for (int y = s.cell_y; y < s.cell_y + s.cell_h; ++y)
      for (int x = s.cell_x; x < s.cell_x + s.cell_w; ++x) film->at(x, y) = PixelStats{};
  }
  if (rgba_width_ != s.width || rgba_height_ != s.height) {
    rgba_.assign(size_t(s.width) * size_t(s.height) * 4, 0);
    for (size_t i = 3; i < rgba_.size(); i += 4) rgba_[i] = 255;
    rgba_width_ = s.width;
    rgba_height_ = s.height;
  }
  job->film = film;
  job->region = render_region(s);
  const size_t n = size_t(s.width) * size_t(s.height);
  job->state = std::make_unique<std::atomic<uint8_t>[]>(n);
  for (size_t i = 0; i < n; ++i) job->state[i].store(0, std::memory_order_relaxed);
  job_ = job;
  thread_ = std::thread([this, job] { run(job); });
}

void RenderSession::run(std::shared_ptr<Job> job) {
  std::shared_lock lock(scene_mutex_);
  const RenderSettings& s = job->render.command.settings;
  // A crash on the render's threads is told as this render.
  set_render_activity("rendered: " + pathtracer_command(job->render.flags, scene_path_));
  struct Told {
    ~Told() { set_render_activity(""); }
  } told;
  try {
    const Scene& scene = *scene_;
    const RayQuery& query = render_query(s);
    const TracedRadianceFn radiance = make_radiance(s, scene, query);
    const PixelFn pixel = make_pixel_fn(s, job->camera, radiance);
    Job& j = *job;
    const int width = s.width;
    // The render job's own pixel, watched: each pixel is marked when it is done (release, so the
    // page's reader sees its film entry whole), and a cancelled render skips what is left.
    const PixelFn watched = [&pixel, &j, width](int x, int y, Rng& rng, TraceContext& context,
                                                PixelStats* stats) {
      if (j.cancel.load(std::memory_order_relaxed)) return;
      pixel(x, y, rng, context, stats);
      j.state[size_t(y) * size_t(width) + size_t(x)].store(1, std::memory_order_release);
      if (j.done.fetch_add(1, std::memory_order_relaxed) == 0)
        j.first_pixel_seconds = std::chrono::duration<double>(Clock::now() - j.started).count();
    };
    const RenderReport report = render_tiles(s, watched, job->film.get(), {});
    job->seconds = report.seconds;
    if (job->cancel) {
      job->phase = Phase::cancelled;
      return;
    }
    job->summary = summary_line(report);
    // Primitive tests per ray: Part 2's binary tree, counting its leaf tests, on camera rays
    // through the pixel centres of a grid over the region (the render's own tree may be the wide
    // one, which counts nothing, and counting needs the tree to itself).
    {
      std::lock_guard q(query_mutex_);
      Bvh& bvh = const_cast<Bvh&>(inspection_bvh(s));
      uint64_t tests = 0, rays = 0, hits = 0;
      bvh.count_primitive_tests(&tests);
      const PixelRect& r = job->region;
      const int gx = std::min(64, r.width()), gy = std::min(48, r.height());
      for (int iy = 0; iy < gy; ++iy)
        for (int ix = 0; ix < gx; ++ix) {
          const int x = r.x0 + int((ix + 0.5) * r.width() / gx);
          const int y = r.y0 + int((iy + 0.5) * r.height() / gy);
          const Ray ray = camera_ray_through_pixel(job->camera, PixelRef{x, y, s.width, s.height},
                                                   glm::vec2(0.5f), glm::vec2(0.5f));
          SurfaceHit hit;
          hits += bvh.intersect(ray, &hit) ? 1 : 0;
          ++rays;
        }
      bvh.count_primitive_tests(nullptr);
      job->counts = {{"camera_rays", rays},
                     {"hits", hits},
                     {"primitive_tests", tests},
                     {"primitive_tests_per_ray", rays ? double(tests) / double(rays) : 0.0},
                     {"primitives", scene.primitive_count()}};
    }
    std::cout << "viewer: " << job->summary << std::endl;
    job->phase = Phase::done;
  } catch (const std::exception& e) {
    job->error = std::string("the render stopped: ") + e.what();
    std::cerr << "viewer: " << job->error << std::endl;
    job->phase = Phase::error;
  }
}

nlohmann::json RenderSession::status() const {
  nlohmann::json out;
  {
    std::shared_lock lock(scene_mutex_, std::try_to_lock);
    out["scene"] = scene_path_;
    if (lock.owns_lock()) {
      out["scene_loaded"] = bool(scene_);
      if (!load_error_.empty()) out["load_error"] = load_error_;
    }
  }
  std::shared_ptr<Job> job;
  {
    std::lock_guard lock(job_mutex_);
    job = job_;
  }
  if (!job) {
    out["state"] = out.value("scene_loaded", true) ? "idle" : "empty";
    return out;
  }
  const Phase phase = job->phase.load();
  const RenderSettings& s = job->render.command.settings;
  out["state"] = phase_name(phase);
  out["width"] = s.width;
  out["height"] = s.height;
  out["region"] = {job->region.x0, job->region.y0, job->region.width(), job->region.height()};
  out["done"] = job->done.load();
  out["total"] = job->region.area();
  out["elapsed"] = phase == Phase::rendering
                       ? std::chrono::duration<double>(Clock::now() - job->started).count()
                       : job->seconds;
  out["first_pixel_seconds"] = job->first_pixel_seconds.load();
  out["adaptive"] = s.adaptive;
  out["command"] = pathtracer_command(job->render.flags, scene_path_);
  out["flags"] = job->render.flags;
  if (phase == Phase::done) {
    out["summary"] = job->summary;
    out["counts"] = job->counts;
  }
  if (phase == Phase::error) out["error"] = job->error;
  return out;
}

std::vector<uint8_t> RenderSession::image_rgba(bool sample_rate, int* width, int* height) {
  std::shared_ptr<Job> job;
  std::lock_guard lock(job_mutex_);
  job = job_;
  if (!job) throw std::invalid_argument("nothing has been rendered yet");
  const RenderSettings& s = job->render.command.settings;
  *width = s.width;
  *height = s.height;
  if (sample_rate) {
    if (!s.adaptive) throw std::invalid_argument("the sample-rate image needs an adaptive render (-a)");
    if (job->phase.load() != Phase::done)
      throw std::invalid_argument("the sample-rate image is drawn when the render is done");
    const Image rate = sample_rate_image(*job->film, s.samples_per_pixel);
    std::vector<uint8_t> out(size_t(s.width) * size_t(s.height) * 4, 255);
    for (size_t i = 0; i < rate.pixels().size(); ++i)
      for (int c = 0; c < 3; ++c) out[4 * i + size_t(c)] = png_byte(rate.pixels()[i][c]);
    return out;
  }
  const size_t n = size_t(s.width) * size_t(s.height);
  for (size_t i = 0; i < n; ++i) {
    if (job->state[i].load(std::memory_order_acquire) != 1) continue;
    const glm::dvec3 mean = job->film->pixels()[i].mean;
    for (int c = 0; c < 3; ++c) rgba_[4 * i + size_t(c)] = png_byte(mean[c]);
    job->state[i].store(2, std::memory_order_relaxed);
  }
  return rgba_;
}

nlohmann::json RenderSession::scene_json(const std::vector<std::string>& flags) {
  ViewerRender render = parse_viewer_flags(flags, scene_path_, threads_);
  std::shared_lock lock(scene_mutex_);
  if (!scene_) throw std::invalid_argument("the scene did not load: " + load_error_);
  const Scene& scene = *scene_;
  const Camera camera = placed_camera(render);
  const RenderSettings& s = render.command.settings;
  nlohmann::json out;
  std::vector<float> positions;
  positions.reserve(scene.positions.size() * 3);
  for (const glm::vec3& p : scene.positions) positions.insert(positions.end(), {p.x, p.y, p.z});
  std::vector<uint32_t> triangles, materials;
  triangles.reserve(scene.triangles.size() * 3);
  for (const Triangle& t : scene.triangles) {
    triangles.insert(triangles.end(), {t.v[0], t.v[1], t.v[2]});
    materials.push_back(t.material);
  }
  out["positions"] = positions;
  out["triangles"] = triangles;
  out["triangle_materials"] = materials;
  nlohmann::json spheres = nlohmann::json::array();
  for (const Sphere& sp : scene.spheres)
    spheres.push_back({{"center", {sp.center.x, sp.center.y, sp.center.z}},
                       {"radius", sp.radius},
                       {"material", sp.material}});
  out["spheres"] = spheres;
  nlohmann::json mats = nlohmann::json::array();
  for (const Material& m : scene.materials)
    mats.push_back({{"name", m.name},
                    {"kind", to_string(m.kind)},
                    {"albedo", {m.albedo.x, m.albedo.y, m.albedo.z}},
                    {"emission", {m.emission.x, m.emission.y, m.emission.z}}});
  out["materials"] = mats;
  nlohmann::json lights = nlohmann::json::array();
  auto v3 = [](const glm::vec3& v) { return nlohmann::json{v.x, v.y, v.z}; };
  for (const Light& l : scene.lights)
    lights.push_back({{"name", l.name},
                      {"kind", to_string(l.kind)},
                      {"position", v3(l.position)},
                      {"direction", v3(l.direction)},
                      {"edge_u", v3(l.edge_u)},
                      {"edge_v", v3(l.edge_v)},
                      {"radiance", v3(l.radiance)}});
  out["lights"] = lights;
  const CameraView view = camera_view_of(camera);
  out["camera"] = {{"eye", v3(view.eye)},
                   {"target", v3(view.target)},
                   {"up", v3(view.up)},
                   {"hfov", view.hfov_degrees},
                   {"znear", camera.znear},
                   {"zfar", camera.zfar},
                   {"text", format_camera_view(view)}};
  out["width"] = s.width;
  out["height"] = s.height;
  const Bounds3 b = scene.bounds();
  out["bounds"] = {v3(b.lo), v3(b.hi)};
  out["description"] = describe_scene(scene);
  out["up_axis"] = scene.up_axis;
  return out;
}

nlohmann::json RenderSession::bvh_json(const std::vector<std::string>& flags) {
  ViewerRender render = parse_viewer_flags(flags, scene_path_, threads_);
  std::shared_lock lock(scene_mutex_);
  if (!scene_) throw std::invalid_argument("the scene did not load: " + load_error_);
  std::lock_guard q(query_mutex_);
  const Bvh& bvh = inspection_bvh(render.command.settings);
  const BvhOptions o = inspection_options(render.command.settings);
  const std::vector<BvhNode>& nodes = bvh.nodes();
  // Depth first: node i's first child is i + 1, its second `offset`. Depth top-down, then each
  // node's SAH cost bottom-up (children come after their parent), relative to its own box:
  // C = c_t + (A_l C_l + A_r C_r) / A for an interior node, c_i n for a leaf.
  std::vector<int> depth(nodes.size(), 0), parent(nodes.size(), -1);
  for (size_t i = 0; i < nodes.size(); ++i)
    if (!nodes[i].is_leaf()) {
      for (uint32_t c : {uint32_t(i + 1), nodes[i].offset}) {
        depth[c] = depth[i] + 1;
        parent[c] = int(i);
      }
    }
  std::vector<double> cost(nodes.size(), 0.0);
  for (size_t k = nodes.size(); k-- > 0;) {
    const BvhNode& n = nodes[k];
    if (n.is_leaf()) {
      cost[k] = double(o.costs.intersection) * n.count;
    } else {
      const double a = n.bounds.surface_area();
      const double al = nodes[k + 1].bounds.surface_area(), ar = nodes[n.offset].bounds.surface_area();
      cost[k] = o.costs.traversal +
                (a > 0.0 ? (al * cost[k + 1] + ar * cost[n.offset]) / a : cost[k + 1] + cost[n.offset]);
    }
  }
  // Flat arrays: the page reads thousands of nodes.
  std::vector<float> boxes;
  std::vector<int> left, right, counts, first;
  boxes.reserve(nodes.size() * 6);
  for (size_t i = 0; i < nodes.size(); ++i) {
    const BvhNode& n = nodes[i];
    boxes.insert(boxes.end(), {n.bounds.lo.x, n.bounds.lo.y, n.bounds.lo.z, n.bounds.hi.x,
                               n.bounds.hi.y, n.bounds.hi.z});
    left.push_back(n.is_leaf() ? -1 : int(i + 1));
    right.push_back(n.is_leaf() ? -1 : int(n.offset));
    counts.push_back(n.count);
    first.push_back(n.is_leaf() ? int(n.offset) : -1);
  }
  // A subtree's primitive count, bottom-up.
  std::vector<int> below(nodes.size(), 0);
  for (size_t k = nodes.size(); k-- > 0;)
    below[k] = nodes[k].is_leaf() ? nodes[k].count : below[k + 1] + below[nodes[k].offset];
  const BvhStats& st = bvh.stats();
  return {{"boxes", boxes},       {"left", left},
          {"right", right},       {"parent", parent},
          {"count", counts},      {"primitives_below", below},
          {"first", first},       {"depth", depth},
          {"sah_cost", cost},     {"order", bvh.order()},
          {"stats",
           {{"nodes", st.nodes},
            {"leaves", st.leaves},
            {"depth", st.depth},
            {"primitives", st.primitives},
            {"sah_cost", st.sah_cost},
            {"build_ms", st.build_ms},
            {"split", st.split == BvhSplitMethod::sah ? "sah" : "median"},
            {"max_leaf_size", o.max_leaf_size}}}};
}

nlohmann::json RenderSession::pick(const std::vector<std::string>& flags, const glm::vec3& origin,
                                   const glm::vec3& direction) {
  ViewerRender render = parse_viewer_flags(flags, scene_path_, threads_);
  std::shared_lock lock(scene_mutex_);
  if (!scene_) throw std::invalid_argument("the scene did not load: " + load_error_);
  std::lock_guard q(query_mutex_);
  const Bvh& bvh = inspection_bvh(render.command.settings);
  Ray ray;
  ray.o = origin;
  ray.d = direction;
  SurfaceHit hit;
  nlohmann::json out = {{"origin", {origin.x, origin.y, origin.z}},
                        {"direction", {direction.x, direction.y, direction.z}}};
  if (!bvh.intersect(ray, &hit)) {
    out["hit"] = false;
    return out;
  }
  out["hit"] = true;
  out["t"] = hit.t;
  out["point"] = {hit.p.x, hit.p.y, hit.p.z};
  out["normal"] = {hit.n.x, hit.n.y, hit.n.z};
  out["primitive"] = hit.primitive;
  const std::vector<BvhNode>& nodes = bvh.nodes();
  for (size_t i = 0; i < nodes.size(); ++i) {
    const BvhNode& n = nodes[i];
    if (!n.is_leaf()) continue;
    for (uint32_t k = n.offset; k < n.offset + n.count; ++k)
      if (bvh.order()[k] == hit.primitive) out["leaf"] = i;
  }
  return out;
}

nlohmann::json RenderSession::explain_pixel(const std::vector<std::string>& flags, int x, int y) {
  ViewerRender render = parse_viewer_flags(flags, scene_path_, threads_);
  std::shared_lock lock(scene_mutex_);
  if (!scene_) throw std::invalid_argument("the scene did not load: " + load_error_);
  const Camera camera = placed_camera(render);
  const RenderSettings& s = render.command.settings;
  if (x < 0 || y < 0 || x >= s.width || y >= s.height)
    throw std::invalid_argument("pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                ") is not in the " + std::to_string(s.width) + "x" +
                                std::to_string(s.height) + " image");
  std::lock_guard q(query_mutex_);
  const Bvh& bvh = inspection_bvh(s);
  return record_pixel(s, *scene_, camera, bvh, x, y);
}

}  // namespace pt
