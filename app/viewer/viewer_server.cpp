#include "app/viewer/viewer_server.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <stdexcept>

#include <httplib.h>

#include "app/viewer/crash_witness.h"
#include "app/viewer/sampling_check.h"
#include "framework/render/tile_renderer.h"

namespace pt {

namespace {

using nlohmann::json;

/// Requests the page sends are small JSON objects: anything larger is refused unread.
constexpr size_t kMaxRequestBytes = 64 * 1024;

/// JSON replies are sent as "application/json; charset=utf-8": cpp-httplib compresses only the
/// bare "application/json", and its Brotli at the default quality took seconds over a scene's
/// triangles, which over the loopback buys nothing.
void send_json(httplib::Response& res, const json& body, int status = 200) {
  res.status = status;
  // error_handler_t::replace: a stub's odd bytes in a name never turn a reply into an exception.
  res.set_content(body.dump(-1, ' ', false, json::error_handler_t::replace),
                  "application/json; charset=utf-8");
}

void send_error(httplib::Response& res, int status, const std::string& message) {
  send_json(res, {{"error", message}}, status);
}

json request_json(const httplib::Request& req) {
  if (req.body.empty()) return json::object();
  json j = json::parse(req.body, nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw std::invalid_argument("the request is not a JSON object");
  return j;
}

std::vector<std::string> request_flags(const json& j) {
  std::vector<std::string> flags;
  if (!j.contains("flags")) return flags;
  if (!j["flags"].is_array()) throw std::invalid_argument("flags must be a list of words");
  for (const json& f : j["flags"]) {
    if (!f.is_string()) throw std::invalid_argument("flags must be a list of words");
    flags.push_back(f.get<std::string>());
  }
  if (flags.size() > 64) throw std::invalid_argument("too many flags");
  return flags;
}

glm::vec3 request_vec3(const json& j, const char* name) {
  if (!j.contains(name) || !j[name].is_array() || j[name].size() != 3)
    throw std::invalid_argument(std::string(name) + " must be three numbers");
  glm::vec3 v;
  for (int i = 0; i < 3; ++i) {
    if (!j[name][size_t(i)].is_number()) throw std::invalid_argument(std::string(name) + " must be three numbers");
    v[i] = j[name][size_t(i)].get<float>();
  }
  return v;
}

int request_int(const json& j, const char* name) {
  if (!j.contains(name) || !j[name].is_number_integer())
    throw std::invalid_argument(std::string(name) + " must be a whole number");
  return j[name].get<int>();
}

std::string cookie_token(const std::string& cookies, const std::string& name) {
  // "a=1; pt_viewer_8184=TOKEN; b=2"
  size_t at = 0;
  while (at < cookies.size()) {
    size_t end = cookies.find(';', at);
    if (end == std::string::npos) end = cookies.size();
    std::string pair = cookies.substr(at, end - at);
    while (!pair.empty() && pair.front() == ' ') pair.erase(pair.begin());
    if (pair.rfind(name + "=", 0) == 0) return pair.substr(name.size() + 1);
    at = end + 1;
  }
  return "";
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot read the viewer's page file");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::string make_token() {
  std::random_device device;
  std::string token;
  for (int i = 0; i < 4; ++i) {
    char buffer[9];
    std::snprintf(buffer, sizeof buffer, "%08x", unsigned(device()));
    token += buffer;
  }
  return token;
}

bool host_is_ours(const std::string& host, int port) {
  const std::string p = ":" + std::to_string(port);
  return host == "127.0.0.1" + p || host == "localhost" + p;
}

bool same_token(const std::string& a, const std::string& b) {
  if (a.size() != b.size() || a.empty()) return false;
  unsigned char diff = 0;
  for (size_t i = 0; i < a.size(); ++i) diff |= (unsigned char)(a[i] ^ b[i]);
  return diff == 0;
}

const char* static_file_type(const std::string& path) {
  static const std::pair<const char*, const char*> kFiles[] = {
      {"/index.html", "text/html; charset=utf-8"},
      {"/viewer.css", "text/css; charset=utf-8"},
      {"/viewer.js", "application/javascript; charset=utf-8"},
      {"/preview.js", "application/javascript; charset=utf-8"},
  };
  for (const auto& [name, type] : kFiles)
    if (path == name) return type;
  return nullptr;
}

ViewerServer::ViewerServer(RenderSession* session, TerminalLog* log, ViewerServerOptions options)
    : session_(session), log_(log), options_(std::move(options)),
      server_(std::make_unique<httplib::Server>()) {
  if (options_.token.empty()) options_.token = make_token();
  routes();
}

ViewerServer::~ViewerServer() { stop(); }

int ViewerServer::bind() {
  const std::string where = "127.0.0.1:" + std::to_string(options_.port);
  if (options_.port == 0) {
    port_ = server_->bind_to_any_port("127.0.0.1");
    if (port_ <= 0) throw std::runtime_error("cannot listen on 127.0.0.1: no free port");
  } else {
    if (!server_->bind_to_port("127.0.0.1", options_.port))
      throw std::runtime_error("cannot listen on " + where +
                               " (is another viewer running there? try --port 0 for any free port)");
    port_ = options_.port;
  }
  return port_;
}

void ViewerServer::listen() { server_->listen_after_bind(); }

void ViewerServer::stop() {
  if (server_) server_->stop();
}

std::string ViewerServer::url() const {
  return "http://127.0.0.1:" + std::to_string(port_) + "/?token=" + options_.token;
}

void ViewerServer::routes() {
  httplib::Server& s = *server_;
  s.set_payload_max_length(kMaxRequestBytes);
  // One request per connection: a browser sends a request again, unasked, when a connection it
  // kept open closes without a reply, and a crash in the student's code closes it, so a kept
  // connection would run the crashing request twice (the second on the server started again).
  // Over the loopback a new connection costs nothing to speak of.
  s.set_keep_alive_max_count(1);

  // Every request, before it is routed: the Host header must name this server, and the token
  // must come with it (in the query, or in the cookie the first tokened request set).
  s.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    res.set_header("Cache-Control", "no-store");
    res.set_header("X-Content-Type-Options", "nosniff");
    res.set_header("Referrer-Policy", "no-referrer");
    res.set_header("Content-Security-Policy",
                   "default-src 'self'; img-src 'self' data: blob:; style-src 'self' 'unsafe-inline'; "
                   "script-src 'self'; connect-src 'self'; frame-ancestors 'none'");
    const std::string host = req.get_header_value("Host");
    if (!host_is_ours(host, port_)) {
      std::cerr << "viewer: refused " << req.method << " " << req.path << ": Host '" << host
                << "' is not 127.0.0.1:" << port_ << " or localhost:" << port_ << std::endl;
      send_error(res, 403, "this viewer answers requests for 127.0.0.1:" + std::to_string(port_) +
                               " or localhost:" + std::to_string(port_) + " only");
      return httplib::Server::HandlerResponse::Handled;
    }
    const std::string cookie = "pt_viewer_" + std::to_string(port_);
    const std::string given = req.has_param("token") ? req.get_param_value("token")
                                                     : cookie_token(req.get_header_value("Cookie"), cookie);
    if (!same_token(given, options_.token)) {
      std::cerr << "viewer: refused " << req.method << " " << req.path
                << ": no token, or not the one printed when the viewer started" << std::endl;
      send_error(res, 403, "open the address the viewer printed, with its token");
      return httplib::Server::HandlerResponse::Handled;
    }
    if (req.has_param("token"))
      res.set_header("Set-Cookie", cookie + "=" + options_.token +
                                       "; Path=/; HttpOnly; SameSite=Strict");
    // What a crash in this request would be told as (the student's code runs in some of them).
    set_thread_activity("answered " + req.method + " " + req.path);
    return httplib::Server::HandlerResponse::Unhandled;
  });
  s.set_post_routing_handler([](const httplib::Request&, httplib::Response&) { set_thread_activity(""); });

