// Not needed for the assignment: the definitions of framework/plot/convergence_plot.h.
#include "framework/plot/convergence_plot.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "framework/text/xml_text.h"


namespace fs = std::filesystem;

namespace pt {
namespace {

std::string trim(const std::string& s) {
  size_t a = s.find_first_not_of(" \t\r\"");
  size_t b = s.find_last_not_of(" \t\r\"");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// The column a header cell names, tolerant of case and of rel_mse / relmse spellings.
std::string canonical_column(const std::string& cell) {
  std::string c = lower(trim(cell));
  c.erase(std::remove(c.begin(), c.end(), '_'), c.end());
  if (c == "relmse" || c == "relativemse") return "relmse";
  if (c == "spp") return "samples";
  if (c == "time" || c == "secs") return "seconds";
  return c;
}

double parse_number(const std::string& text, const std::string& where, const std::string& col) {
  std::string t = trim(text);
  char* end = nullptr;
  double v = std::strtod(t.c_str(), &end);
  if (t.empty() || end != t.c_str() + t.size()) {
    throw PlotError(where + ": " + col + " '" + t + "' is not a number");
  }
  return v;
}

std::vector<ConvergenceRow> read_csv(const fs::path& file, std::istream& in) {
  std::vector<ConvergenceRow> rows;
  std::map<std::string, size_t> col;
  int line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    if (trim(line).empty() || trim(line)[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    std::string where = file.string() + ":" + std::to_string(line_no);
    if (col.empty()) {
      for (size_t i = 0; i < cells.size(); ++i) col[canonical_column(cells[i])] = i;
      for (const char* need : {"strategy", "samples", "seconds", "relmse"}) {
        if (!col.count(need)) {
          throw PlotError(where + ": the header has no '" + std::string(need) +
                          "' column (expected strategy,samples,seconds,relMSE)");
        }
      }
      continue;
    }
    auto cell = [&](const char* name) -> std::string {
      size_t i = col.at(name);
      if (i >= cells.size()) throw PlotError(where + ": the row has no " + name + " value");
      return cells[i];
    };
    ConvergenceRow r;
    r.strategy = trim(cell("strategy"));
    r.samples = parse_number(cell("samples"), where, "samples");
    r.seconds = parse_number(cell("seconds"), where, "seconds");
    r.rel_mse = parse_number(cell("relmse"), where, "relMSE");
    r.line = line_no;
    rows.push_back(r);
  }
  return rows;
}

std::vector<ConvergenceRow> read_json(const fs::path& file, std::istream& in) {
  nlohmann::json doc = nlohmann::json::parse(in, nullptr, false);
  if (doc.is_discarded()) throw PlotError(file.string() + ": not valid JSON");
  if (doc.is_object() && doc.contains("rows")) doc = doc["rows"];
  if (!doc.is_array()) throw PlotError(file.string() + ": expected an array of rows");
  std::vector<ConvergenceRow> rows;
  for (size_t i = 0; i < doc.size(); ++i) {
    const auto& o = doc[i];
    std::string where = file.string() + ": row " + std::to_string(i + 1);
    auto number = [&](std::initializer_list<const char*> keys) {
      for (const char* k : keys) {
        if (o.contains(k) && o[k].is_number()) return o[k].get<double>();
      }
      throw PlotError(where + ": missing number '" + std::string(*keys.begin()) + "'");
    };
    if (!o.is_object() || !o.contains("strategy") || !o["strategy"].is_string()) {
      throw PlotError(where + ": missing 'strategy'");
    }
    ConvergenceRow r;
    r.strategy = o["strategy"].get<std::string>();
    r.samples = number({"samples", "spp"});
    r.seconds = number({"seconds", "time"});
    r.rel_mse = number({"relMSE", "rel_mse", "relmse"});
    r.line = static_cast<int>(i + 1);
    rows.push_back(r);
  }
  return rows;
}

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

/// A decade's label: plain for 0.001 .. 10000, otherwise 1e-5 style.
std::string decade_label(int k) {
  if (k >= 0 && k <= 4) return std::to_string(static_cast<long>(std::pow(10.0, k)));
  if (k < 0 && k >= -3) return "0." + std::string(-k - 1, '0') + "1";
  return "1e" + std::to_string(k);
}

/// A log axis spanning whole decades around the data.
struct LogAxis {
  int lo = 0, hi = 1;
  double pixel_lo = 0, pixel_hi = 1;
  static LogAxis around(double min, double max, double p0, double p1) {
    LogAxis a;
    a.lo = static_cast<int>(std::floor(std::log10(min)));
    a.hi = static_cast<int>(std::ceil(std::log10(max)));
    if (a.hi <= a.lo) a.hi = a.lo + 1;
    a.pixel_lo = p0;
    a.pixel_hi = p1;
    return a;
  }
  double map(double v) const {
    double t = (std::log10(v) - lo) / (hi - lo);
    return pixel_lo + t * (pixel_hi - pixel_lo);
  }
};

}  // namespace

std::vector<ConvergenceRow> read_convergence_table(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw PlotError(file.string() + ": cannot open the table");
  std::string ext = lower(file.extension().string());
  auto rows = ext == ".json" ? read_json(file, in) : read_csv(file, in);
  if (rows.empty()) throw PlotError(file.string() + ": the table has no rows");
  return rows;
}

std::string convergence_svg(const std::vector<ConvergenceRow>& rows, PlotAxis x_axis,
                            const std::string& title, const std::string& source_name) {
  const double width = 640, height = 420, left = 78, right = 170, top = 40, bottom = 58;
  auto xval = [&](const ConvergenceRow& r) {
    return x_axis == PlotAxis::seconds ? r.seconds : r.samples;
  };
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  for (const ConvergenceRow& r : rows) {
    std::string where = source_name + ":" + std::to_string(r.line);
    double xv = xval(r);
    if (!(xv > 0) || !std::isfinite(xv)) {
      throw PlotError(where + ": " + (x_axis == PlotAxis::seconds ? "seconds" : "samples") +
                      " must be a positive number for a log axis");
    }
    if (!(r.rel_mse > 0) || !std::isfinite(r.rel_mse)) {
      throw PlotError(where + ": relMSE must be a positive number for a log axis");
    }
    xmin = std::min(xmin, xv);
    xmax = std::max(xmax, xv);
    ymin = std::min(ymin, r.rel_mse);
    ymax = std::max(ymax, r.rel_mse);
  }
  LogAxis xa = LogAxis::around(xmin, xmax, left, width - right);
  LogAxis ya = LogAxis::around(ymin, ymax, height - bottom, top);

  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
    << "\" viewBox=\"0 0 " << width << ' ' << height << "\" font-family=\"sans-serif\" "
    << "font-size=\"12\">\n";
  s << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s << "<text x=\"" << fmt((left + width - right) / 2) << "\" y=\"22\" text-anchor=\"middle\" "
    << "font-size=\"15\">" << xml_escape(title) << "</text>\n";
  // Grid lines and ticks: a labelled major tick per decade, minor ticks at 2..9.
  for (int k = xa.lo; k <= xa.hi; ++k) {
    double px = xa.map(std::pow(10.0, k));
    s << "<line x1=\"" << fmt(px) << "\" y1=\"" << top << "\" x2=\"" << fmt(px) << "\" y2=\""
      << height - bottom << "\" stroke=\"#ddd\"/>\n";
    s << "<line x1=\"" << fmt(px) << "\" y1=\"" << height - bottom << "\" x2=\"" << fmt(px)
      << "\" y2=\"" << height - bottom + 6 << "\" stroke=\"black\"/>\n";
    s << "<text x=\"" << fmt(px) << "\" y=\"" << height - bottom + 20
      << "\" text-anchor=\"middle\">" << decade_label(k) << "</text>\n";
    for (int m = 2; m <= 9 && k < xa.hi; ++m) {
      double mx = xa.map(m * std::pow(10.0, k));
      s << "<line x1=\"" << fmt(mx) << "\" y1=\"" << height - bottom << "\" x2=\"" << fmt(mx)
        << "\" y2=\"" << height - bottom + 3 << "\" stroke=\"black\"/>\n";
    }
  }
  for (int k = ya.lo; k <= ya.hi; ++k) {
    double py = ya.map(std::pow(10.0, k));
    s << "<line x1=\"" << left << "\" y1=\"" << fmt(py) << "\" x2=\"" << width - right
      << "\" y2=\"" << fmt(py) << "\" stroke=\"#ddd\"/>\n";
    s << "<line x1=\"" << left - 6 << "\" y1=\"" << fmt(py) << "\" x2=\"" << left << "\" y2=\""
      << fmt(py) << "\" stroke=\"black\"/>\n";
    s << "<text x=\"" << left - 9 << "\" y=\"" << fmt(py + 4) << "\" text-anchor=\"end\">"
      << decade_label(k) << "</text>\n";
    for (int m = 2; m <= 9 && k < ya.hi; ++m) {
      double my = ya.map(m * std::pow(10.0, k));
      s << "<line x1=\"" << left - 3 << "\" y1=\"" << fmt(my) << "\" x2=\"" << left
        << "\" y2=\"" << fmt(my) << "\" stroke=\"black\"/>\n";
    }
  }
  s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << width - left - right
    << "\" height=\"" << height - top - bottom << "\" fill=\"none\" stroke=\"black\"/>\n";
  s << "<text x=\"" << fmt((left + width - right) / 2) << "\" y=\"" << height - 14
    << "\" text-anchor=\"middle\">"
    << (x_axis == PlotAxis::seconds ? "render time (s)" : "samples per pixel") << "</text>\n";
  s << "<text transform=\"translate(20," << fmt((top + height - bottom) / 2)
    << ") rotate(-90)\" text-anchor=\"middle\">relative MSE</text>\n";

  // One series per strategy, in the order the table first names them, sorted along x.
  static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                  "#9467bd", "#8c564b", "#e377c2", "#17becf"};
  std::vector<std::string> order;
  for (const ConvergenceRow& r : rows) {
    if (std::find(order.begin(), order.end(), r.strategy) == order.end()) order.push_back(r.strategy);
  }
  for (size_t si = 0; si < order.size(); ++si) {
    std::vector<ConvergenceRow> series;
    for (const ConvergenceRow& r : rows) {
      if (r.strategy == order[si]) series.push_back(r);
    }
    std::sort(series.begin(), series.end(),
              [&](const ConvergenceRow& a, const ConvergenceRow& b) { return xval(a) < xval(b); });
    const char* colour = colours[si % 8];
    s << "<g class=\"series\" stroke=\"" << colour << "\" fill=\"" << colour << "\">\n";
    s << "<polyline fill=\"none\" stroke-width=\"2\" points=\"";
    for (const ConvergenceRow& r : series) s << fmt(xa.map(xval(r))) << ',' << fmt(ya.map(r.rel_mse)) << ' ';
    s << "\"/>\n";
    for (const ConvergenceRow& r : series) {
      s << "<circle cx=\"" << fmt(xa.map(xval(r))) << "\" cy=\"" << fmt(ya.map(r.rel_mse))
        << "\" r=\"3.5\"/>\n";
    }
    s << "</g>\n";
    double ly = top + 14 + 20 * static_cast<double>(si);
    double lx = width - right + 14;
    s << "<line x1=\"" << lx << "\" y1=\"" << fmt(ly) << "\" x2=\"" << lx + 24 << "\" y2=\""
      << fmt(ly) << "\" stroke=\"" << colour << "\" stroke-width=\"2\"/>\n";
    s << "<circle cx=\"" << lx + 12 << "\" cy=\"" << fmt(ly) << "\" r=\"3.5\" fill=\"" << colour
      << "\"/>\n";
    s << "<text x=\"" << lx + 30 << "\" y=\"" << fmt(ly + 4) << "\">" << xml_escape(order[si])
      << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace pt
