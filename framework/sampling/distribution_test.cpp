// Not needed for the assignment.
// Distribution1D's cell pick: the last cell whose CDF is at most u, never an empty one, the same
// whether it is found by counting (small distributions) or by binary search (larger ones).
#include "framework/sampling/distribution.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "framework/sampling/rng.h"

namespace pt {
namespace {

/// The cell sample_continuous picks for u.
int cell_of(const Distribution1D& d, float u) {
  float pdf = 0.0f;
  int cell = -1;
  d.sample_continuous(u, &pdf, &cell);
  return cell;
}

/// Small whole weights with empty cells among them: 1, 0, 2, 1, 0, 1, ...
std::vector<float> weights(int n) {
  std::vector<float> w(n);
  for (int i = 0; i < n; ++i) w[i] = float(i % 3 == 1 ? 0 : 1 + i % 2);
  return w;
}

// Sizes on both sides of the switch from counting to searching.
class DistributionCells : public ::testing::TestWithParam<int> {};

TEST_P(DistributionCells, AnUOnABoundaryPicksTheCellThatStartsThere) {
  const int n = GetParam();
  const std::vector<float> w = weights(n);
  const Distribution1D d(w);
  double total = 0.0;
  for (float x : w) total += x;
  double below = 0.0;
  for (int i = 0; i < n; ++i) {
    if (w[i] > 0.0f) {
      // The CDF at the start of cell i, as the distribution rounds it to float.
      EXPECT_EQ(cell_of(d, float(below / total)), i) << "n " << n << ", cell " << i;
    }
    below += w[i];
  }
}

TEST_P(DistributionCells, CellsAreNonDecreasingInUAndNeverEmpty) {
  const int n = GetParam();
  const std::vector<float> w = weights(n);
  const Distribution1D d(w);
  int last = 0;
  for (int k = 0; k < 4096; ++k) {
    const float u = float(k) / 4096.0f;
    const int cell = cell_of(d, u);
    ASSERT_GE(cell, last) << "u " << u;
    ASSERT_GT(w[cell], 0.0f) << "u " << u << " picked empty cell " << cell;
    last = cell;
  }
  Rng rng(7, uint64_t(n));
  for (int k = 0; k < 4096; ++k) {
    const float u = rng.next_float();
    float pdf = 0.0f;
    int cell = -1;
    const float x = d.sample_continuous(u, &pdf, &cell);
    ASSERT_GE(x, float(cell) / float(n));
    ASSERT_LE(x, float(cell + 1) / float(n));
    ASSERT_EQ(pdf, w[cell] / d.integral());
  }
}

TEST_P(DistributionCells, ANaNUPicksALastCellAsTheSearchDid) {
  const int n = GetParam();
  const Distribution1D d(std::vector<float>(n, 1.0f));
  EXPECT_EQ(cell_of(d, std::nanf("")), n - 1);
}

INSTANTIATE_TEST_SUITE_P(Sizes, DistributionCells, ::testing::Values(1, 2, 3, 15, 16, 17, 40));

}  // namespace
}  // namespace pt
