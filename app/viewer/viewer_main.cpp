// The viewer command: serves a page on 127.0.0.1 that previews a scene, renders it with the
// student's code, and shows what the code did (the BVH, one pixel's paths).
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli_parse.h"
#include "app/command_line.h"
#include "app/viewer/crash_witness.h"
#include "app/viewer/render_session.h"
#include "app/viewer/terminal_log.h"
#include "app/viewer/viewer_server.h"

#ifndef PT_VIEWER_WEB_DIR
#error "PT_VIEWER_WEB_DIR names the folder of the page's files (app/viewer/web)"
#endif

namespace pt {
namespace {

struct ViewerCommand {
  std::string scene;
  int port = 8184;
  int threads = 0;
  bool no_restart = false;
  std::vector<std::string> flags;  ///< the first render's, as the pathtracer takes them
};

/// A free port on 127.0.0.1 for --port 0, chosen once, so that a server started again after a
/// crash listens where the page already is.
int free_port() {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return 0;
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = 0;
  socklen_t len = sizeof a;
  int port = 0;
  if (::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0 &&
      getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len) == 0)
    port = ntohs(a.sin_port);
  close(fd);
  return port;
}

/// What a server that crashes while it starts was doing.
constexpr const char* kStartingUp = "read the scene and built the first render's tree (Part 2)";

/// One server's life: load the scene, listen, answer. Returns the exit code.
int serve(const ViewerCommand& c, const std::string& token, const std::string& crash_note,
          bool announce, bool warm_up) {
  TerminalLog log;
  log.start();
  // Said here rather than by the supervisor, so that the page's terminal shows it too.
  if (!crash_note.empty()) std::cerr << "viewer: " << crash_note << std::endl;
  RenderSession session(c.scene, c.threads);
  std::string error;
  set_thread_activity(kStartingUp);
  const bool loaded = session.load(&error, warm_up);
  set_thread_activity("");
  if (!loaded)
    std::cerr << "viewer: " << error << " (the page shows it; fix the file and press Reload)"
              << std::endl;
  ViewerServerOptions options;
  options.port = c.port;
  options.token = token;
  options.web_dir = PT_VIEWER_WEB_DIR;
  options.crash_note = crash_note;
  options.initial_flags = c.flags;
  ViewerServer server(&session, &log, options);
  try {
    server.bind();
  } catch (const std::exception& e) {
    std::cerr << "viewer: " << e.what() << std::endl;
    return kExitIoError;
  }
  if (announce) {
    std::cout << "viewer: " << c.scene << "\nviewer: open " << server.url()
              << "\n        (over SSH: ssh -L " << server.port() << ":127.0.0.1:" << server.port()
              << " HOST, then open the same address here)" << std::endl;
  }
  server.listen();
  return kExitOk;
}

/// The server's process while the supervisor waits for it: a SIGTERM, SIGINT or SIGHUP sent to
/// the supervisor (by a test, or a terminal closing) is passed on, so no server outlives it.
volatile sig_atomic_t g_server_pid = 0;

void pass_on(int sig) {
  if (g_server_pid > 0) kill(pid_t(g_server_pid), sig);
  signal(sig, SIG_DFL);
  raise(sig);
}

const char* signal_name(int sig) {
  const char* d = strsignal(sig);
  return d ? d : "unknown signal";
}

/// What the crashed server's witness wrote (install_crash_witness): what it was doing.
std::string read_witness(int fd) {
  std::string what;
  char buffer[256];
  for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) > 0;) what.append(buffer, size_t(n));
  return what;
}

