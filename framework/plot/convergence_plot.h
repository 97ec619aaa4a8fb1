// Not needed for the assignment.
// The plot of a convergence table: error against time (or samples) for each strategy, on
// log-log axes, written as a self-contained SVG (bench writes the table, the write-up shows it).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace pt {

/// One measurement: a strategy rendered with so many samples took so long and had this error.
struct ConvergenceRow {
  std::string strategy;
  double samples = 0;
  double seconds = 0;
  double rel_mse = 0;
  int line = 0;  ///< where it was read (CSV line, or JSON array index + 1)
};

/// A table that cannot be plotted; the message names the file and the line.
class PlotError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads a CSV with a header naming strategy, samples, seconds, relMSE (any order, other
/// columns ignored), or a JSON array of objects with those keys (or {"rows": [...]}).
std::vector<ConvergenceRow> read_convergence_table(const std::filesystem::path& file);

/// What the plot shows on its x axis.
enum class PlotAxis { seconds, samples };

/// The log-log SVG of the rows: one line with markers per strategy, decade ticks with labels,
/// minor ticks, axis titles and a legend. Throws PlotError for a value a log axis cannot show.
std::string convergence_svg(const std::vector<ConvergenceRow>& rows, PlotAxis x,
                            const std::string& title, const std::string& source_name);

}  // namespace pt
