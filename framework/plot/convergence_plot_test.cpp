// Not needed for the assignment.
// The convergence table is read from CSV or JSON and plotted on log-log axes: each strategy is
// a line whose points sit where their values say, and bad rows are reported at their line.
#include "framework/plot/convergence_plot.h"

#include <gtest/gtest.h>

#include <regex>

#include "framework/testing/temp_folder.h"

using pt::ConvergenceRow;
using pt::PlotAxis;
using pt::PlotError;
using pt::convergence_svg;
using pt::read_convergence_table;
using pt::test::TempFolder;

namespace {

/// The (x, y) of every circle in a group of the SVG, in order.
std::vector<std::pair<double, double>> points(const std::string& svg_group) {
  std::vector<std::pair<double, double>> out;
  std::regex circle("<circle cx=\"([0-9.]+)\" cy=\"([0-9.]+)\"");
  for (std::sregex_iterator it(svg_group.begin(), svg_group.end(), circle), end; it != end; ++it) {
    out.push_back({std::stod((*it)[1]), std::stod((*it)[2])});
  }
  return out;
}

}  // namespace

TEST(FrameworkPlot, ReadsCsvInAnyColumnOrderAndJson) {
  TempFolder dir;
  auto csv = dir.write("t.csv", "seconds,strategy,relMSE,samples\n0.5,uniform,0.1,4\n");
  auto rows = read_convergence_table(csv);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].strategy, "uniform");
  EXPECT_DOUBLE_EQ(rows[0].samples, 4);
  EXPECT_DOUBLE_EQ(rows[0].seconds, 0.5);
  EXPECT_DOUBLE_EQ(rows[0].rel_mse, 0.1);
  auto json = dir.write("t.json", R"({"rows": [{"strategy": "adaptive", "samples": 8,
                                     "seconds": 2, "relMSE": 0.01}]})");
  rows = read_convergence_table(json);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].strategy, "adaptive");
  EXPECT_DOUBLE_EQ(rows[0].rel_mse, 0.01);
}

TEST(FrameworkPlot, BadRowsAreReportedWithFileAndLine) {
  TempFolder dir;
  auto csv = dir.write("t.csv", "strategy,samples,seconds,relMSE\na,1,1,0.1\na,2,fast,0.1\n");
  try {
    read_convergence_table(csv);
    FAIL() << "a non-number was accepted";
  } catch (const PlotError& e) {
    EXPECT_NE(std::string(e.what()).find("t.csv:3"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_convergence_table(dir.write("u.csv", "strategy,samples\na,1\n")), PlotError);
  std::vector<ConvergenceRow> zero = {{"a", 1, 0, 0.1, 7}};
  try {
    convergence_svg(zero, PlotAxis::seconds, "t", "z.csv");
    FAIL() << "zero seconds cannot sit on a log axis";
  } catch (const PlotError& e) {
    EXPECT_NE(std::string(e.what()).find("z.csv:7"), std::string::npos) << e.what();
  }
}

TEST(FrameworkPlot, EachStrategyIsALineWithPointsWhereTheValuesAre) {
  std::vector<ConvergenceRow> rows = {{"uniform", 16, 10, 0.001, 4}, {"uniform", 1, 0.1, 0.1, 2},
                                      {"uniform", 4, 1, 0.01, 3}, {"adaptive", 1, 0.1, 0.05, 5},
                                      {"adaptive", 4, 1, 0.005, 6}};
  std::string svg = convergence_svg(rows, PlotAxis::seconds, "Error", "t.csv");
  size_t first = svg.find("<g class=\"series\""), second = svg.find("<g class=\"series\"", first + 1);
  ASSERT_NE(second, std::string::npos);
  auto uniform = points(svg.substr(first, svg.find("</g>", first) - first));
  auto adaptive = points(svg.substr(second, svg.find("</g>", second) - second));
  ASSERT_EQ(uniform.size(), 3u);
  ASSERT_EQ(adaptive.size(), 2u);
  // Sorted along x; a decade of seconds is the same width everywhere on a log axis, and lower
  // error is lower on the page (larger y).
  EXPECT_LT(uniform[0].first, uniform[1].first);
  EXPECT_NEAR(uniform[1].first - uniform[0].first, uniform[2].first - uniform[1].first, 0.2);
  EXPECT_NEAR(uniform[1].second - uniform[0].second, uniform[2].second - uniform[1].second, 0.2);
  EXPECT_GT(uniform[1].second, uniform[0].second);
  EXPECT_NEAR(adaptive[0].first, uniform[0].first, 0.05);
  EXPECT_GT(adaptive[0].second, uniform[0].second);  // 0.05 is less error than 0.1: lower
  // Legend and axis labels.
  EXPECT_NE(svg.find(">uniform</text>"), std::string::npos);
  EXPECT_NE(svg.find(">adaptive</text>"), std::string::npos);
  EXPECT_NE(svg.find(">relative MSE</text>"), std::string::npos);
  EXPECT_NE(svg.find(">0.001</text>"), std::string::npos);
  EXPECT_NE(svg.find(">10</text>"), std::string::npos);
}
