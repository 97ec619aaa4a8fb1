#include "app/speed_report.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace pt {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

/// What one run of a child cost.
struct ChildRun {
  int exit_code = -1;
  double wall_seconds = 0.0;
  double peak_rss_mb = 0.0;  ///< the child's resident high-water mark (getrusage's ru_maxrss)
  std::string output;        ///< stdout and stderr together
};

/// Runs argv (argv[0] a path) with `extra_env` added to this process's environment, waits for it
/// and reads its resources from wait4. The wall time runs from the spawn to the reaping.
ChildRun run_measured(const std::vector<std::string>& argv, const std::vector<std::string>& extra_env) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::vector<std::string> env_strings;
  for (char** e = environ; *e; ++e) env_strings.emplace_back(*e);
  env_strings.insert(env_strings.end(), extra_env.begin(), extra_env.end());
  std::vector<char*> env;
  for (const std::string& e : env_strings) env.push_back(const_cast<char*>(e.c_str()));
  env.push_back(nullptr);

  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) throw std::runtime_error("bench render: cannot make a pipe");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[0]);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[1]);
  ChildRun run;
  pid_t pid = 0;
  const auto start = std::chrono::steady_clock::now();
  const int spawned = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), env.data());
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_fds[1]);
  if (spawned != 0) {
    close(pipe_fds[0]);
    throw std::runtime_error("bench render: cannot run " + argv[0]);
  }
  char buffer[4096];
  for (ssize_t n; (n = read(pipe_fds[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    run.output.append(buffer, size_t(n));
  }
  close(pipe_fds[0]);
  int status = 0;
  struct rusage usage {};
  while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  run.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.peak_rss_mb = double(usage.ru_maxrss) / 1024.0;  // Linux reports kilobytes
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return run;
}

std::string command_text(const std::vector<std::string>& argv) {
  std::string text;
  for (const std::string& a : argv) text += (text.empty() ? "" : " ") + a;
  return text;
}

/// The first line of `text` that holds `what`, or "".
std::string line_with(const std::string& text, const std::string& what) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.find(what) != std::string::npos) return line;
  return {};
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) {
      const size_t colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(colon + 2);
    }
  return "unknown";
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  in >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return text;
}

double median_of(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// The folder of the running executable (bench), where the pathtracer is built beside it.
fs::path own_folder() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::current_path() : exe.parent_path();
}

}  // namespace

