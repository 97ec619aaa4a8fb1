// render_job: the rays a render reports are every ray it traced, not only the camera's.
#include "app/render_job.h"

#include "app/accelerator.h"
#include "app/radiance.h"

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

/// The project's Cornell box, loaded once for every test here.
const Scene& cornell() {
  static const Scene scene =
      load_collada(std::string(pt::test::source_dir()) + "/scenes/cornell_spheres.dae");
  return scene;
}

/// `settings` made small: 24 x 18 pixels on two threads.
RenderSettings small(RenderSettings settings) {
  settings.width = 24;
  settings.height = 18;
  settings.threads = 2;
  return settings;
}

/// Renders the project's Cornell box small through a counting query of its own, so the count the
/// render reports can be compared with the calls the query really received.
Counted render_cornell(RenderSettings settings) {
  settings = small(settings);
  const std::unique_ptr<RayQuery> query = make_ray_query(settings, cornell());
  const CountingRayQuery outer(*query);
  Film film(settings.width, settings.height);
  const RenderReport report = render_scene(settings, cornell(), outer, &film);
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
  const Scene& scene = cornell();
  for (int width : {2, 8}) {
    RenderSettings s = small({});
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

// The report tells the kinds apart: one camera ray a sample, the shadow rays the occlusion
// queries, the same counts on the tree's own type (where shadow rays go in packets) as through a
// counter of another type; and its line says so.
TEST(RenderJob, RaysAreToldApartByKind) {
  const Scene& scene = cornell();
  RenderSettings s = small({});
  s.samples_per_pixel = 2;
  s.light_samples = 16;
  s.max_depth = 3;
  const std::unique_ptr<RayQuery> query = make_ray_query(s, scene);
  Film film(s.width, s.height), counted_film(s.width, s.height);
  const RenderReport direct = render_scene(s, scene, *query, &film);
  const CountingRayQuery outer(*query);
  const RenderReport counted = render_scene(s, scene, outer, &counted_film);
  EXPECT_EQ(direct.camera_rays, uint64_t(24 * 18 * 2));
  EXPECT_GT(direct.shadow_rays, 16 * direct.camera_rays / 4) << "a shadow ray per light sample";
  EXPECT_LT(direct.camera_rays + direct.shadow_rays, direct.rays) << "bounces besides";
  EXPECT_EQ(direct.camera_rays, counted.camera_rays);
  EXPECT_EQ(direct.shadow_rays, counted.shadow_rays);
  EXPECT_EQ(direct.rays, counted.rays);
  EXPECT_EQ(counted.packets, 0u) << "only the wide tree's own walk traces packets";
#if defined(PT_HAVE_WIDE_BVH) && defined(PT_HAVE_FAST_LIGHTS) && defined(__AVX2__)
  EXPECT_GT(direct.packets, 0u);
#endif
  EXPECT_LE(direct.packet_rays, 8 * direct.packets);
  const std::string line = ray_kinds_line(direct);
  EXPECT_EQ(line.rfind("rays: camera ", 0), 0u) << line;
  EXPECT_NE(line.find(direct.packets > 0 ? "rays a packet" : "no shadow packets"), std::string::npos)
      << line;
}

}  // namespace
}  // namespace pt
