// Not needed for the assignment.
// The tile renderer: every pixel exactly once, -p cells respected, images independent of threads.
#include "framework/render/tile_renderer.h"

#include <atomic>
#include <cmath>
#include <vector>

#include <link.h>

#include <gtest/gtest.h>

#include "framework/render/film.h"
#include "framework/render/tiles.h"

namespace {

// Counts how often each pixel of a w × h image is covered by `tiles`.
std::vector<int> coverage(const std::vector<pt::PixelRect>& tiles, int w, int h) {
  std::vector<int> hits(size_t(w) * size_t(h), 0);
  for (const pt::PixelRect& t : tiles)
    for (int y = t.y0; y < t.y1; ++y)
      for (int x = t.x0; x < t.x1; ++x) {
        if (x < 0 || y < 0 || x >= w || y >= h) {
          ADD_FAILURE() << "tile pixel (" << x << "," << y << ") outside the image";
          continue;
        }
        ++hits[size_t(y) * size_t(w) + size_t(x)];
      }
  return hits;
}

// A pixel function whose value depends on its random numbers, and which counts one ray a sample.
pt::PixelFn noisy_pixel(int samples) {
  return [samples](int x, int y, pt::Rng& rng, pt::TraceContext& context, pt::PixelStats* stats) {
    for (int s = 0; s < samples; ++s) {
      stats->add(glm::vec3(rng.next_float(), float(x) * rng.next_float(), float(y)));
      context.rays.add();
    }
  };
}

// How many shared objects the process has loaded (the program itself included).
int loaded_objects() {
  int count = 0;
  dl_iterate_phdr([](dl_phdr_info*, size_t, void* n) { return ++*static_cast<int*>(n), 0; }, &count);
  return count;
}

}  // namespace

TEST(FrameworkTiles, OddSizesCoveredExactlyOnce) {
  for (int w : {1, 31, 32, 33, 97})
    for (int h : {1, 17, 64, 65})
      for (int tile : {1, 7, 32}) {
        auto tiles = pt::split_into_tiles({0, 0, w, h}, tile);
        for (const pt::PixelRect& t : tiles) {
          EXPECT_GE(t.width(), 1);
          EXPECT_LE(t.width(), tile);
          EXPECT_LE(t.height(), tile);
        }
        std::vector<int> hits = coverage(tiles, w, h);
        for (size_t i = 0; i < hits.size(); ++i)
          ASSERT_EQ(hits[i], 1) << w << "x" << h << " tile " << tile << " pixel " << i;
      }
}

TEST(FrameworkTiles, CellCoveredExactlyOnceAndNothingElse) {
  const int w = 100, h = 70;
  pt::PixelRect cell{13, 29, 13 + 45, 29 + 33};
  std::vector<int> hits = coverage(pt::split_into_tiles(cell, 32), w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      bool inside = x >= cell.x0 && x < cell.x1 && y >= cell.y0 && y < cell.y1;
      ASSERT_EQ(hits[size_t(y) * w + x], inside ? 1 : 0) << x << "," << y;
    }
  EXPECT_TRUE(pt::split_into_tiles({5, 5, 5, 9}, 32).empty());
  EXPECT_THROW(pt::split_into_tiles(cell, 0), std::invalid_argument);
}

TEST(FrameworkTileRenderer, RendersEachPixelOnceWithItsOwnSamples) {
  pt::RenderSettings settings;
  settings.width = 67, settings.height = 45, settings.threads = 2;
  pt::Film film(settings.width, settings.height);
  pt::RenderReport report = pt::render_tiles(settings, noisy_pixel(3), &film);
  for (int y = 0; y < settings.height; ++y)
    for (int x = 0; x < settings.width; ++x) ASSERT_EQ(film.at(x, y).count, 3) << x << "," << y;
  EXPECT_EQ(report.samples, 67L * 45 * 3);
  EXPECT_EQ(report.rays, uint64_t(67 * 45 * 3));  // per-tile counters, summed
  EXPECT_EQ(report.threads, 2);
  EXPECT_NE(pt::summary_line(report).find("render: 67x45, 3 spp"), std::string::npos)
      << pt::summary_line(report);
}