int run(int argc, char** argv) {
  ViewerCommand c;
  CLI::App app{"Serves a page on 127.0.0.1 that previews a COLLADA scene, renders it with your "
               "code tile by tile, and shows what the code did: the BVH, one pixel's paths.",
               "viewer"};
  app.add_option("scene", c.scene, "The scene (COLLADA .dae)")->required();
  app.add_option("--port", c.port, "Port on 127.0.0.1 (0: any free port)")->capture_default_str()
      ->check(CLI::Range(0, 65535));
  app.add_option("-t,--threads", c.threads, "Render threads; 0 uses every core")->capture_default_str()
      ->check(CLI::Range(0, 1024));
  app.add_flag("--no-restart",  c.no_restart,
               "Do not start the server again when a render crashes it (for a debugger)");
  int samples = 1, light_samples = 1, depth = 1;
  std::vector<int> resolution;
  std::vector<double> adaptive;
  bool hemisphere = false;
  std::string camera, seed;
  app.add_option("-s,--samples", samples, "First render: camera rays per pixel")->capture_default_str();
  app.add_option("-l,--light-samples", light_samples, "First render: samples per area light")
      ->capture_default_str();
  app.add_option("-m,--max-depth", depth, "First render: maximum ray depth")->capture_default_str();
  app.add_flag("-H,--hemisphere", hemisphere, "First render: uniform hemisphere sampling");
  app.add_option("-a,--adaptive", adaptive, "First render: adaptive sampling, BATCH TOL")
      ->expected(2)->type_name("BATCH TOL");
  app.add_option("-r,--resolution", resolution, "Image width and height")->expected(2)->type_name("W H");
  app.add_option("--camera", camera, "First render's camera, as the pathtracer's --camera")
      ->type_name("px,py,pz,tx,ty,tz,ux,uy,uz,fov");
  app.add_option("--seed", seed, "Random seed")->type_name("UINT");
  if (auto code = parse_or_exit(app, argc, argv, "viewer", "Run with --help for the options.",
                                std::cout, std::cerr))
    return *code;

  c.flags = {"-s", std::to_string(samples), "-l", std::to_string(light_samples), "-m",
             std::to_string(depth)};
  if (hemisphere) c.flags.push_back("-H");
  if (!adaptive.empty()) {
    std::ostringstream b, t;
    b << adaptive[0];
    t << adaptive[1];
    c.flags.insert(c.flags.end(), {"-a", b.str(), t.str()});
  }
  if (!resolution.empty())
    c.flags.insert(c.flags.end(), {"-r", std::to_string(resolution[0]), std::to_string(resolution[1])});
  if (!camera.empty()) c.flags.insert(c.flags.end(), {"--camera", camera});
  if (!seed.empty()) c.flags.insert(c.flags.end(), {"--seed", seed});
  try {
    parse_viewer_flags(c.flags, c.scene, c.threads);
  } catch (const std::invalid_argument& e) {
    std::cerr << "viewer: " << e.what() << "\n";
    return kExitUsage;
  }

  if (c.port == 0) c.port = free_port();
  const std::string token = make_token();
  if (c.no_restart) return serve(c, token, "", true, true);

  // A crash in a student's function (a segfault, an abort) ends the process that ran it: the
  // server runs in a child, and this process starts it again on the same port and token, so the
  // page stays where it is and says what happened.
  std::string note;
  std::string again = "gdb --args";  // this viewer, as it was started, without the restarts
  for (int i = 0; i < argc; ++i) again += " " + std::string(argv[i]);
  again += " --no-restart";
  int crashes = 0, recent = 0;
  bool warm_up = true;
  auto window_start = std::chrono::steady_clock::now();
  for (bool first = true;; first = false) {
    std::cout.flush();
    int witness[2] = {-1, -1};
    if (pipe(witness) != 0) witness[0] = witness[1] = -1;
    const pid_t child = fork();
    if (child < 0) return serve(c, token, "", true, true);
    if (child == 0) {
      for (int sig : {SIGTERM, SIGINT, SIGHUP}) signal(sig, SIG_DFL);
      if (witness[0] >= 0) close(witness[0]);
      install_crash_witness(witness[1]);
      _exit(serve(c, token, note, first, warm_up));
    }
    if (witness[1] >= 0) close(witness[1]);
    g_server_pid = child;
    for (int sig : {SIGTERM, SIGINT, SIGHUP}) signal(sig, pass_on);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    const std::string what = witness[0] >= 0 ? read_witness(witness[0]) : "";
    if (witness[0] >= 0) close(witness[0]);
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    const int sig = WTERMSIG(status);
    if (sig == SIGINT || sig == SIGTERM || sig == SIGHUP || sig == SIGKILL) return 128 + sig;
    const auto now = std::chrono::steady_clock::now();
    if (now - window_start > std::chrono::minutes(1)) window_start = now, recent = 0;
    ++crashes;
    // A crash while it built the first render's tree (Part 2) would come again at once: the
    // next server builds it when the page asks, so the page opens and says what happened.
    if (what == kStartingUp) warm_up = false;
    note = std::string("the viewer's server crashed (") + signal_name(sig) + ")" +
           (what.empty() ? "" : " while it " + what) +
           ", most likely in a function you wrote; it was started again (crash " +
           std::to_string(crashes) + "). To find the line, run the viewer under gdb (" + again +
           "), do the same on the page, and type bt where it stops" +
           (what.rfind("rendered: ", 0) == 0 ? "; or run that pathtracer command under gdb." : ".");
    // A crash in a request or a render took the page's asking, and the page's next request
    // deserves a server; one anywhere else could come again by itself: stop after five.
    const bool asked = what.rfind("answered ", 0) == 0 || what.rfind("rendered: ", 0) == 0;
    if (!asked && ++recent > 5) {
      std::cerr << "viewer: " << note << "\nviewer: it crashed " << recent
                << " times in a minute; stopping" << std::endl;
      return kExitIoError;
    }
  }
}

}  // namespace
}  // namespace pt

int main(int argc, char** argv) {
  try {
    return pt::run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "viewer: " << e.what() << "\n";
    return pt::kExitIoError;
  }
}
