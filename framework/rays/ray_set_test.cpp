// Not needed for the assignment.
// Ray set files: what is written reads back bit for bit, and broken files are refused by name.
#include "framework/rays/ray_set.h"
#include "framework/testing/test_paths.h"

#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace pt {
namespace {

std::string temp_path(const std::string& name) {
  return std::string(pt::test::binary_dir()) + "/ray_set_test_" + name;
}

TEST(RaySetFile, RaysAndHitsRoundTrip) {
  std::vector<Ray> rays(3);
  rays[0] = {glm::vec3(1, 2, 3), glm::vec3(0, 0, -1), 0.0f,
             std::numeric_limits<float>::infinity()};
  rays[1] = {glm::vec3(-1e-30f, 7, 0), glm::vec3(0.6f, 0.8f, 0), 1e-4f, 5.0f};
  rays[2] = {glm::vec3(0), glm::vec3(1, 0, 0), 0.25f, 0.5f};
  const std::string rp = temp_path("a.rays"), hp = temp_path("a.hits");
  write_ray_set(rp, rays);
  const std::vector<Ray> back = read_ray_set(rp);
  ASSERT_EQ(back.size(), rays.size());
  for (size_t i = 0; i < rays.size(); ++i) {
    EXPECT_EQ(back[i].o, rays[i].o);
    EXPECT_EQ(back[i].d, rays[i].d);
    EXPECT_EQ(back[i].tmin, rays[i].tmin);
    EXPECT_EQ(back[i].tmax, rays[i].tmax);
  }
  const std::vector<float> hits = {1.5f, std::numeric_limits<float>::infinity(), 0.0f};
  write_hit_set(hp, hits);
  EXPECT_EQ(read_hit_set(hp), hits);
  std::remove(rp.c_str());
  std::remove(hp.c_str());
}

void expect_refused(const std::string& path, const std::string& what) {
  try {
    read_ray_set(path);
    ADD_FAILURE() << "accepted " << path;
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find(what), std::string::npos) << msg;
  }
}

TEST(RaySetFile, BrokenFilesAreRefusedByName) {
  const std::string p = temp_path("broken.rays");
  expect_refused(temp_path("missing.rays"), "cannot open");
  write_hit_set(p, {1.0f});
  expect_refused(p, "PTRAYS01");
  std::vector<Ray> rays(2);
  write_ray_set(p, rays);
  {  // cut the last ray short
    std::ifstream in(p, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size() - 4));
  }
  expect_refused(p, "bytes follow");
  rays[1].o.x = std::numeric_limits<float>::quiet_NaN();
  write_ray_set(p, rays);
  expect_refused(p, "ray 1");
  std::remove(p.c_str());
}

}  // namespace
}  // namespace pt
