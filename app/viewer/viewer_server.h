// The viewer's web server: the page's files and its JSON requests, on 127.0.0.1 only, answering
// only requests that carry the token it printed and name this machine's address as their Host.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "app/viewer/render_session.h"
#include "app/viewer/terminal_log.h"

namespace httplib {
class Server;
}

namespace pt {

/// Where and how the server listens.
struct ViewerServerOptions {
  int port = 0;            ///< 0: any free port (port() says which)
  std::string token;       ///< what every request must carry (?token= or the cookie it sets)
  std::string web_dir;     ///< the page's files (index.html, viewer.js, ...)
  std::string crash_note;  ///< why the server was started again, if it was (shown on the page)
  std::vector<std::string> initial_flags;  ///< the first render's flags, from the command line
};

/// A random token of 32 hexadecimal digits (128 bits from std::random_device).
std::string make_token();

/// Whether `host` (a request's Host header) names this server: 127.0.0.1:PORT or localhost:PORT.
/// Anything else (another name, another port, none) is refused, so a page elsewhere that makes a
/// name resolve to 127.0.0.1 (DNS rebinding) cannot reach the viewer.
bool host_is_ours(const std::string& host, int port);

/// Whether two tokens are equal, comparing every character whatever the first difference.
bool same_token(const std::string& a, const std::string& b);

/// The page's files, by the path the page asks for. Only these names are served: a path that is
/// not one of them (another file, a folder, "..") is not found, whatever it names on disk.
const char* static_file_type(const std::string& path);

class ViewerServer {
 public:
  ViewerServer(RenderSession* session, TerminalLog* log, ViewerServerOptions options);
  ~ViewerServer();
  /// Binds 127.0.0.1 at the port asked (or any). Returns the port; throws std::runtime_error
  /// naming the port when it cannot be had.
  int bind();
  /// Answers requests until stop(). Call bind() first.
  void listen();
  void stop();
  int port() const { return port_; }
  /// The address to open: http://127.0.0.1:PORT/?token=TOKEN
  std::string url() const;

 private:
  void routes();
  RenderSession* session_;
  TerminalLog* log_;
  ViewerServerOptions options_;
  std::unique_ptr<httplib::Server> server_;
  int port_ = 0;
};

}  // namespace pt
