// bench: how fast the BVH builds and answers rays, as JSON, optionally beside Intel Embree on the
// very same rays (the ray sets of rays-format.md, read from files or made from the scene).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "parts/1-raygen/camera_ray.h"
#include "parts/2-bvh/bvh.h"
#ifdef PT_HAVE_WIDE_BVH
#include "app/accel/wide_bvh.h"
#endif
#include "app/convergence.h"
#include "app/strategy_agreement.h"
#include "framework/math/float_error.h"
#include "framework/math/frame.h"
#include "framework/rays/ray_set.h"
#include "framework/sampling/rng.h"
#include "framework/sampling/warp.h"
#include "framework/scene/collada_loader.h"
#include "framework/scene/scene_error.h"

#ifdef PT_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

namespace pt {
namespace {

using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

const char* const kSets[] = {"primary", "diffuse", "shadow"};
/// What each timing asks, said in the JSON so that no ratio compares unlike work.
const char* const kFullQuery = "intersect: the full SurfaceHit a renderer shades; shadow: any hit";
const char* const kNearestQuery = "nearest (primitive, t, barycentrics); shadow: any hit";

/// One ray set: the rays, whether they are occlusion queries, and the answers if a file gave them.
struct RaySet {
  std::string name;
  std::vector<Ray> rays;
  bool occlusion = false;
  std::vector<float> answers;  ///< empty when there is no answer file
};

/// Something that traces a whole ray set: per ray the nearest t (+inf for a miss), or 1/0 for
/// an occlusion set.
class Tracer {
 public:
  virtual ~Tracer() = default;
  virtual float trace(const Ray& ray, bool occlusion) const = 0;
};

class BvhTracer final : public Tracer {
 public:
  explicit BvhTracer(const RayQuery& bvh) : bvh_(bvh) {}
  float trace(const Ray& ray, bool occlusion) const override {
    if (occlusion) return bvh_.occluded(ray) ? 1.0f : 0.0f;
    SurfaceHit hit;
    return bvh_.intersect(ray, &hit) ? hit.t : std::numeric_limits<float>::infinity();
  }

 private:
  const RayQuery& bvh_;
};

#ifdef PT_HAVE_EMBREE
/// Embree's single-ray queries (rtcIntersect1 / rtcOccluded1) over the scene's triangles.
class EmbreeTracer final : public Tracer {
 public:
  explicit EmbreeTracer(const Scene& scene) {
    device_ = rtcNewDevice(nullptr);
    const auto start = Clock::now();
    scene_ = rtcNewScene(device_);
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                          RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                          scene.positions.size()));
    for (size_t i = 0; i < scene.positions.size(); ++i)
      for (int k = 0; k < 3; ++k) v[3 * i + k] = scene.positions[i][k];
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0,
                                                               RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                               scene.triangles.size()));
    for (size_t i = 0; i < scene.triangles.size(); ++i)
      for (int k = 0; k < 3; ++k) idx[3 * i + k] = scene.triangles[i].v[k];
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene_, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene_);
    build_ms_ = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  }
  ~EmbreeTracer() override {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  float trace(const Ray& ray, bool occlusion) const override {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray.org_x = ray.o.x, rh.ray.org_y = ray.o.y, rh.ray.org_z = ray.o.z;
    rh.ray.dir_x = ray.d.x, rh.ray.dir_y = ray.d.y, rh.ray.dir_z = ray.d.z;
    rh.ray.tnear = ray.tmin, rh.ray.tfar = ray.tmax;
    rh.ray.time = 0.0f, rh.ray.mask = ~0u, rh.ray.id = 0, rh.ray.flags = 0;
    if (occlusion) {
      rtcOccluded1(scene_, &context, &rh.ray);
      return rh.ray.tfar < 0.0f ? 1.0f : 0.0f;
    }
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rh);
    return rh.hit.geomID != RTC_INVALID_GEOMETRY_ID ? rh.ray.tfar
                                                     : std::numeric_limits<float>::infinity();
  }
  double build_ms() const { return build_ms_; }

 private:
  RTCDevice device_;
  RTCScene scene_;
  double build_ms_ = 0.0;
};
#endif

