// A tiny convergence study end to end on the project's Cornell box: every strategy measured at
// every budget, errors that fall with the budget, a table the plotter reads, a reused reference.
// Renders are seeded (pixel by pixel), so the figures are the same on every run.
#include "app/convergence.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "framework/plot/convergence_plot.h"
#include "framework/testing/temp_folder.h"
#include "framework/testing/test_paths.h"

namespace pt {
namespace {

namespace fs = std::filesystem;

class BenchConvergence : public ::testing::Test {
 protected:
  void SetUp() override {
    options_.scene_path = std::string(pt::test::source_dir()) + "/scenes/cornell_spheres.dae";
    options_.out_dir = dir_;
    options_.width = 32;
    options_.height = 24;
    options_.budgets = {1, 4, 16};
    options_.reference_spp = 512;
    options_.max_depth = 2;
    options_.adaptive_batch = 4;  // so that adaptive sampling has a budget above one batch
    options_.speedup_budget = 4;
  }
  test::TempFolder folder_{"pt-convergence"};
  const fs::path& dir_ = folder_.path();
  ConvergenceOptions options_;
};

TEST_F(BenchConvergence, TinyStudyWritesATableThePlotterReads) {
  std::ostringstream log;
  ConvergenceResult r = run_convergence(options_, log);
  EXPECT_FALSE(r.reference.reused);

  // Strategy -> budget -> row.
  std::map<std::string, std::map<int, ConvergenceMeasurement>> by;
  for (const ConvergenceMeasurement& m : r.rows) {
    by[m.strategy][m.budget] = m;
    EXPECT_TRUE(std::isfinite(m.rel_mse) && m.rel_mse > 0.0) << m.strategy << " " << m.budget;
    EXPECT_GT(m.seconds, 0.0);
    EXPECT_LE(m.samples, double(m.budget) + 1e-9);
  }
  for (const char* s : {"hemisphere", "light", "mis"}) ASSERT_EQ(by[s].size(), 3u) << s;
  const std::string adaptive = "adaptive (" + r.adaptive_base + ")";
  ASSERT_EQ(by[adaptive].size(), 1u) << "adaptive runs only at budgets above one batch (16)";
  EXPECT_GT(by[adaptive][16].samples, 0.0);

  // Light importance: the error falls with the budget, roughly as 1/n (each 4x budget at
  // least halves it, with the reference's own noise far below).
  EXPECT_LT(by["light"][4].rel_mse, 0.5 * by["light"][1].rel_mse);
  EXPECT_LT(by["light"][16].rel_mse, 0.5 * by["light"][4].rel_mse);
  EXPECT_LT(r.reference.noise_rel_mse, 0.25 * by["light"][16].rel_mse);
  // Hemisphere sampling of a small light is far noisier at the same budget.
  EXPECT_GT(by["hemisphere"][16].rel_mse, 3.0 * by["light"][16].rel_mse);

  // Light importance reaches its own last error at its own last time; hemisphere needs longer.
  EXPECT_DOUBLE_EQ(r.target, by["light"][16].rel_mse);
  for (const StrategyTime& t : r.times)
    if (t.strategy == "light") {
      EXPECT_NEAR(t.time.seconds, by["light"][16].seconds, 1e-9);
      EXPECT_NEAR(t.ratio_to_light, 1.0, 1e-9);
    } else if (t.strategy == "hemisphere") {
      EXPECT_TRUE(t.beyond_reach || t.ratio_to_light > 1.0) << t.ratio_to_light;
    }
  // The Cornell box's pixels all carry noise (no sky, no pixel left unlit), so the best
  // allocation saves something, but not everything.
  EXPECT_GT(r.allocation_bound.best_sample_fraction, 0.3);
  EXPECT_LT(r.allocation_bound.best_sample_fraction, 1.0);
  EXPECT_LT(r.allocation_bound.zero_variance_share, 0.2);
  // The time fraction weighs each pixel by its measured cost, which a busy machine skews at
  // will (a pixel preempted mid-sample looks expensive): only what holds whatever the clocks
  // say is asserted here, Cauchy-Schwarz's (mean sqrt(ac))^2 <= mean a * mean c. The formula
  // itself is checked on exact costs in allocation_bound_test.
  EXPECT_GT(r.allocation_bound.best_time_fraction, 0.0);
  EXPECT_LE(r.allocation_bound.best_time_fraction, 1.0 + 1e-9);
  EXPECT_NE(convergence_report(r).find("the best any per-pixel allocation can do"),
            std::string::npos);
  EXPECT_TRUE(r.has_speedup);
  EXPECT_EQ(r.speedup.budget, 4);
  EXPECT_GT(r.speedup.seconds_one, 0.0);

  auto written = write_convergence_outputs(options_, r);
  ASSERT_EQ(written.size(), 3u);
  std::vector<ConvergenceRow> table = read_convergence_table(dir_ / "convergence.csv");
  ASSERT_EQ(table.size(), r.rows.size());
  for (size_t i = 0; i < table.size(); ++i) {
    EXPECT_EQ(table[i].strategy, r.rows[i].strategy);
    EXPECT_NEAR(table[i].rel_mse, r.rows[i].rel_mse, 1e-8 * r.rows[i].rel_mse);
  }
  EXPECT_EQ(read_convergence_table(dir_ / "convergence.json").size(), r.rows.size());
  std::ifstream svg(dir_ / "convergence.svg");
  std::string text((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("hemisphere"), std::string::npos) << "every strategy is in the legend";

  // A second study of the same scene and settings reuses the reference.
  options_.budgets = {1};
  options_.speedup_budget = -1;
  ConvergenceResult again = run_convergence(options_, log);
  EXPECT_TRUE(again.reference.reused);
  EXPECT_EQ(again.reference.key, r.reference.key);
}

TEST_F(BenchConvergence, OptionsThatCannotBeHonouredAreRefused) {
  std::ostringstream log;
  ConvergenceOptions same_seed = options_;
  same_seed.reference_seed = same_seed.seed;
  EXPECT_THROW(run_convergence(same_seed, log), ConvergenceOptionError);
  ConvergenceOptions shrinking = options_;
  shrinking.budgets = {4, 2};
  EXPECT_THROW(run_convergence(shrinking, log), ConvergenceOptionError);
  ConvergenceOptions zero = options_;
  zero.budgets = {0, 1};
  EXPECT_THROW(run_convergence(zero, log), ConvergenceOptionError);
  EXPECT_FALSE(fs::exists(dir_ / "convergence.csv"));
}

}  // namespace
}  // namespace pt