  // The page's own files, and nothing else: an unknown path is not found, never a file on disk.
  auto serve_file = [this](const httplib::Request& req, httplib::Response& res) {
    const std::string path = req.path == "/" ? "/index.html" : req.path;
    const char* type = static_file_type(path);
    if (!type) return send_error(res, 404, "not found");
    res.set_content(read_file(options_.web_dir + path), type);
  };
  s.Get("/", serve_file);
  s.Get("/index.html", serve_file);
  s.Get("/viewer.css", serve_file);
  s.Get("/viewer.js", serve_file);
  s.Get("/preview.js", serve_file);

  s.Get("/api/status", [this](const httplib::Request& req, httplib::Response& res) {
    json j = session_->status();
    size_t from = 0, next = 0;
    if (req.has_param("log")) from = size_t(std::strtoull(req.get_param_value("log").c_str(), nullptr, 10));
    if (log_) {
      j["log"] = log_->since(from, &next);
      j["log_next"] = next;
    }
    if (!options_.crash_note.empty()) j["crash"] = options_.crash_note;
    j["initial_flags"] = options_.initial_flags;
    send_json(res, j);
  });
  s.Post("/api/render", [this](const httplib::Request& req, httplib::Response& res) {
    session_->start(request_flags(request_json(req)));
    // The reply waits for a first tile's worth of pixels, up to a second, so the page draws its
    // first image as soon as it reads this reply.
    const long tile = TileRenderOptions{}.tile_size;
    session_->wait_for_pixels(tile * tile, 1000);
    send_json(res, session_->status());
  });
  s.Post("/api/cancel", [this](const httplib::Request&, httplib::Response& res) {
    session_->cancel();
    send_json(res, session_->status());
  });
  s.Post("/api/reload", [this](const httplib::Request&, httplib::Response& res) {
    std::string error;
    if (!session_->load(&error)) {
      std::cerr << "viewer: " << error << std::endl;
      return send_error(res, 422, error);
    }
    send_json(res, session_->status());
  });
  s.Get("/api/image", [this](const httplib::Request& req, httplib::Response& res) {
    int w = 0, h = 0;
    const bool rate = req.has_param("kind") && req.get_param_value("kind") == "rate";
    std::vector<uint8_t> rgba = session_->image_rgba(rate, &w, &h);
    // Width and height (little-endian 32-bit), then the RGBA bytes, top row first.
    std::string body(8, '\0');
    for (int i = 0; i < 4; ++i) {
      body[size_t(i)] = char((uint32_t(w) >> (8 * i)) & 0xff);
      body[size_t(4 + i)] = char((uint32_t(h) >> (8 * i)) & 0xff);
    }
    body.append(reinterpret_cast<const char*>(rgba.data()), rgba.size());
    res.set_content(body, "application/octet-stream");
  });
  s.Post("/api/scene", [this](const httplib::Request& req, httplib::Response& res) {
    send_json(res, session_->scene_json(request_flags(request_json(req))));
  });
  s.Post("/api/bvh", [this](const httplib::Request& req, httplib::Response& res) {
    send_json(res, session_->bvh_json(request_flags(request_json(req))));
  });
  s.Post("/api/pick", [this](const httplib::Request& req, httplib::Response& res) {
    const json j = request_json(req);
    send_json(res, session_->pick(request_flags(j), request_vec3(j, "origin"),
                                  request_vec3(j, "direction")));
  });
  s.Post("/api/pixel", [this](const httplib::Request& req, httplib::Response& res) {
    const json j = request_json(req);
    send_json(res, session_->explain_pixel(request_flags(j), request_int(j, "x"), request_int(j, "y")));
  });

