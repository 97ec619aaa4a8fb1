// render_job: the rays a render reports are every ray it traced, not only the camera's.
#include "app/render_job.h"

#include "app/accelerator.h"

#include <gtest/gtest.h>

#include "framework/geometry/counting_ray_query.h"
#include "framework/scene/collada_loader.h"
#include "framework/testing/test_paths.h"

namespace pt {
namespace {

struct Counted {
  uint64_t reported = 0;  ///< what the render's summary would say
  uint64_t traced = 0;    ///< what actually reached the ray query
};

/// Renders the project's Cornell box small through a counting query of its own, so the count the
/// render reports can be compared with the calls the query really received.
Counted render_cornell(RenderSettings settings) {
  const Scene scene = load_collada(std::string(pt::test::source_dir()) + "/scenes/cornell_spheres.dae");
  settings.width = 24;
  settings.height = 18;
  settings.threads = 2;
  const std::unique_ptr<RayQuery> query = make_ray_query(settings, scene);
  const CountingRayQuery outer(*query);
  Film film(settings.width, settings.height);
  const RenderReport report = render_scene(settings, scene, outer, &film);
  return {report.rays, outer.total()};
}

TEST(RenderJob, NormalsViewTracesOneRayPerSample) {
  RenderSettings s;
  s.shading = ShadingMode::normals;
  s.samples_per_pixel = 3;
  const Counted c = render_cornell(s);
  EXPECT_EQ(c.reported, uint64_t(24 * 18 * 3));
  EXPECT_EQ(c.traced, c.reported);
}

TEST(RenderJob, ShadowAndBounceRaysAreCounted) {
  RenderSettings s;
  s.samples_per_pixel = 2;
  s.light_samples = 2;
  s.max_depth = 3;
  const Counted c = render_cornell(s);
  // Camera rays alone would be 24·18·2; every diffuse hit adds shadow rays and bounces.
  EXPECT_GT(c.reported, uint64_t(2 * 24 * 18 * 2));
  EXPECT_EQ(c.reported, c.traced);
}

// A render straight on the wide tree counts its rays without the counter above (on the tree's own
// type); the same render, same seed, through that counter traces the same rays.
TEST(RenderJob, ARenderOnTheQueryItselfReportsTheRaysItTraced) {
  const Scene scene = load_collada(std::string(pt::test::source_dir()) + "/scenes/cornell_spheres.dae");
  for (int width : {2, 8}) {
    RenderSettings s;
    s.width = 24;
    s.height = 18;
    s.threads = 2;
    s.samples_per_pixel = 2;
    s.light_samples = 2;
    s.max_depth = 3;
    s.bvh_width = width;
    const std::unique_ptr<RayQuery> query = make_ray_query(s, scene);
    Film direct_film(s.width, s.height);
    const RenderReport direct = render_scene(s, scene, *query, &direct_film);
    const Counted counted = render_cornell(s);
    EXPECT_GT(direct.rays, uint64_t(2 * 24 * 18 * 2)) << "bvh width " << width;
    EXPECT_EQ(direct.rays, counted.traced) << "bvh width " << width;
  }
}

}  // namespace
}  // namespace pt
