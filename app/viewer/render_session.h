// The viewer's scene and its render: loaded from the one file named on the command line, rendered
// again whenever the page asks, on a thread of its own so the server keeps answering.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/command_line.h"
#include "framework/geometry/ray_query.h"
#include "framework/render/film.h"
#include "framework/scene/scene.h"
#include "parts/2-bvh/bvh.h"

namespace pt {

/// A render's settings as the page asked for them, parsed by the pathtracer's own command line
/// (so the page takes exactly the flags the pathtracer takes, and says what it would run).
struct ViewerRender {
  CommandLine command;
  std::vector<std::string> flags;  ///< as the page sent them
};

/// Parses the page's flags with the pathtracer's parser, after refusing those that name files or
/// print instead of rendering (-f, -e, --info, --help, -t: the viewer's threads are fixed when it
/// starts). Throws std::invalid_argument with the parser's message.
ViewerRender parse_viewer_flags(const std::vector<std::string>& flags, const std::string& scene_path,
                                int threads);

/// One scene, its render and what the page inspects of it. Every member may be called from any
/// of the server's threads.
class RenderSession {
 public:
  RenderSession(std::string scene_path, int threads);
  ~RenderSession();

  /// (Re)reads the scene file, after stopping a render in flight. On failure the message (file,
  /// element, what is wrong) is kept for status() and returned in *error. With `warm_up`, the
  /// first render's tree (the student's Part 2) is built now rather than when it is asked for.
  bool load(std::string* error, bool warm_up = true);

  /// Starts a render with these flags, stopping the one in flight (its pixels stay on the page
  /// until new ones replace them). A -p cell renders again only the cell, over the last image
  /// when it has the same size. Throws std::invalid_argument for flags the command line refuses.
  void start(const std::vector<std::string>& flags);
  /// Stops the render in flight, if any, and waits for its threads.
  void cancel();
  /// Waits until the render in flight has finished `pixels` pixels (or all of its region), has
  /// ended, or `limit_ms` has passed: the page's first image is then one request away, rather
  /// than a status poll and a request.
  void wait_for_pixels(long pixels, int limit_ms) const;

  /// The state for the page: "empty" (no scene), "idle", "rendering", "done", "cancelled" or
  /// "error", with the progress, the summary line, the command line and any error.
  nlohmann::json status() const;
  /// The image so far, 8-bit sRGB RGBA (the bytes the pathtracer's PNG holds, alpha 255), and
  /// its size in *width, *height; or the sample-rate image of the last finished render.
  std::vector<uint8_t> image_rgba(bool sample_rate, int* width, int* height);

  /// The scene for the preview: triangles, spheres, materials, lights, the camera a render with
  /// `flags` would use, and the scene's description.
  nlohmann::json scene_json(const std::vector<std::string>& flags);
  /// Part 2's tree, as the student's build makes it with `flags`' --bvh and --leaf-size: every
  /// node's box, children, primitive count, depth and SAH cost, and the primitives in leaf order.
  nlohmann::json bvh_json(const std::vector<std::string>& flags);
  /// The ray from `origin` along `direction` through Part 2's tree (the student's traversal):
  /// its hit, and the leaf that holds the primitive hit.
  nlohmann::json pick(const std::vector<std::string>& flags, const glm::vec3& origin,
                      const glm::vec3& direction);
  /// Pixel (x, y) of a render with `flags`, sample by sample as the render takes it (the same
  /// random numbers): each sample's rays (camera, bounce, shadow: blocked or not) and what each
  /// bounce added.
  nlohmann::json explain_pixel(const std::vector<std::string>& flags, int x, int y);

 private:
  struct Job;
  void run(std::shared_ptr<Job> job);
  /// The camera a render with these settings uses, placed as the pathtracer places it.
  Camera placed_camera(ViewerRender& render) const;
  const Bvh& inspection_bvh(const RenderSettings& settings);
  const RayQuery& render_query(const RenderSettings& settings);

  const std::string scene_path_;
  const int threads_;

  mutable std::shared_mutex scene_mutex_;  ///< shared by readers of the scene, unique to load()
  std::unique_ptr<Scene> scene_;
  std::string load_error_;

  std::mutex query_mutex_;  ///< the cached trees below
  std::unique_ptr<RayQuery> query_;
  std::string query_key_;
  std::unique_ptr<Bvh> bvh_;
  std::string bvh_key_;

  mutable std::mutex job_mutex_;  ///< job_, thread_, rgba_
  std::shared_ptr<Job> job_;
  std::thread thread_;
  std::vector<uint8_t> rgba_;
  int rgba_width_ = 0, rgba_height_ = 0;
};

}  // namespace pt