TEST(FrameworkTileRenderer, CellRendersOnlyItsPixels) {
  pt::RenderSettings settings;
  settings.width = 80, settings.height = 50;
  settings.has_cell = true;
  settings.cell_x = 70, settings.cell_y = 3, settings.cell_w = 10, settings.cell_h = 40;
  pt::Film film(settings.width, settings.height);
  pt::RenderReport report = pt::render_tiles(settings, noisy_pixel(2), &film);
  for (int y = 0; y < settings.height; ++y)
    for (int x = 0; x < settings.width; ++x) {
      bool inside = x >= 70 && y >= 3 && y < 43;
      ASSERT_EQ(film.at(x, y).count, inside ? 2 : 0) << x << "," << y;
    }
  EXPECT_EQ(report.samples, 10L * 40 * 2);
  EXPECT_NE(pt::summary_line(report).find("cell 70 3 10 40"), std::string::npos);

  settings.cell_w = 11;  // one column past the right edge
  EXPECT_THROW(pt::render_tiles(settings, noisy_pixel(1), &film), std::invalid_argument);
}

TEST(FrameworkTileRenderer, SameSeedSameImageWhateverTheThreads) {
  pt::RenderSettings settings;
  settings.width = 53, settings.height = 41, settings.seed = 12345;
  auto render = [&](int threads, int tile_size) {
    settings.threads = threads;
    pt::Film film(settings.width, settings.height);
    pt::TileRenderOptions options;
    options.tile_size = tile_size;
    pt::render_tiles(settings, noisy_pixel(4), &film, options);
    return film.estimate();
  };
  pt::RenderEstimate one = render(1, 32), two = render(2, 32), two_small = render(2, 5);
  EXPECT_EQ(one.mean, two.mean);
  EXPECT_EQ(one.variance, two.variance);
  EXPECT_EQ(one.mean, two_small.mean);  // nor on how the image is cut
  settings.seed = 12346;
  pt::RenderEstimate other = render(2, 32);
  EXPECT_NE(one.mean, other.mean);  // and the seed does matter
}

TEST(FrameworkFilm, MeanImageAndEstimateAgreeWithTheSamples) {
  pt::Film film(3, 2);
  film.at(2, 1).add(glm::vec3(1.0f, 2.0f, 3.0f));
  film.at(2, 1).add(glm::vec3(3.0f, 2.0f, 1.0f));
  pt::Image image = film.mean_image();
  EXPECT_EQ(image.at(2, 1), glm::vec3(2.0f, 2.0f, 2.0f));
  EXPECT_EQ(image.at(0, 0), glm::vec3(0.0f));  // no sample: black
  pt::RenderEstimate e = film.estimate();
  ASSERT_EQ(e.mean.size(), 6u);
  EXPECT_EQ(e.mean[5], glm::vec3(2.0f));
  EXPECT_EQ(e.variance[5], glm::vec3(2.0f, 0.0f, 2.0f));  // unbiased: ((1)^2+(1)^2)/1
  EXPECT_EQ(e.count[5], 2.0f);
  EXPECT_EQ(e.count[0], 0.0f);
  EXPECT_EQ(film.total_samples(), 2);
}

// pathtracer starts the image module's preload (hundreds of shared objects) beside the render, and
// a library opened while another thread opens its own waits for all of it. start_render_threads
// is what keeps the render clear of that: once it has run, a render opens nothing.
TEST(StartRenderThreads, LeavesTheRenderNoLibraryToOpen) {
  pt::RenderSettings settings;
  settings.width = 40, settings.height = 30, settings.threads = 2;
  const int before = loaded_objects();
  pt::start_render_threads(settings);
  const int started = loaded_objects();
  pt::Film film(settings.width, settings.height);
  pt::render_tiles(settings, noisy_pixel(2), &film);
  EXPECT_EQ(loaded_objects(), started)
      << "the render opened shared objects that start_render_threads did not";
  if (started == before)
    GTEST_SKIP() << "oneTBB had already started in this process (or opens nothing when it "
                    "starts): the render was not shown to need what start_render_threads opens";
}