/// Traces the set with `threads` threads until at least `min_seconds` have passed; returns
/// millions of rays per second, and the answers of the first pass in *answers.
double measure(const Tracer& tracer, const RaySet& set, int threads, double min_seconds,
               std::vector<float>* answers) {
  answers->assign(set.rays.size(), 0.0f);
  tbb::task_arena arena(threads);
  size_t traced = 0;
  const auto start = Clock::now();
  double seconds = 0.0;
  do {
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, set.rays.size(), 1024),
                        [&](const tbb::blocked_range<size_t>& r) {
                          for (size_t i = r.begin(); i < r.end(); ++i)
                            (*answers)[i] = tracer.trace(set.rays[i], set.occlusion);
                        });
    });
    traced += set.rays.size();
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
  } while (seconds < min_seconds && !set.rays.empty());
  return seconds > 0.0 ? double(traced) / seconds * 1e-6 : 0.0;
}

/// Whether two answers to one ray agree: both misses, both the same occlusion, or distances
/// within a part in 10^4 (two intersectors round differently; a different surface is much
/// farther off than that).
bool agree(float a, float b, bool occlusion) {
  if (occlusion || std::isinf(a) || std::isinf(b)) return a == b;
  return std::abs(a - b) <= 1e-4f * std::max(std::abs(a), std::abs(b));
}

size_t count_agreeing(const std::vector<float>& a, const std::vector<float>& b, bool occlusion) {
  size_t n = 0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) n += agree(a[i], b[i], occlusion);
  return n;
}

int up_axis_index(const std::string& up) { return up == "X_UP" ? 0 : up == "Z_UP" ? 2 : 1; }

/// The three sets of rays-format.md made from the scene: a pinhole ray per pixel of a
/// width x height image; from each primary hit a cosine-distributed bounce about the geometric
/// normal (facing the incoming ray) and a shadow ray to a random point of the top face of the
/// scene's bounds, ending just short of it.
std::vector<RaySet> make_sets(const Scene& scene, const Bvh& bvh, int width, int height,
                              uint64_t seed) {
  std::vector<RaySet> sets(3);
  for (int k = 0; k < 3; ++k) sets[k].name = kSets[k];
  sets[2].occlusion = true;
  Camera camera = scene.camera;
  camera.lens_radius = 0.0f;
  const float aspect = float(width) / float(height);
  const Bounds3 b = scene.bounds();
  const int up = up_axis_index(scene.up_axis);
  const int u = (up + 1) % 3, v = (up + 2) % 3;
  Rng rng(seed);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::vec2 film((float(x) + 0.5f) / float(width), 1.0f - (float(y) + 0.5f) / float(height));
      const Ray ray = generate_camera_ray(camera, aspect, film, glm::vec2(0.5f));
      sets[0].rays.push_back(ray);
      SurfaceHit hit;
      if (!bvh.intersect(ray, &hit)) continue;
      glm::vec3 n = hit.ng;
      if (glm::dot(n, ray.d) > 0.0f) n = -n;
      Ray bounce;
      bounce.d = glm::normalize(Frame(n).to_world(square_to_cosine_hemisphere(rng.next_2d())));
      bounce.o = offset_ray_origin(hit.p, hit.p_error, n, bounce.d);
      sets[1].rays.push_back(bounce);
      glm::vec3 target;
      target[up] = b.hi[up];
      target[u] = b.lo[u] + rng.next_float() * (b.hi[u] - b.lo[u]);
      target[v] = b.lo[v] + rng.next_float() * (b.hi[v] - b.lo[v]);
      Ray shadow;
      shadow.o = offset_ray_origin(hit.p, hit.p_error, n, target - hit.p);
      const float dist = glm::length(target - shadow.o);
      if (!(dist > 0.0f)) continue;
      shadow.d = (target - shadow.o) / dist;
      shadow.tmax = dist * (1.0f - 0x1p-12f);
      sets[2].rays.push_back(shadow);
    }
  return sets;
}

/// Times `tracer` on every set at every thread count; adds the figures to *out.
void time_sets(const Tracer& tracer, const std::vector<RaySet>& sets,
               const std::vector<int>& threads, double min_seconds, json* out,
               std::vector<std::vector<float>>* first_answers) {
  first_answers->assign(sets.size(), {});
  for (size_t s = 0; s < sets.size(); ++s) {
    json per_thread;
    for (int t : threads) {
      std::vector<float> answers;
      per_thread[std::to_string(t)] = measure(tracer, sets[s], t, min_seconds, &answers);
      if ((*first_answers)[s].empty()) (*first_answers)[s] = std::move(answers);
    }
    (*out)[sets[s].name] = per_thread;
  }
}

