// A stand-in for the pathtracer in the website's tests: takes the same -r/-f flags, writes a
// small gradient PNG (and a "_rate" image with -a), and logs each run, so the tests can count
// renders without waiting for real ones. `--fail` makes it exit with an error message.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  int w = 16, h = 12;
  std::string out;
  bool adaptive = false;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "-r" && i + 2 < argc) {
      w = std::atoi(argv[i + 1]);
      h = std::atoi(argv[i + 2]);
      i += 2;
    } else if (a == "-f" && i + 1 < argc) {
      out = argv[++i];
    } else if (a == "-a") {
      adaptive = true;
    } else if (a == "--fail") {
      std::cerr << "error: scene has no camera\n";
      return 3;
    }
  }
  if (const char* log = std::getenv("FAKE_PATHTRACER_LOG")) {
    std::ofstream(log, std::ios::app) << "run\n";
  }
  if (out.empty() || w <= 0 || h <= 0) return 2;
  auto write = [&](const std::string& file) {
    std::vector<unsigned char> px(static_cast<size_t>(w) * h * 3);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        unsigned char* p = &px[(static_cast<size_t>(y) * w + x) * 3];
        p[0] = static_cast<unsigned char>(255 * x / std::max(1, w - 1));
        p[1] = static_cast<unsigned char>(255 * y / std::max(1, h - 1));
        p[2] = 128;
      }
    }
    auto o = OIIO::ImageOutput::create(file);
    OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
    return o && o->open(file, spec) && o->write_image(OIIO::TypeDesc::UINT8, px.data()) &&
           o->close();
  };
  if (!write(out)) return 4;
  if (adaptive) {
    std::string rate = out.substr(0, out.size() - 4) + "_rate.png";
    if (!write(rate)) return 4;
  }
  return 0;
}
