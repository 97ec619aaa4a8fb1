#include "grader/manifest.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include <boost/crc.hpp>

#include "framework/render/stopping_rule.h"
#include "framework/text/text_file.h"

namespace pt::grader {
namespace {

[[noreturn]] void bad(const std::string& path, const std::string& where, const std::string& what) {
  throw std::runtime_error(path + ": " + where + ": " + what);
}

template <typename T>
T field(const std::string& path, const std::string& where, const nlohmann::ordered_json& j,
        const char* key) {
  if (!j.contains(key)) bad(path, where, std::string("missing \"") + key + "\"");
  try {
    return j.at(key).get<T>();
  } catch (const nlohmann::json::exception&) {
    bad(path, where, std::string("\"") + key + "\" has the wrong type");
  }
}

template <typename T>
T optional(const nlohmann::ordered_json& j, const char* key, T fallback) {
  return j.contains(key) ? j.at(key).get<T>() : fallback;
}

}  // namespace

std::string StepSpec::full_name() const {
  return "part" + std::to_string(part) + ".step" + std::to_string(step) + "." + name;
}

std::string StepSpec::test_prefix() const {
  return "part" + std::to_string(part) + ".step" + std::to_string(step) + ".";
}

const StepSpec* PartSpec::find_step(int step) const {
  for (const StepSpec& s : steps)
    if (s.step == step) return &s;
  return nullptr;
}

std::vector<const RenderCheck*> PartSpec::renders() const {
  std::vector<const RenderCheck*> all;
  for (const StepSpec& s : steps)
    for (const RenderCheck& r : s.renders) all.push_back(&r);
  return all;
}

std::vector<const RenderCheck*> PartSpec::renders_of_every_rule() const {
  std::vector<const RenderCheck*> all = renders();
  for (const StepSpec& s : steps)
    for (const RenderCheck& r : s.other_rule_renders) all.push_back(&r);
  return all;
}

double PartSpec::points() const {
  double sum = 0.0;
  for (const StepSpec& s : steps) sum += s.points;
  return sum;
}

const PartSpec* Manifest::find_part(int part) const {
  for (const PartSpec& p : parts)
    if (p.part == part) return &p;
  return nullptr;
}

const RenderCheck* Manifest::find_render(const std::string& name) const {
  for (const PartSpec& p : parts)
    for (const RenderCheck* r : p.renders())
      if (r->name == name) return r;
  return nullptr;
}

Manifest read_manifest(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot be read (the grading manifest)");
  Manifest m;
  try {
    m.json = nlohmann::ordered_json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error(path + ": not valid JSON: " + e.what());
  }
  try {
    m.block_size = optional(m.json, "block_size", 16);
    m.alpha = optional(m.json, "alpha", 0.01);
    m.relative_tolerance = optional(m.json, "relative_tolerance", 1e-5);
    m.absolute_tolerance = optional(m.json, "absolute_tolerance", 1e-6);
    m.stopping_rule = optional(m.json, "stopping_rule", std::string("split"));
    if (m.block_size < 1 || !(m.alpha > 0 && m.alpha < 1))
      bad(path, "top level", "block_size must be >= 1 and alpha in (0, 1)");
    if (!(m.relative_tolerance >= 0.0) || !(m.absolute_tolerance >= 0.0))
      bad(path, "top level", "relative_tolerance and absolute_tolerance must be >= 0");
    if (!parse_stopping_rule(m.stopping_rule))
      bad(path, "top level", "stopping_rule must be \"split\" or \"course\" (got \"" +
                                 m.stopping_rule + "\")");
    for (const auto& pj : field<nlohmann::ordered_json>(path, "top level", m.json, "parts")) {
      PartSpec p;
      p.part = field<int>(path, "a part", pj, "part");
      std::string where = "part " + std::to_string(p.part);
      if (m.find_part(p.part)) bad(path, where, "listed twice");
      p.title = optional(pj, "title", std::string());
      p.test_timeout = optional(pj, "test_timeout", 60.0);
      p.build_timeout = optional(pj, "build_timeout", 1200.0);
      p.renders_rest_on = optional(pj, "renders_rest_on", std::vector<int>());
      p.tests_rest_on = optional(pj, "tests_rest_on", std::vector<int>());
      for (const auto& [field_name, list] : {std::pair<const char*, const std::vector<int>*>{
                                                 "renders_rest_on", &p.renders_rest_on},
                                             {"tests_rest_on", &p.tests_rest_on}})
        for (int earlier : *list)
          if (earlier < 1 || earlier >= p.part)
            bad(path, where, std::string(field_name) + " names part " + std::to_string(earlier) +
                                 ", which is not an earlier part");
      for (const auto& sj : field<nlohmann::ordered_json>(path, where, pj, "steps")) {
        StepSpec st;
        st.part = p.part;
        st.step = field<int>(path, where + ", a step", sj, "step");
        std::string sw = where + ", step " + std::to_string(st.step);
        if (st.step != int(p.steps.size()) + 1) bad(path, sw, "steps are numbered 1, 2, ... in order");
        st.name = field<std::string>(path, sw, sj, "name");
        st.title = optional(sj, "title", std::string());
        st.points = field<double>(path, sw, sj, "points");
        if (!(st.points >= 0.0)) bad(path, sw, "points must be >= 0");
        st.functions = optional(sj, "functions", std::vector<std::string>());
        st.rests_on = optional(sj, "rests_on", std::string());
        st.tests_rest_on_steps = optional(sj, "tests_rest_on_steps", std::vector<int>());
        for (int k : st.tests_rest_on_steps)
          if (k < 1 || k == st.step)
            bad(path, sw, "tests_rest_on_steps names other steps of the part only (from 1, not " +
                              std::to_string(st.step) + " itself)");
        for (const auto& rj : optional(sj, "renders", nlohmann::ordered_json::array())) {
          RenderCheck r;
          r.part = p.part;
          r.step = st.step;
          std::string scene_name = field<std::string>(path, sw, rj, "name");
          r.name = st.test_prefix() + "render." + scene_name;
          std::string rw = sw + ", render \"" + scene_name + "\"";
          auto same_name = [&](const RenderCheck& o) { return o.name == r.name; };
          if (m.find_render(r.name) || std::any_of(st.renders.begin(), st.renders.end(), same_name) ||
              std::any_of(st.other_rule_renders.begin(), st.other_rule_renders.end(), same_name))
            bad(path, rw, "two renders of one name");
          r.scene = field<std::string>(path, rw, rj, "scene");
          r.course_scene = optional(rj, "course_scene", false);
          r.kind = field<std::string>(path, rw, rj, "kind");
          if (r.kind != "normals" && r.kind != "direct" && r.kind != "hemisphere" &&
              r.kind != "path" && r.kind != "adaptive")
            bad(path, rw, "kind must be normals, direct, hemisphere, path or adaptive");
          r.args = field<std::vector<std::string>>(path, rw, rj, "args");
          r.reference_args = field<std::vector<std::string>>(path, rw, rj, "reference_args");
          r.seed = field<uint64_t>(path, rw, rj, "seed");
          r.reference_seed = field<uint64_t>(path, rw, rj, "reference_seed");
          r.timeout = optional(rj, "timeout", 60.0);
          r.relative_tolerance = optional(rj, "relative_tolerance", -1.0);
          r.noise_limit = optional(rj, "noise_limit", 0.0);
          if (r.noise_limit != 0.0 && !(r.noise_limit > 1.0))
            bad(path, rw, "noise_limit is a factor above 1 (or 0: no noise check)");
          r.reference = field<std::string>(path, rw, rj, "reference");
          if (rj.contains("made")) r.checksum = optional(rj.at("made"), "crc32", std::string());
          r.reference_runs = optional(rj, "reference_runs", 1);
          if (r.reference_runs < 1 || r.reference_runs > 1000)
            bad(path, rw, "reference_runs is the number of renders the reference averages: 1 to 1000");
          if (r.is_reference_seed(r.seed))
            bad(path, rw, "the graded render must use other random numbers than its reference "
                          "(its seed is one of the reference's)");
          r.stopping_rule = optional(rj, "stopping_rule", std::string());
          if (!r.stopping_rule.empty() && !parse_stopping_rule(r.stopping_rule))
            bad(path, rw, "stopping_rule must be \"split\" or \"course\" (got \"" +
                              r.stopping_rule + "\")");
          if (!r.stopping_rule.empty() && r.kind != "adaptive")
            bad(path, rw, "only an adaptive render has a stopping rule");
          if (rj.contains("rests_on_steps")) {
            r.rests_on_steps = field<std::vector<int>>(path, rw, rj, "rests_on_steps");
            for (int k : r.rests_on_steps)
              if (k < 1 || k >= st.step)
                bad(path, rw, "rests_on_steps names earlier steps of the part only (1 to " +
                                  std::to_string(st.step - 1) + ")");
          } else {
            for (int k = 1; k < st.step; ++k) r.rests_on_steps.push_back(k);
          }
          // A render of the other stopping rule keeps its reference but is not graded.
          if (r.stopping_rule.empty() || r.stopping_rule == m.stopping_rule)
            st.renders.push_back(r);
          else
            st.other_rule_renders.push_back(r);
        }
        for (const auto& uj : optional(sj, "rules", nlohmann::ordered_json::array())) {
          Rule rule;
          rule.id = field<std::string>(path, sw + ", a rule", uj, "id");
          const std::string uw = sw + ", rule \"" + rule.id + "\"";
          if (rule.id.empty() || rule.id.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") !=
                                     std::string::npos)
            bad(path, uw, "a rule's id is lower-case letters, digits and _");
          for (const Rule& other : st.rules)
            if (other.id == rule.id) bad(path, uw, "two rules of one id");
          rule.text = field<std::string>(path, uw, uj, "rule");
          rule.checks = optional(uj, "checks", std::vector<std::string>());
          rule.mutants = optional(uj, "mutants", std::vector<std::string>());
          st.rules.push_back(rule);
        }
        p.steps.push_back(st);
      }
      if (p.steps.empty()) bad(path, where, "a part has at least one step");
      // Whose functions a step's tests run: a failing test is charged to a failing step it runs
      // (step_at_fault.h). Steps whose tests run each other would pass a failure back and forth.
      // (A render runs earlier steps only: it belongs to the latest step it runs.)
      std::map<int, std::vector<int>> runs;
      for (const StepSpec& st : p.steps) runs[st.step] = st.tests_rest_on_steps;
      for (const StepSpec& st : p.steps)
        for (int k : st.tests_rest_on_steps) {
          const std::string sw = where + ", step " + std::to_string(st.step);
          if (!p.find_step(k))
            bad(path, sw, "tests_rest_on_steps names step " + std::to_string(k) +
                              ", which the part does not have");
          std::vector<int> todo = {k};
          std::set<int> seen;
          while (!todo.empty()) {
            const int at = todo.back();
            todo.pop_back();
            if (at == st.step)
              bad(path, sw, "its tests run step " + std::to_string(k) +
                                ", whose tests run it in turn (tests_rest_on_steps): a failure "
                                "would be charged back and forth");
            if (seen.insert(at).second) todo.insert(todo.end(), runs[at].begin(), runs[at].end());
          }
        }
      m.parts.push_back(p);
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  return m;
}

void record_reference(const std::string& manifest_path, const std::string& check_name,
                      const nlohmann::ordered_json& made) {
  Manifest m = read_manifest(manifest_path);
  bool found = false;
  for (auto& pj : m.json["parts"])
    for (auto& sj : pj["steps"])
      for (auto& rj : sj["renders"]) {
        std::string name = "part" + std::to_string(pj["part"].get<int>()) + ".step" +
                           std::to_string(sj["step"].get<int>()) + ".render." +
                           rj["name"].get<std::string>();
        if (name == check_name) {
          rj["made"] = made;
          found = true;
        }
      }
  if (!found) throw std::runtime_error(manifest_path + ": no render named " + check_name);
  std::ofstream out(manifest_path);
  out << m.json.dump(2) << "\n";
  if (!out) throw std::runtime_error(manifest_path + ": cannot be written");
}

std::string file_checksum(const std::string& path) {
  const std::string bytes = read_text_file(path);
  boost::crc_32_type crc;
  crc.process_bytes(bytes.data(), bytes.size());
  char buf[16];
  std::snprintf(buf, sizeof buf, "%08x", unsigned(crc.checksum()));
  return buf;
}

}  // namespace pt::grader