json ratio(const json& a, const json& b) {
  json r;
  for (auto set = a.begin(); set != a.end(); ++set)
    for (auto t = set.value().begin(); t != set.value().end(); ++t) {
      const double d = b[set.key()][t.key()].get<double>();
      r[set.key()][t.key()] = d > 0.0 ? t.value().get<double>() / d : 0.0;
    }
  return r;
}

/// Per set, Mrays/s on the most threads timed over Mrays/s on one thread (when both were timed).
json speedup_over_one_thread(const json& mrays) {
  json r = json::object();
  for (auto set = mrays.begin(); set != mrays.end(); ++set) {
    int most = 1;
    for (auto t = set.value().begin(); t != set.value().end(); ++t)
      most = std::max(most, std::stoi(t.key()));
    const json& per = set.value();
    if (most > 1 && per.contains("1") && per["1"].get<double>() > 0.0)
      r[set.key()] = {{"threads", most},
                      {"speedup", per[std::to_string(most)].get<double>() / per["1"].get<double>()}};
  }
  return r;
}

json bvh_stats_json(const BvhStats& s, int leaf) {
  return {{"split", s.split == BvhSplitMethod::sah ? "sah" : "median"},
          {"leaf_size", leaf},
          {"build_ms", s.build_ms},
          {"nodes", s.nodes},
          {"leaves", s.leaves},
          {"depth", s.depth},
          {"sah_cost", s.sah_cost}};
}