std::vector<SpeedCase> speed_cases(bool quick) {
  // The goals' flags; the quick report keeps each scene and setting and renders 160 × 120 (a
  // ninth of the pixels) or an eighth of the samples.
  const std::vector<std::string> big = quick ? std::vector<std::string>{"-r", "160", "120"}
                                             : std::vector<std::string>{"-r", "480", "360"};
  auto with = [](std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  std::vector<SpeedCase> cases;
  cases.push_back({"help", "", {"--help"}, false});
  cases.push_back({"info CBbunny", "sky/CBbunny.dae", {"--info"}, false});
  const std::vector<std::string> path_flags = {"-t", "2", "-s", "64", "-l", "16", "-m", "5"};
  cases.push_back({"CBspheres_lambertian", "sky/CBspheres_lambertian.dae", with(path_flags, big)});
  cases.push_back({"CBbunny", "sky/CBbunny.dae", with(path_flags, big)});
  cases.push_back({"CBbunny adaptive", "sky/CBbunny.dae",
                   with({"-t", "2", "-s", "16", "-l", "8", "-m", "6", "-a", "64", "0.05"}, big)});
  const std::vector<std::string> long_paths = {"-t", "2", "-r", "160", "120", "-s",
                                               quick ? "128" : "1024", "-l", "1", "-m", "100"};
  for (const char* scene : {"CBspheres_lambertian", "CBspheres", "CBbunny", "CBgems"})
    cases.push_back({std::string(scene) + " 160x120 m100", std::string("sky/") + scene + ".dae",
                     long_paths});
  return cases;
}

namespace {

/// What `bench render` was asked for.
struct SpeedReportOptions {
  bool quick = false;
  std::string scenes = "../shared/scenes/cs184", pathtracer, out_path;
  int repeat = 1;
};

int speed_report(SpeedReportOptions o) {
  const bool quick = o.quick;
  const std::string& scenes = o.scenes;
  const std::string& out_path = o.out_path;
  const int repeat = o.repeat;
  std::string& pathtracer = o.pathtracer;

  if (pathtracer.empty()) pathtracer = (own_folder() / "pathtracer").string();
  if (!fs::exists(pathtracer)) throw std::runtime_error(pathtracer + ": no pathtracer there (--pathtracer)");
  const std::vector<SpeedCase> cases = speed_cases(quick);
  for (const SpeedCase& c : cases)
    if (!c.scene.empty() && !fs::exists(fs::path(scenes) / c.scene))
      throw std::runtime_error((fs::path(scenes) / c.scene).string() +
                               ": scene missing (the course's scenes: --scenes DIR)");

  const fs::path tmp = fs::temp_directory_path() / ("pt_speed_report_" + std::to_string(getpid()));
  fs::create_directories(tmp);
  json report = {{"report", quick ? "bench render --quick" : "bench render"},
                 {"date", utc_now()},
                 {"machine", {{"cpu", cpu_model()},
                              {"cores", std::thread::hardware_concurrency()},
                              {"load_average_before", load_average()}}},
                 {"pathtracer", pathtracer},
                 {"repeat", repeat}};
  const std::regex summary(R"(render: (\d+)x(\d+).*, ([0-9.]+) s, ([0-9.]+) M rays/s)");
  // The pathtracer's line of rays by kind (ray_kinds_line), and its packets where it has some.
  const std::regex kinds(R"(rays: camera ([0-9.]+), shadow ([0-9.]+), bounce and other ([0-9.]+) M/s)");
  const std::regex packets(R"(shadow packets: ([0-9.]+) % of the shadow rays, ([0-9.]+) rays a packet)");
  const char* kind_keys[] = {"camera_mrays_per_s", "shadow_mrays_per_s", "bounce_mrays_per_s",
                             "packet_share_percent", "packet_occupancy"};
  int failures = 0;
  for (const SpeedCase& c : cases) {
    std::vector<std::string> argv = {pathtracer};
    argv.insert(argv.end(), c.flags.begin(), c.flags.end());
    if (c.writes_image) argv.insert(argv.end(), {"-f", (tmp / "render.png").string()});
    if (!c.scene.empty()) argv.push_back((fs::path(scenes) / c.scene).string());
    json entry = {{"name", c.name}, {"command", command_text(argv)}};
    std::vector<double> walls, renders, mrays, rss;
    std::vector<double> by_kind[5];  // in the order of kind_keys
    json runs = json::array();
    std::cerr << "bench render: " << c.name << "\n";
    for (int r = 0; r < repeat; ++r) {
      const ChildRun run = run_measured(argv, {});
      json one = {{"exit_code", run.exit_code}, {"wall_s", run.wall_seconds},
                  {"peak_rss_mb", run.peak_rss_mb}};
      if (run.exit_code != 0) {
        ++failures;
        one["output"] = run.output.substr(0, 2000);
        runs.push_back(one);
        continue;
      }
      walls.push_back(run.wall_seconds);
      rss.push_back(run.peak_rss_mb);
      std::smatch m;
      const std::string line = line_with(run.output, "render: ");
      if (std::regex_search(line, m, summary)) {
        const double pixels = std::stod(m[1]) * std::stod(m[2]);
        entry["pixels"] = pixels;
        one["render_s"] = std::stod(m[3]);
        one["mrays_per_s"] = std::stod(m[4]);
        renders.push_back(std::stod(m[3]));
        mrays.push_back(std::stod(m[4]));
      }
      const std::string kinds_text = line_with(run.output, "rays: camera");
      if (std::regex_search(kinds_text, m, kinds))
        for (int k = 0; k < 3; ++k) {
          one[kind_keys[k]] = std::stod(m[k + 1]);
          by_kind[k].push_back(std::stod(m[k + 1]));
        }
      if (std::regex_search(kinds_text, m, packets))
        for (int k = 3; k < 5; ++k) {
          one[kind_keys[k]] = std::stod(m[k - 2]);
          by_kind[k].push_back(std::stod(m[k - 2]));
        }
      runs.push_back(one);
    }
    if (!walls.empty()) {
      entry["wall_s"] = median_of(walls);
      entry["peak_rss_mb"] = median_of(rss);
    }
    if (!renders.empty()) {
      entry["render_s"] = median_of(renders);
      entry["mrays_per_s"] = median_of(mrays);
    }
    for (int k = 0; k < 5; ++k)
      if (!by_kind[k].empty()) entry[kind_keys[k]] = median_of(by_kind[k]);
    if (c.writes_image) {
      // The render's own peak, without the image library: the same command at one sample a
      // pixel (memory does not grow with samples) with the image module made unfindable, so it
      // renders and then fails to write. Writing the image opens OpenImageIO, whose libraries
      // then set the peak of the whole command (peak_rss_mb).
      std::vector<std::string> one = argv;
      for (size_t k = 0; k + 1 < one.size(); ++k)
        if (one[k] == "-s") one[k + 1] = "1";
      const ChildRun refused =
          run_measured(one, {"PT_IMAGE_MODULE_DIR=" + (tmp / "no_image_module").string()});
      if (refused.output.find("render: ") != std::string::npos)
        entry["render_phase_peak_rss_mb"] = refused.peak_rss_mb;
    } else {
      // What the dynamic loader brought in (a run of its own: LD_DEBUG slows the start).
      const ChildRun traced = run_measured(argv, {"LD_DEBUG=files"});
      size_t objects = 0;
      for (size_t at = 0; (at = traced.output.find("generating link map", at)) != std::string::npos; ++at)
        ++objects;
      entry["shared_objects_loaded"] = objects;
    }
    entry["runs"] = runs;
    report["cases"].push_back(entry);
  }
  report["machine"]["load_average_after"] = load_average();
  std::error_code ec;
  fs::remove_all(tmp, ec);
  const std::string text = report.dump(2);
  std::cout << text << std::endl;
  if (!out_path.empty()) {
    std::ofstream out(out_path);
    if (!(out << text << "\n")) throw std::runtime_error(out_path + ": cannot write the report");
  }
  if (failures > 0) {
    std::cerr << "bench render: " << failures << " run(s) failed; their output is in the JSON\n";
    return 1;
  }
  return 0;
}

}  // namespace

BenchCommand add_speed_report_command(CLI::App& bench) {
  auto o = std::make_shared<SpeedReportOptions>();
  CLI::App* app = bench.add_subcommand(
      "render", "the speed report: runs pathtracer on the course's scenes at the flags of the "
                "performance goals, one run after another, and prints JSON: wall and render "
                "seconds, rays/s, peak memory, and the cost of commands that write no image");
  app->add_flag("--quick", o->quick, "the same scenes and settings at 160x120 or an eighth of the samples");
  app->add_option("--scenes", o->scenes, "the course's scenes (default ../shared/scenes/cs184)");
  app->add_option("--pathtracer", o->pathtracer, "the pathtracer to run (default: beside bench)");
  app->add_option("--repeat", o->repeat, "runs of each case; the median is reported with every run")
      ->check(CLI::Range(1, 100));
  app->add_option("--out", o->out_path, "also write the JSON to this file");
  return {app, [o] { return speed_report(*o); }};
}

}  // namespace pt
