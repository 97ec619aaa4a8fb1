#include "app/ray_benchmark.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
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
/// millions of rays per second, and the answers of the first pass in *answers (when not null).
double measure(const Tracer& tracer, const RaySet& set, int threads, double min_seconds,
               std::vector<float>* answers) {
  std::vector<float> scratch(set.rays.size(), 0.0f);
  std::vector<float>& out = answers ? *answers : scratch;
  out.assign(set.rays.size(), 0.0f);
  tbb::task_arena arena(threads);
  size_t traced = 0;
  const auto start = Clock::now();
  double seconds = 0.0;
  do {
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, set.rays.size(), 1024),
                        [&](const tbb::blocked_range<size_t>& r) {
                          for (size_t i = r.begin(); i < r.end(); ++i)
                            out[i] = tracer.trace(set.rays[i], set.occlusion);
                        });
    });
    traced += set.rays.size();
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
  } while (seconds < min_seconds && !set.rays.empty());
  return seconds > 0.0 ? double(traced) / seconds * 1e-6 : 0.0;
}

/// A tracer timed by bench under a JSON key, on every set or on the nearest-hit sets only.
struct TimedTracer {
  std::string key;
  const Tracer* tracer = nullptr;
  bool occlusion_sets = true;
  /// Per set and thread count, Mrays/s of each round; and per set the first answers.
  std::map<std::string, std::map<int, std::vector<double>>> rounds;
  std::vector<std::vector<float>> answers;
};

/// Times every tracer on every set at every thread count, round by round: in each round each
/// tracer traces the set (for at least min_seconds) once, the tracers taking turns in an order that
/// rotates from round to round, so a change in the machine's load falls on all of them alike and
/// a ratio of two tracers is taken between runs made seconds apart.
void time_interleaved(std::vector<TimedTracer>* tracers, const std::vector<RaySet>& sets,
                      const std::vector<int>& threads, int rounds, double min_seconds) {
  for (TimedTracer& t : *tracers) t.answers.assign(sets.size(), {});
  for (size_t s = 0; s < sets.size(); ++s)
    for (int th : threads)
      for (int r = 0; r < rounds; ++r)
        for (size_t k = 0; k < tracers->size(); ++k) {
          TimedTracer& t = (*tracers)[(k + size_t(r)) % tracers->size()];
          if (sets[s].occlusion && !t.occlusion_sets) continue;
          std::vector<float>* answers = t.answers[s].empty() ? &t.answers[s] : nullptr;
          t.rounds[sets[s].name][th].push_back(measure(*t.tracer, sets[s], th, min_seconds, answers));
        }
}