int run(int argc, char** argv) {
  // bench --convergence SCENE is a study of its own (error against time), with its own options.
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]).rfind("--convergence", 0) == 0) return convergence_main(argc, argv);
  // bench --agreement SCENE... renders each strategy at full resolution and compares them.
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]).rfind("--agreement", 0) == 0) return agreement_main(argc, argv);
  CLI::App app{"bench: BVH build time and rays per second (primary, diffuse, shadow) as JSON"};
  app.footer("Studies with options of their own: bench --convergence SCENE --help (error against "
             "time per strategy), bench --agreement SCENE... --help (do the strategies render one "
             "image?)");
  std::string scene_path, rays_prefix, write_prefix, split = "sah";
  int leaf = 4, width = 640, height = 480;
  bool embree = false, wide = false;
  double min_seconds = 1.0;
  uint64_t seed = 1;
  std::vector<int> threads;
  app.add_option("scene", scene_path, "COLLADA scene (.dae)")->required();
  app.add_option("--rays", rays_prefix,
                 "read PREFIX.{primary,diffuse,shadow}.rays (and .hits answers, where present) "
                 "instead of making the sets from the scene");
  app.add_option("--write-rays", write_prefix, "write the sets made from the scene to PREFIX.*.rays");
  app.add_option("--bvh", split, "split heuristic: sah, median, or both (and their ratio)")
      ->check(CLI::IsMember({"sah", "median", "both"}));
  app.add_option("--leaf-size", leaf, "largest leaf")->check(CLI::Range(1, Bvh::kMaxLeafSize));
  app.add_option("-r,--resolution", width, "width of the primary set made from the scene")
      ->check(CLI::Range(1, 1 << 14));
  app.add_option("--threads", threads, "thread counts to time (default: 1 and every core)");
  app.add_option("--min-seconds", min_seconds, "time each measurement for at least this long")
      ->check(CLI::Range(0.0, 600.0));
  app.add_option("--seed", seed, "seed of the diffuse and shadow sets made from the scene");
  app.add_flag("--wide", wide,
               "also time the app's wide BVH (8 children a node) collapsed from the first "
               "tree (\"wide\"): "
               "its nearest query (primitive, t, barycentrics: what rtcIntersect1 reports) is what "
               "is compared with Embree; its full intersect (the SurfaceHit a renderer shades) is "
               "timed and reported apart, as is the binary tree, which has only the full intersect");
  app.add_flag("--embree", embree,
               "also trace the same rays with Intel Embree (rtcIntersect1 / rtcOccluded1) and print "
               "the ratios");
  CLI11_PARSE(app, argc, argv);
  height = std::max(1, width * 3 / 4);

  if (threads.empty()) threads = {1, int(std::max(1u, std::thread::hardware_concurrency()))};
  for (int t : threads)
    if (t < 1) throw std::runtime_error("--threads: " + std::to_string(t) + " is not a thread count");

  Scene scene = load_collada(scene_path, [](const std::string& w) { std::cerr << "warning: " << w << "\n"; });
  const size_t spheres = scene.spheres.size();
  scene.spheres.clear();  // the ray sets count triangles only (rays-format.md)
  // Both before the others are made, so that both time the same rays and a build is not
  // charged for a cold page cache.
  json out;
  out["scene"] = scene_path;
  out["triangles"] = scene.triangles.size();
  if (spheres) out["spheres_ignored"] = spheres;
  out["threads"] = threads;

  std::vector<BvhSplitMethod> methods;
  if (split != "median") methods.push_back(BvhSplitMethod::sah);
  if (split != "sah") methods.push_back(BvhSplitMethod::median);
  std::vector<std::unique_ptr<Bvh>> bvhs;
  for (BvhSplitMethod m : methods) {
    BvhOptions o;
    o.split = m;
    o.max_leaf_size = leaf;
    bvhs.push_back(std::make_unique<Bvh>(scene, o));
  }

  std::vector<RaySet> sets;
  if (!rays_prefix.empty()) {
    out["rays"] = rays_prefix;
    for (const char* name : kSets) {
      RaySet set;
      set.name = name;
      set.occlusion = std::string(name) == "shadow";
      set.rays = read_ray_set(rays_prefix + "." + name + ".rays");
      const std::string hits = rays_prefix + "." + name + ".hits";
      if (std::ifstream(hits).good()) {
        set.answers = read_hit_set(hits);
        if (set.answers.size() != set.rays.size())
          throw std::runtime_error(hits + ": " + std::to_string(set.answers.size()) +
                                   " answers for " + std::to_string(set.rays.size()) + " rays");
      }
      sets.push_back(std::move(set));
    }
  } else {
    out["rays"] = "made from the scene, " + std::to_string(width) + "x" + std::to_string(height) +
                  ", seed " + std::to_string(seed);
    sets = make_sets(scene, *bvhs.front(), width, height, seed);
    if (!write_prefix.empty())
      for (const RaySet& s : sets) write_ray_set(write_prefix + "." + s.name + ".rays", s.rays);
  }
  for (const RaySet& s : sets) out["ray_counts"][s.name] = s.rays.size();

  std::vector<json> mrays(bvhs.size());
  std::vector<std::vector<float>> ours;
  for (size_t k = 0; k < bvhs.size(); ++k) {
    json entry = bvh_stats_json(bvhs[k]->stats(), leaf);
    entry["query"] = kFullQuery;
    std::vector<std::vector<float>> answers;
    time_sets(BvhTracer(*bvhs[k]), sets, threads, min_seconds, &mrays[k], &answers);
    entry["mrays_per_s"] = mrays[k];
    entry["speedup"] = speedup_over_one_thread(mrays[k]);
    json agreement;
    for (size_t s = 0; s < sets.size(); ++s)
      if (!sets[s].answers.empty())
        agreement[sets[s].name] = {
            {"rays", sets[s].rays.size()},
            {"agree", count_agreeing(answers[s], sets[s].answers, sets[s].occlusion)}};
    if (!agreement.is_null()) entry["agreement_with_answer_files"] = agreement;
    out[k == 0 && methods[0] == BvhSplitMethod::sah ? "sah" : "median"] = entry;
    if (k == 0) ours = std::move(answers);
  }
  if (bvhs.size() == 2) out["sah_over_median"] = ratio(mrays[0], mrays[1]);

  json wide_mrays, wide_full_mrays;
#ifndef PT_HAVE_WIDE_BVH
  if (wide) throw std::runtime_error("--wide: the wide BVH is not in this build (the handout)");
