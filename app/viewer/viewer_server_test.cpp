// The viewer's server, over HTTP on 127.0.0.1: what it refuses (another Host, no token, a path
// outside its page, a scene that does not load, flags the pathtracer refuses), and that what it
// renders is the pathtracer's render job's image to the byte.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include "app/accelerator.h"
#include "app/render_job.h"
#include "app/viewer/render_session.h"
#include "app/viewer/viewer_server.h"
#include "framework/image/image.h"
#include "framework/scene/camera_placement.h"
#include "framework/scene/collada_loader.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace pt {
namespace {

const char* const kToken = "0123456789abcdef0123456789abcdef";

/// A viewer on a free port of 127.0.0.1, answering from a thread of its own.
class Viewer {
 public:
  explicit Viewer(const std::string& scene) : session_(scene, 2) {
    session_.load(nullptr);
    ViewerServerOptions o;
    o.port = 0;
    o.token = kToken;
    o.web_dir = PT_VIEWER_WEB_DIR;
    server_ = std::make_unique<ViewerServer>(&session_, nullptr, o);
    port_ = server_->bind();
    thread_ = std::thread([this] { server_->listen(); });
  }
  ~Viewer() {
    server_->stop();
    thread_.join();
    session_.cancel();
  }
  int port() const { return port_; }
  std::string host() const { return "127.0.0.1:" + std::to_string(port_); }
  httplib::Client client() const {
    httplib::Client c("127.0.0.1", port_);
    c.set_read_timeout(60, 0);
    return c;
  }
  /// POST `body` to `path` with the token.
  httplib::Result post(const std::string& path, const json& body) const {
    return client().Post((path + "?token=" + kToken).c_str(), body.dump(), "application/json");
  }
  json status() const {
    auto r = client().Get((std::string("/api/status?token=") + kToken).c_str());
    return r && r->status == 200 ? json::parse(r->body) : json();
  }
  /// Polls the status until the render is no longer running.
  json wait() const {
    for (int i = 0; i < 6000; ++i) {
      json s = status();
      if (s.value("state", "") != "rendering") return s;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return status();
  }

 private:
  RenderSession session_;
  std::unique_ptr<ViewerServer> server_;
  int port_ = 0;
  std::thread thread_;
};

TEST(ViewerServer, RefusesARequestForAnotherHost) {
  Viewer v(PT_VIEWER_TEST_SCENE);
  httplib::Client c = v.client();
  const std::string tokened = std::string("/?token=") + kToken;
  // A page elsewhere whose name was made to resolve to 127.0.0.1 sends its own name as Host.
  for (const std::string& host : {std::string("evil.example:") + std::to_string(v.port()),
                                 std::string("evil.example"), std::string("127.0.0.1"),
                                 "127.0.0.1:" + std::to_string(v.port() + 1),
                                 "localhost:" + std::to_string(v.port()) + ".evil.example",
                                 std::string("")}) {
    auto r = c.Get(tokened.c_str(), {{"Host", host}});
    ASSERT_TRUE(r) << host;
    EXPECT_EQ(r->status, 403) << "Host '" << host << "' was answered";
    EXPECT_EQ(r->body.find("<html"), std::string::npos) << host;
  }
  for (const std::string& host : {v.host(), "localhost:" + std::to_string(v.port())}) {
    auto r = c.Get(tokened.c_str(), {{"Host", host}});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << "Host '" << host << "' was refused";
  }
  EXPECT_FALSE(host_is_ours("127.0.0.2:" + std::to_string(v.port()), v.port()));
}

TEST(ViewerServer, RefusesARequestWithoutTheToken) {
  Viewer v(PT_VIEWER_TEST_SCENE);
  httplib::Client c = v.client();
  for (const char* path : {"/", "/index.html", "/viewer.js", "/api/status", "/api/image",
                           "/?token=", "/?token=0123456789abcdef0123456789abcdee",
                           "/?token=0123456789abcdef", "/api/status?token=x"}) {
    auto r = c.Get(path);
    ASSERT_TRUE(r) << path;
    EXPECT_EQ(r->status, 403) << path << " was answered without the token";
  }
  auto post = c.Post("/api/render", R"({"flags":["-s","1"]})", "application/json");
  ASSERT_TRUE(post);
  EXPECT_EQ(post->status, 403);
  // A cookie of the wrong value, or for another port's viewer, is no token either.
  auto wrong = c.Get("/api/status", {{"Cookie", "pt_viewer_" + std::to_string(v.port()) + "=nope"}});
  ASSERT_TRUE(wrong);
  EXPECT_EQ(wrong->status, 403);
  auto other = c.Get("/api/status", {{"Cookie", "pt_viewer_1=" + std::string(kToken)}});
  ASSERT_TRUE(other);
  EXPECT_EQ(other->status, 403);

  // The token in the query opens the page and sets the cookie the page's requests then carry.
  auto page = c.Get((std::string("/?token=") + kToken).c_str());
  ASSERT_TRUE(page);
  ASSERT_EQ(page->status, 200);
  EXPECT_NE(page->body.find("<html"), std::string::npos);
  const std::string cookie = page->get_header_value("Set-Cookie");
  EXPECT_NE(cookie.find("pt_viewer_" + std::to_string(v.port()) + "=" + kToken), std::string::npos) << cookie;
  EXPECT_NE(cookie.find("HttpOnly"), std::string::npos) << cookie;
  EXPECT_NE(cookie.find("SameSite=Strict"), std::string::npos) << cookie;
  auto with_cookie = c.Get("/api/status", {{"Cookie", cookie.substr(0, cookie.find(';'))}});
  ASSERT_TRUE(with_cookie);
  EXPECT_EQ(with_cookie->status, 200);
}

TEST(ViewerServer, ServesOnlyItsOwnFiles) {
  Viewer v(PT_VIEWER_TEST_SCENE);
  httplib::Client c = v.client();
  const std::string t = std::string("token=") + kToken;
  for (const char* path : {"/../../../../etc/passwd", "/%2e%2e/%2e%2e/%2e%2e/etc/passwd",
                           "/..%2f..%2f..%2fetc%2fpasswd", "/etc/passwd", "/CMakeLists.txt",
                           "/viewer_main.cpp", "/web/index.html", "/index.html/..", "//etc/passwd",
                           "/./viewer.js/../../CMakeLists.txt", "/browser_test.js"}) {
    auto r = c.Get((std::string(path) + "?" + t).c_str());
    ASSERT_TRUE(r) << path;
    EXPECT_NE(r->status, 200) << path << " was served";
    EXPECT_EQ(r->body.find("root:"), std::string::npos) << path;
    EXPECT_EQ(r->body.find("cmake"), std::string::npos) << path;
  }
  for (const char* path : {"/", "/index.html", "/viewer.js", "/preview.js", "/viewer.css"}) {
    auto r = c.Get((std::string(path) + "?" + t).c_str());
    ASSERT_TRUE(r) << path;
    EXPECT_EQ(r->status, 200) << path;
  }
  EXPECT_EQ(static_file_type("/../viewer.js"), nullptr);
  EXPECT_EQ(static_file_type("viewer.js"), nullptr);
}

TEST(ViewerServer, ASceneThatDoesNotLoadIsAMessageAndTheServerStaysUp) {
  const fs::path dir = fs::temp_directory_path() / ("pt_viewer_test_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string broken = (dir / "broken.dae").string();
  std::ofstream(broken) << "<COLLADA><library_geometries><geometry id=\"g\"><mesh>";
  {
    Viewer v(broken);
    json s = v.status();
    EXPECT_EQ(s.value("state", ""), "empty");
    EXPECT_NE(s.value("load_error", "").find("broken.dae"), std::string::npos) << s.dump();
    auto r = v.post("/api/render", {{"flags", {"-s", "1"}}});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400);
    EXPECT_NE(json::parse(r->body).value("error", "").find("broken.dae"), std::string::npos) << r->body;
    for (const char* path : {"/api/scene", "/api/bvh", "/api/pixel"}) {
      auto q = v.post(path, {{"flags", json::array()}, {"x", 0}, {"y", 0}});
      ASSERT_TRUE(q) << path;
      EXPECT_EQ(q->status, 400) << path;
      EXPECT_NE(json::parse(q->body).value("error", "").find("broken.dae"), std::string::npos) << q->body;
    }
    // Mended and reloaded, it renders.
    fs::copy_file(PT_VIEWER_TEST_SCENE, broken, fs::copy_options::overwrite_existing);
    auto reload = v.post("/api/reload", json::object());
    ASSERT_TRUE(reload);
    EXPECT_EQ(reload->status, 200) << reload->body;
    auto again = v.post("/api/render", {{"flags", {"-r", "16", "12"}}});
    ASSERT_TRUE(again);
    EXPECT_EQ(again->status, 200) << again->body;
    EXPECT_EQ(v.wait().value("state", ""), "done");
  }
  {
    Viewer v((dir / "absent.dae").string());
    EXPECT_NE(v.status().value("load_error", "").find("absent.dae"), std::string::npos);
  }
  fs::remove_all(dir);
}

TEST(ViewerServer, RefusesFlagsThePathtracerRefusesOrThatNameFiles) {
  Viewer v(PT_VIEWER_TEST_SCENE);
  struct Case {
    json flags;
    std::string mention;
  };
  const Case cases[] = {
      {{"-s", "0"}, "--samples"},
      {{"-m", "-1"}, "--max-depth"},
      {{"-f", "/tmp/out.png"}, "-f"},
      {{"--file=/tmp/out.png"}, "--file"},
      {{"-e", "/etc/passwd"}, "-e"},
      {{"-t", "64"}, "-t"},
      {{"/etc/passwd.dae"}, "passwd.dae"},
      {{"--camera", "1,2,3"}, "ten numbers"},
      {{"-p", "0", "0", "999", "1"}, "--cell"},
      {{1, 2}, "list of words"},
  };
  for (const Case& c : cases) {
    auto r = v.post("/api/render", {{"flags", c.flags}});
    ASSERT_TRUE(r) << c.flags.dump();
    EXPECT_EQ(r->status, 400) << c.flags.dump();
    EXPECT_NE(r->body.find(c.mention), std::string::npos) << c.flags.dump() << ": " << r->body;
  }
  auto junk = v.client().Post((std::string("/api/render?token=") + kToken).c_str(), "{not json",
                              "application/json");
  ASSERT_TRUE(junk);
  EXPECT_EQ(junk->status, 400);
  EXPECT_EQ(v.status().value("state", ""), "idle");  // nothing started, and still answering
}

// The page's image is the render job's: the same flags rendered by render_scene, as the
// pathtracer renders them, give the same bytes its PNG would hold; a pixel explained has the
// value the render gave it.
TEST(ViewerServer, RendersThePathtracersImageAndExplainsItsPixels) {
  Viewer v(PT_VIEWER_TEST_SCENE);
  const json flags = {"-r", "40", "30", "-s", "4", "-l", "2", "-m", "3", "--seed", "7"};
  auto r = v.post("/api/render", {{"flags", flags}});
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const json s = v.wait();
  ASSERT_EQ(s.value("state", ""), "done") << s.dump();
  EXPECT_NE(s.value("summary", "").find("render: 40x30, 4 spp"), std::string::npos) << s.dump();
  EXPECT_GT(s["counts"].value("primitive_tests_per_ray", 0.0), 0.0) << s.dump();
  auto image = v.client().Get((std::string("/api/image?token=") + kToken).c_str());
  ASSERT_TRUE(image);
  ASSERT_EQ(image->body.size(), 8u + 40u * 30u * 4u);

  Scene scene = load_collada(PT_VIEWER_TEST_SCENE);
  ViewerRender render = parse_viewer_flags(flags.get<std::vector<std::string>>(), PT_VIEWER_TEST_SCENE, 2);
  centre_camera_on(scene.bounds(), &scene.camera);
  const RenderSettings& settings = render.command.settings;
  std::unique_ptr<RayQuery> query = make_ray_query(settings, scene);
  Film film(40, 30);
  render_scene(settings, scene, *query, &film);
  long differ = 0;
  for (size_t i = 0; i < film.pixels().size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const float linear = float(film.pixels()[i].mean[c]);
      const int expected = int(std::lround(255.0f * srgb_encode(linear)));
      differ += uint8_t(image->body[8 + 4 * i + size_t(c)]) != expected;
    }
  EXPECT_EQ(differ, 0) << "bytes differ from the render job's image";

  for (auto [x, y] : {std::pair{20, 15}, std::pair{3, 27}}) {
    auto p = v.post("/api/pixel", {{"flags", flags}, {"x", x}, {"y", y}});
    ASSERT_TRUE(p);
    ASSERT_EQ(p->status, 200) << p->body;
    const json px = json::parse(p->body);
    for (int c = 0; c < 3; ++c)
      EXPECT_FLOAT_EQ(px["value"][size_t(c)].get<float>(), float(film.at(x, y).mean[c])) << x << "," << y;
    ASSERT_EQ(px["samples"].size(), 4u);
    EXPECT_EQ(px["samples"][0]["rays"][0].value("kind", ""), "trace");  // the camera ray first
    for (const json& sample : px["samples"]) {
      EXPECT_EQ(sample["bounces"].size(), 4u);  // -m 3: bounces 0 .. 3
      // What the bounces added sums to the sample: they are the very path's.
      EXPECT_TRUE(sample.value("bounces_add_up", false)) << sample.dump();
    }
  }
  auto outside = v.post("/api/pixel", {{"flags", flags}, {"x", 40}, {"y", 0}});
  ASSERT_TRUE(outside);
  EXPECT_EQ(outside->status, 400);
}

TEST(ViewerServer, TheBvhIsPartTwosTreeWithItsCosts) {
  Viewer v(PT_VIEWER_TEST_SCENE);
  auto r = v.post("/api/bvh", {{"flags", {"--leaf-size", "2"}}});
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const json b = json::parse(r->body);
  const size_t n = b["left"].size();
  ASSERT_GT(n, 1u);
  ASSERT_EQ(b["boxes"].size(), 6 * n);
  EXPECT_EQ(b["primitives_below"][0].get<int>(), b["stats"]["primitives"].get<int>());
  // The root's cost, relative to its own box, is the tree's SAH cost as --info states it.
  EXPECT_NEAR(b["sah_cost"][0].get<double>(), b["stats"]["sah_cost"].get<double>(),
              1e-6 * b["stats"]["sah_cost"].get<double>());
  for (size_t i = 0; i < n; ++i)
    if (b["left"][i].get<int>() >= 0) {
      const int l = b["left"][i], rr = b["right"][i];
      EXPECT_EQ(b["parent"][size_t(l)].get<int>(), int(i));
      EXPECT_EQ(b["parent"][size_t(rr)].get<int>(), int(i));
      EXPECT_EQ(b["depth"][size_t(l)].get<int>(), b["depth"][i].get<int>() + 1);
    } else {
      EXPECT_LE(b["count"][i].get<int>(), 2);
    }
  // A ray from outside the box towards its centre ends in a leaf holding the primitive it hit.
  auto p = v.post("/api/pick", {{"flags", json::array()}, {"origin", {0.0, 0.0, 10.0}},
                                {"direction", {0.0, 0.0, -1.0}}});
  ASSERT_TRUE(p);
  ASSERT_EQ(p->status, 200) << p->body;
  const json pick = json::parse(p->body);
  if (pick.value("hit", false)) {
    ASSERT_TRUE(pick.contains("leaf")) << pick.dump();
  }
}

}  // namespace
}  // namespace pt

