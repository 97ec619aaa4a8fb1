// A stand-in for the pathtracer (and for bench convergence) in the website's tests: takes the
// same -r/-f flags, writes a small gradient image at once (PNG, or a linear EXR), prints the
// pathtracer's summary line, writes a "_rate" image with -a, and logs each run, so the tests can
// count renders without waiting for real ones. The picture depends on the flags: -m K scales it
// by K/5 (so a difference of two depths is known), and the blue channel is a hash of the other
// flags (so two renders with different flags look different); --bvh none takes 100 times
// as long by its summary line. `--fail` exits with an error
// message, `--hang` sleeps for a minute. As `bench convergence` it writes bench's table and summary.
#include <OpenImageIO/imageio.h>

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

int convergence(const std::string& out_dir) {
  if (out_dir.empty()) return 2;
  std::ofstream(out_dir + "/convergence.csv")
      << "strategy,samples,seconds,relMSE,RMSE,budget\n"
         "hemisphere,1,0.1,2.0,1,1\nhemisphere,4,0.4,0.5,1,4\nhemisphere,16,1.6,0.125,1,16\n"
         "light,1,0.1,0.2,1,1\nlight,4,0.4,0.05,1,4\nlight,16,1.6,0.0125,1,16\n";
  std::ofstream(out_dir + "/convergence.json")
      << R"({"target": {"relMSE": 0.0125, "source": "light's last"}, "time_to_target": [
  {"strategy": "hemisphere", "seconds": 16.0, "extrapolated": true, "beyond_reach": false,
   "ratio_to_light": 10.0},
  {"strategy": "light", "seconds": 1.6, "extrapolated": false, "beyond_reach": false,
   "ratio_to_light": 1.0}]})";
  std::cout << "wrote " << out_dir << "/convergence.csv\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  int w = 16, h = 12;
  double scale = 1.0;
  std::string out, out_dir, flags;
  bool adaptive = false, study = false, brute_force = false;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "-r" && i + 2 < argc) {
      w = std::atoi(argv[i + 1]);
      h = std::atoi(argv[i + 2]);
      i += 2;
    } else if (a == "-f" && i + 1 < argc) {
      out = argv[++i];
    } else if (a == "--out" && i + 1 < argc) {
      out_dir = argv[++i];
    } else if (a == "-m" && i + 1 < argc) {
      scale = std::atoi(argv[++i]) / 5.0;
    } else if (a == "-a") {
      adaptive = true;
      flags += a;
    } else if (a == "convergence" && i == 1) {
      study = true;
    } else if (a == "--bvh" && i + 1 < argc) {
      brute_force = std::string(argv[++i]) == "none";
      flags += a + argv[i];
    } else if (a == "--fail") {
      std::cerr << "error: scene has no camera\n";
      return 3;
    } else if (a == "--hang") {
      sleep(60);
    } else if (i + 1 < argc) {
      flags += a;  // the scene (the last argument) does not change the picture
    }
  }
  if (const char* log = std::getenv("FAKE_PATHTRACER_LOG")) {
    std::ofstream(log, std::ios::app) << "run\n";
  }
  if (study) return convergence(out_dir);
  if (out.empty() || w <= 0 || h <= 0) return 2;
  unsigned hash = 2166136261u;
  for (unsigned char c : flags) hash = (hash ^ c) * 16777619u;
  auto write = [&](const std::string& file, bool linear) {
    std::vector<float> px(static_cast<size_t>(w) * h * 3);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        float* p = &px[(static_cast<size_t>(y) * w + x) * 3];
        p[0] = static_cast<float>(scale * x / std::max(1, w - 1));
        p[1] = static_cast<float>(scale * y / std::max(1, h - 1));
        p[2] = static_cast<float>((hash % 256) / 255.0);
      }
    }
    auto o = OIIO::ImageOutput::create(file);
    OIIO::ImageSpec spec(w, h, 3, linear ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    spec.channelnames = {"R", "G", "B"};
    return o && o->open(file, spec) && o->write_image(OIIO::TypeDesc::FLOAT, px.data()) &&
           o->close();
  };
  const bool exr = out.size() > 4 && out.substr(out.size() - 4) == ".exr";
  if (!write(out, exr)) return 4;
  std::cout << "render: " << w << "x" << h << (adaptive ? ", 12.5 spp on average" : ", 4 spp")
            << (brute_force ? ", 25.00 s" : ", 0.25 s") << ", 1.0 M rays/s, 2 threads\nwrote " << out
            << "\n";
  if (adaptive) {
    std::string rate = out.substr(0, out.size() - 4) + "_rate.png";
    if (!write(rate, false)) return 4;
  }
  return 0;
}