#else
  if (wide) {
    const WideBvh wide_bvh(scene, *bvhs.front());
    const WideBvhStats& ws = wide_bvh.stats();
    json entry = {{"from", methods[0] == BvhSplitMethod::sah ? "sah" : "median"},
                  {"collapse_ms", ws.build_ms},
                  {"nodes", ws.nodes},
                  {"leaves", ws.leaves},
                  {"depth", ws.depth},
                  {"mean_children", ws.mean_children}};
    /// The wide tree's nearest query: what rtcIntersect1 reports, no SurfaceHit made.
    class NearestTracer final : public Tracer {
     public:
      explicit NearestTracer(const WideBvh& bvh) : bvh_(bvh) {}
      float trace(const Ray& ray, bool occlusion) const override {
        if (occlusion) return bvh_.occluded(ray) ? 1.0f : 0.0f;
        NearestHit hit;
        return bvh_.nearest(ray, &hit) ? hit.t : std::numeric_limits<float>::infinity();
      }

     private:
      const WideBvh& bvh_;
    };
    std::vector<std::vector<float>> answers, full_answers;
    time_sets(NearestTracer(wide_bvh), sets, threads, min_seconds, &wide_mrays, &answers);
    entry["query"] = kNearestQuery;
    entry["mrays_per_s"] = wide_mrays;
    // The full intersect, which the renderer calls, on the sets it differs on.
    std::vector<RaySet> nearest_sets;
    for (const RaySet& s : sets)
      if (!s.occlusion) nearest_sets.push_back(s);
    time_sets(BvhTracer(wide_bvh), nearest_sets, threads, min_seconds, &wide_full_mrays,
              &full_answers);
    entry["full_intersect"] = {{"query", kFullQuery},
                               {"mrays_per_s", wide_full_mrays},
                               {"over_binary", ratio(wide_full_mrays, mrays[0])}};
    entry["over_binary"] = ratio(wide_mrays, mrays[0]);
    // The wide tree answers exactly as the binary one: every t equal, not merely close.
    json same;
    for (size_t s = 0, f = 0; s < sets.size(); ++s) {
      size_t n = 0, n_full = 0;
      for (size_t i = 0; i < answers[s].size(); ++i) n += answers[s][i] == ours[s][i];
      same[sets[s].name] = {{"rays", sets[s].rays.size()}, {"identical_to_binary", n}};
      if (sets[s].occlusion) continue;
      for (size_t i = 0; i < full_answers[f].size(); ++i) n_full += full_answers[f][i] == ours[s][i];
      same[sets[s].name]["full_intersect_identical_to_binary"] = n_full;
      ++f;
    }
    entry["agreement_with_binary"] = same;
    entry["width"] = WideNode::kWidth;
    out["wide"] = entry;
  }
#endif

  if (embree) {
#ifdef PT_HAVE_EMBREE
    const EmbreeTracer tracer(scene);
    json e, em;
    std::vector<std::vector<float>> answers;
    time_sets(tracer, sets, threads, min_seconds, &em, &answers);
    e["version"] = RTC_VERSION_STRING;
    e["calls"] = "rtcIntersect1 / rtcOccluded1";
    e["query"] = kNearestQuery;
    e["build_ms"] = tracer.build_ms();
    e["mrays_per_s"] = em;
    e["ours_over_embree"] = ratio(mrays[0], em);
    if (wide) {
      e["wide_over_embree"] = ratio(wide_mrays, em);
      e["wide_full_intersect_over_embree"] = ratio(wide_full_mrays, em);
    }
    json agreement;
    for (size_t s = 0; s < sets.size(); ++s)
      agreement[sets[s].name] = {{"rays", sets[s].rays.size()},
                                 {"agree", count_agreeing(ours[s], answers[s], sets[s].occlusion)}};
    e["agreement_with_ours"] = agreement;
    out["embree"] = e;
#else
    std::cerr << "bench: --embree: this bench was built without Embree (Embree 3 was not found "
                 "when CMake configured the project; install libembree-dev and reconfigure)\n";
    out["embree"] = {{"available", false}, {"reason", "built without Embree"}};
#endif
  }
  std::cout << out.dump(2) << std::endl;
  return 0;
}

}  // namespace
}  // namespace pt

int main(int argc, char** argv) {
  try {
    return pt::run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "bench: " << e.what() << "\n";
    return 1;
  }
}