namespace pt {
namespace {

// The sampling panel runs the tests' chi-square check: the framework's warps pass it, their
// histogram holds every sample, and a name or count it does not know is a message.
TEST(ViewerServer, SamplingPanelRunsTheChiSquareTest) {
  Viewer v(PT_VIEWER_TEST_SCENE);
  for (const char* name : {"cosine_hemisphere", "uniform_sphere"}) {
    auto r = v.post("/api/sampling", {{"name", name}, {"samples", 100000}});
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    const json j = json::parse(r->body);
    EXPECT_TRUE(j.value("passes", false)) << name << ": " << j.value("summary", "");
    double total = 0.0;
    for (const json& o : j["observed"]) total += o.get<double>();
    EXPECT_EQ(total, 100000.0) << name;
    EXPECT_EQ(j["observed"].size(), size_t(j["cos_bins"].get<int>() * j["phi_bins"].get<int>() + 1));
    EXPECT_GT(j["points"].size(), 3000u);
  }
  // The uniform hemisphere's histogram has no sample below the surface.
  auto h = v.post("/api/sampling", {{"name", "uniform_hemisphere"}, {"samples", 50000}});
  ASSERT_TRUE(h);
  const json hj = json::parse(h->body);
  const int cols = hj["phi_bins"].get<int>(), rows = hj["cos_bins"].get<int>();
  for (int cell = 0; cell < rows / 2 * cols; ++cell) EXPECT_EQ(hj["observed"][size_t(cell)].get<double>(), 0.0);
  for (const json& bad : {json{{"name", "square_to_nothing"}}, json{{"name", "cosine_hemisphere"}, {"samples", 10}},
                          json{{"samples", 1000}}}) {
    auto r = v.post("/api/sampling", bad);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400) << bad.dump();
  }
}

}  // namespace
}  // namespace pt