  s.Post("/api/sampling", [](const httplib::Request& req, httplib::Response& res) {
    const json j = request_json(req);
    if (!j.contains("name") || !j["name"].is_string()) throw std::invalid_argument("name must be a sampler's name");
    const long samples = j.contains("samples") && j["samples"].is_number_integer() ? j["samples"].get<long>() : 200000;
    send_json(res, sampling_check(j["name"].get<std::string>(), samples));
  });

  // What a handler throws (flags the command line refuses, a scene that did not load, a
  // student's function that threw) is the page's message and the terminal's, never a dead server.
  s.set_exception_handler([](const httplib::Request& req, httplib::Response& res,
                             std::exception_ptr ep) {
    std::string message = "unknown error";
    int status = 500;
    try {
      std::rethrow_exception(ep);
    } catch (const std::invalid_argument& e) {
      message = e.what();
      status = 400;
    } catch (const std::exception& e) {
      message = e.what();
    } catch (...) {
    }
    std::cerr << "viewer: " << req.method << " " << req.path << ": " << message << std::endl;
    send_error(res, status, message);
  });
  s.set_error_handler([](const httplib::Request&, httplib::Response& res) {
    if (res.body.empty()) send_error(res, res.status, res.status == 404 ? "not found" : "refused");
  });
}

}  // namespace pt
