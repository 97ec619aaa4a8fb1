// Not needed for the assignment.
// The film's memory: what a pixel costs, what a render of a given size needs at its peak, what
// the process may still take; and a film written straight from its statistics is the very file
// the whole-image copies made.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "framework/image/estimate_exr.h"
#include "framework/image/image.h"
#include "framework/render/available_memory.h"
#include "framework/render/film.h"

namespace pt {
namespace {

namespace fs = std::filesystem;

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// (j) -r 16384 16384 went on until a bare std::bad_alloc: about 118 bytes a pixel between the
// film (64), an estimate copied out of it (28) and an EXR image copied out of that (28). The
// film is 56 now and the output is written from it directly.
TEST(FrameworkFilm, BytesPerPixelAreTheFilmsAndTheOutputsOnly) {
  EXPECT_EQ(Film::kBytesPerPixel, 56u);
  EXPECT_EQ(film_peak_bytes(100, 10, "a.png", false), 1000u * (56 + 3));
  EXPECT_EQ(film_peak_bytes(100, 10, "a.EXR", false), 1000u * (56 + 28));
  EXPECT_EQ(film_peak_bytes(100, 10, "a.png", true), 1000u * (56 + 15));  // the rate image
  EXPECT_EQ(film_peak_bytes(16384, 16384, "a.png", false), uint64_t(16384) * 16384 * 59);
}

TEST(FrameworkFilm, WrittenStraightFromTheStatisticsAsTheCopiesWere) {
  Film film(7, 5);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 7; ++x)
      for (int k = 0; k <= (x + y) % 3; ++k)
        film.at(x, y).add(glm::vec3(0.1f * float(x), 0.05f * float(y * k), 2.0f - float(k)));
  const fs::path dir = fs::temp_directory_path() / ("pt_film_test_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string png = (dir / "direct.png").string(), png_copy = (dir / "copy.png").string();
  write_film(png, film);
  write_image(png_copy, film.mean_image());
  EXPECT_EQ(bytes_of(png), bytes_of(png_copy));
  const std::string exr = (dir / "direct.exr").string(), exr_copy = (dir / "copy.exr").string();
  write_film(exr, film);
  write_estimate_exr(exr_copy, film.estimate());
  const RenderEstimate a = read_estimate_exr(exr), b = read_estimate_exr(exr_copy);
  EXPECT_EQ(a.mean, b.mean);
  EXPECT_EQ(a.variance, b.variance);
  EXPECT_EQ(a.count, b.count);
  fs::remove_all(dir);
}

TEST(FrameworkFilm, AvailableMemoryHonoursTheProcessLimit) {
  const uint64_t free_now = available_memory_bytes();
  EXPECT_GT(free_now, uint64_t(16) << 20) << "this machine reports almost no free memory";
  EXPECT_EQ(describe_bytes(uint64_t(15) << 30), "15.0 GiB");
  EXPECT_EQ(describe_bytes(900), "900 bytes");
  // Under an address-space limit (set in a child: the test's own allocations must not feel it)
  // what is left is at most the limit.
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer's shadow memory cannot live under RLIMIT_AS";
#endif
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    rlimit limit{};
    getrlimit(RLIMIT_AS, &limit);
    const rlim_t cap = rlim_t(4) << 30;
    if (limit.rlim_max != RLIM_INFINITY && limit.rlim_max < cap) _exit(3);
    limit.rlim_cur = cap;
    if (setrlimit(RLIMIT_AS, &limit) != 0) _exit(3);
    _exit(available_memory_bytes() <= uint64_t(cap) ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  if (WEXITSTATUS(status) == 3) GTEST_SKIP() << "cannot set an address-space limit here";
  EXPECT_EQ(WEXITSTATUS(status), 0) << "available memory ignored RLIMIT_AS";
}

}  // namespace
}  // namespace pt