namespace pt {
namespace {

// Part 5's sample-rate image: drawn after an adaptive render, refused before one.
TEST(ViewerServer, SampleRateImageAfterAnAdaptiveRender) {
  Viewer v(PT_VIEWER_TEST_SCENE);
  const std::string rate = std::string("/api/image?kind=rate&token=") + kToken;
  auto plain = v.post("/api/render", {{"flags", {"-r", "24", "18", "-s", "2"}}});
  ASSERT_TRUE(plain);
  ASSERT_EQ(v.wait().value("state", ""), "done");
  auto refused = v.client().Get(rate.c_str());
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 400);
  EXPECT_NE(refused->body.find("adaptive"), std::string::npos) << refused->body;

  auto adaptive = v.post("/api/render", {{"flags", {"-r", "24", "18", "-s", "64", "-a", "8", "0.2", "-m", "2"}}});
  ASSERT_TRUE(adaptive);
  ASSERT_EQ(adaptive->status, 200) << adaptive->body;
  ASSERT_EQ(v.wait().value("state", ""), "done");
  auto r = v.client().Get(rate.c_str());
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  ASSERT_EQ(r->body.size(), 8u + 24u * 18u * 4u);
  // Where the samples went differs from pixel to pixel: the map is not one colour.
  bool varies = false;
  for (size_t i = 8 + 4; i < r->body.size(); i += 4)
    varies |= r->body.compare(i, 3, r->body, 8, 3) != 0;
  EXPECT_TRUE(varies);
}

}  // namespace
}  // namespace pt