double median_of(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// Per set and thread count, the median of the rounds' Mrays/s.
json median_mrays(const TimedTracer& t) {
  json out = json::object();
  for (const auto& [set, per_thread] : t.rounds)
    for (const auto& [th, rounds] : per_thread) out[set][std::to_string(th)] = median_of(rounds);
  return out;
}

/// Per set and thread count that both timed, a's Mrays/s over b's round by round: the median
/// and the range of those ratios, and how many rounds they come from.
json round_ratios(const TimedTracer& a, const TimedTracer& b) {
  json out = json::object();
  for (const auto& [set, per_thread] : a.rounds) {
    const auto other = b.rounds.find(set);
    if (other == b.rounds.end()) continue;
    for (const auto& [th, ra] : per_thread) {
      const auto rb = other->second.find(th);
      if (rb == other->second.end()) continue;
      std::vector<double> ratios;
      for (size_t r = 0; r < std::min(ra.size(), rb->second.size()); ++r)
        if (rb->second[r] > 0.0) ratios.push_back(ra[r] / rb->second[r]);
      if (ratios.empty()) continue;
      out[set][std::to_string(th)] = {
          {"median", median_of(ratios)},
          {"min", *std::min_element(ratios.begin(), ratios.end())},
          {"max", *std::max_element(ratios.begin(), ratios.end())},
          {"rounds", ratios.size()}};
    }
  }
  return out;
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

/// What `bench rays` was asked for.
struct RaysOptions {
  std::string scene_path, rays_prefix, write_prefix, split = "sah";
  int leaf = 4, width = 640;
  bool embree = false, wide = false;
  double min_seconds = 0.2;
  int rounds = 5;
  uint64_t seed = 1;
  std::vector<int> threads;
};

int ray_benchmark(RaysOptions o) {
  const std::string& scene_path = o.scene_path;
  const std::string& rays_prefix = o.rays_prefix;
  const std::string& write_prefix = o.write_prefix;
  const std::string& split = o.split;
  const int leaf = o.leaf, width = o.width, rounds = o.rounds;
  const bool embree = o.embree, wide = o.wide;
  const double min_seconds = o.min_seconds;
  const uint64_t seed = o.seed;
  std::vector<int>& threads = o.threads;
  const int height = std::max(1, width * 3 / 4);

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

  // Every tracer is made first and then timed round by round (time_interleaved), so the ratios
  // between them hold on a machine whose load changes while bench runs.
  std::vector<std::unique_ptr<Tracer>> owned;
  std::vector<TimedTracer> timed;
  auto add = [&](const std::string& key, std::unique_ptr<Tracer> tracer, bool occlusion_sets) {
    TimedTracer t;
    t.key = key;
    t.tracer = tracer.get();
    t.occlusion_sets = occlusion_sets;
    owned.push_back(std::move(tracer));
    timed.push_back(std::move(t));
  };
  auto find = [&](const std::string& key) -> const TimedTracer* {
    for (const TimedTracer& t : timed)
      if (t.key == key) return &t;
    return nullptr;
  };
  std::vector<std::string> binary_keys;
  for (size_t k = 0; k < bvhs.size(); ++k) {
    binary_keys.push_back(methods[k] == BvhSplitMethod::sah ? "sah" : "median");
    add(binary_keys.back(), std::make_unique<BvhTracer>(*bvhs[k]), true);
  }

#ifndef PT_HAVE_WIDE_BVH
  if (wide) throw std::runtime_error("--wide: the wide BVH is not in this build (the handout)");
#else
  std::unique_ptr<WideBvh> wide_bvh;
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
  if (wide) {
    wide_bvh = std::make_unique<WideBvh>(scene, *bvhs.front());
    add("wide", std::make_unique<NearestTracer>(*wide_bvh), true);
    // The full intersect, which the renderer calls, on the sets it differs on.
    add("wide_full", std::make_unique<BvhTracer>(*wide_bvh), false);
  }
#endif

#ifdef PT_HAVE_EMBREE
  std::unique_ptr<EmbreeTracer> embree_tracer;
  if (embree) {
    embree_tracer = std::make_unique<EmbreeTracer>(scene);
    TimedTracer t;
    t.key = "embree";
    t.tracer = embree_tracer.get();
    timed.push_back(std::move(t));
  }
#endif

  time_interleaved(&timed, sets, threads, rounds, min_seconds);
  out["timing"] = {{"rounds", rounds},
                   {"min_seconds_per_tracer_and_round", min_seconds},
                   {"method", "every tracer traces each set once a round, in an order rotating from "
                              "round to round; Mrays/s are the rounds' median, ratios the median "
                              "(and range) of the rounds' ratios"}};

  const std::vector<std::vector<float>>& ours = find(binary_keys.front())->answers;
  for (size_t k = 0; k < bvhs.size(); ++k) {
    const TimedTracer& t = *find(binary_keys[k]);
    json entry = bvh_stats_json(bvhs[k]->stats(), leaf);
    entry["query"] = kFullQuery;
    entry["mrays_per_s"] = median_mrays(t);
    entry["speedup"] = speedup_over_one_thread(entry["mrays_per_s"]);
    json agreement;
    for (size_t s = 0; s < sets.size(); ++s)
      if (!sets[s].answers.empty())
        agreement[sets[s].name] = {
            {"rays", sets[s].rays.size()},
            {"agree", count_agreeing(t.answers[s], sets[s].answers, sets[s].occlusion)}};
    if (!agreement.is_null()) entry["agreement_with_answer_files"] = agreement;
    out[binary_keys[k]] = entry;
  }
  if (bvhs.size() == 2) out["sah_over_median"] = round_ratios(*find("sah"), *find("median"));

#ifdef PT_HAVE_WIDE_BVH
  if (wide) {
    const TimedTracer& near = *find("wide");
    const TimedTracer& full = *find("wide_full");
    const WideBvhStats& ws = wide_bvh->stats();
    json entry = {{"from", binary_keys.front()},
                  {"collapse_ms", ws.build_ms},
                  {"nodes", ws.nodes},
                  {"leaves", ws.leaves},
                  {"depth", ws.depth},
                  {"mean_children", ws.mean_children}};
    entry["query"] = kNearestQuery;
    entry["mrays_per_s"] = median_mrays(near);
    entry["full_intersect"] = {{"query", kFullQuery},
                               {"mrays_per_s", median_mrays(full)},
                               {"over_binary", round_ratios(full, *find(binary_keys.front()))}};
    entry["over_binary"] = round_ratios(near, *find(binary_keys.front()));
    // The wide tree answers exactly as the binary one: every t equal, not merely close.
    json same;
    for (size_t s = 0; s < sets.size(); ++s) {
      size_t n = 0, n_full = 0;
      for (size_t i = 0; i < near.answers[s].size(); ++i) n += near.answers[s][i] == ours[s][i];
      same[sets[s].name] = {{"rays", sets[s].rays.size()}, {"identical_to_binary", n}};
      if (sets[s].occlusion) continue;
      for (size_t i = 0; i < full.answers[s].size(); ++i) n_full += full.answers[s][i] == ours[s][i];
      same[sets[s].name]["full_intersect_identical_to_binary"] = n_full;
    }
    entry["agreement_with_binary"] = same;
    entry["width"] = WideNode::kWidth;
    out["wide"] = entry;
  }
#endif

  if (embree) {
#ifdef PT_HAVE_EMBREE
    const TimedTracer& em = *find("embree");
    json e;
    e["version"] = RTC_VERSION_STRING;
    e["calls"] = "rtcIntersect1 / rtcOccluded1";
    e["query"] = kNearestQuery;
    e["build_ms"] = embree_tracer->build_ms();
    e["mrays_per_s"] = median_mrays(em);
    e["ours_over_embree"] = round_ratios(*find(binary_keys.front()), em);
    if (wide) {
      e["wide_over_embree"] = round_ratios(*find("wide"), em);
      e["wide_full_intersect_over_embree"] = round_ratios(*find("wide_full"), em);
    }
    json agreement;
    for (size_t s = 0; s < sets.size(); ++s)
      agreement[sets[s].name] = {{"rays", sets[s].rays.size()},
                                 {"agree", count_agreeing(ours[s], em.answers[s], sets[s].occlusion)}};
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

BenchCommand add_rays_command(CLI::App& bench) {
  auto o = std::make_shared<RaysOptions>();
  CLI::App* app = bench.add_subcommand(
      "rays", "BVH build time and rays per second (primary, diffuse, shadow) as JSON, with "
              "Intel Embree on the same rays when asked");
  app->add_option("scene", o->scene_path, "COLLADA scene (.dae)")->required();
  app->add_option("--rays", o->rays_prefix,
                  "read PREFIX.{primary,diffuse,shadow}.rays (and .hits answers, where present) "
                  "instead of making the sets from the scene");
  app->add_option("--write-rays", o->write_prefix, "write the sets made from the scene to PREFIX.*.rays");
  app->add_option("--bvh", o->split, "split heuristic: sah, median, or both (and their ratio)")
      ->check(CLI::IsMember({"sah", "median", "both"}));
  app->add_option("--leaf-size", o->leaf, "largest leaf")->check(CLI::Range(1, Bvh::kMaxLeafSize));
  app->add_option("-r,--resolution", o->width, "width of the primary set made from the scene")
      ->check(CLI::Range(1, 1 << 14));
  app->add_option("--threads", o->threads, "thread counts to time (default: 1 and every core)");
  app->add_option("--min-seconds", o->min_seconds,
                  "time each tracer for at least this long in each round (default 0.2)")
      ->check(CLI::Range(0.0, 600.0));
  app->add_option("--rounds", o->rounds,
                  "rounds of timing: in each, every tracer traces each set in turn (the order "
                  "rotating), and ratios are taken round by round; medians and ranges are printed")
      ->check(CLI::Range(1, 1000));
  app->add_option("--seed", o->seed, "seed of the diffuse and shadow sets made from the scene");
  app->add_flag("--wide", o->wide,
                "also time the app's wide BVH (8 children a node) collapsed from the first "
                "tree (\"wide\"): "
                "its nearest query (primitive, t, barycentrics: what rtcIntersect1 reports) is what "
                "is compared with Embree; its full intersect (the SurfaceHit a renderer shades) is "
                "timed and reported apart, as is the binary tree, which has only the full intersect");
  app->add_flag("--embree", o->embree,
                "also trace the same rays with Intel Embree (rtcIntersect1 / rtcOccluded1) and print "
                "the ratios");
  return {app, [o] { return ray_benchmark(*o); }};
}

}  // namespace pt
