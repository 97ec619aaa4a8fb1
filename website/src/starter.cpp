#include "website/src/starter.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace pt::web {
namespace {

/// Small, quick settings: the whole starting write-up renders in a minute or two on two cores.
constexpr const char* kSmall = "-t 0 -r 160 120";
constexpr const char* kTiny = "-t 0 -r 64 48";

class StarterWriter {
 public:
  explicit StarterWriter(const StarterOptions& o) : opt_(o) {}

  bool have(const std::string& scene) const {
    for (const fs::path& d : opt_.scene_dirs) {
      if (fs::is_regular_file(d / scene)) return true;
    }
    return false;
  }

  /// The first of `candidates` that exists, or "".
  std::string first(std::initializer_list<const char*> candidates) const {
    for (const char* c : candidates) {
      if (have(c)) return c;
    }
    return "";
  }

  std::string text() {
    std::ostringstream md;
    md << R"(# Path tracer write-up

*Your name, your partner's name.* Replace every paragraph in italics with your own words, keep the
renders, and add your own. Build the page with `website build writeup.md -o site` and check the
folder you submit with `website check site`.

Renders are made by the `render` and `grid` blocks below: each names a scene and the pathtracer
flags, and is rendered again only when the scene, the flags or the pathtracer change. Math is
written as in LaTeX: inline $L_o(p, \omega_o)$ or displayed:

$$L_o(p,\omega_o) = L_e(p,\omega_o) + \int_{H^2} f_r(p,\omega_i\to\omega_o)\,L_i(p,\omega_i)\,\cos\theta_i\,d\omega_i$$

## Part 1: Ray generation and scene intersection

*Explain how a camera ray is generated for a pixel sample and how you intersect triangles
(Möller–Trumbore or a watertight test) and spheres.* The renders show surface normals,
$n \mapsto (n + 1)/2$ as a colour.

)";
    grid(md, "Normals of the spheres, the coil and the teapot.", std::string(kSmall) + " --normals",
         {{first({"cornell_spheres.dae", "sky/CBspheres_lambertian.dae"}), "", "spheres"},
          {first({"cornell_coil.dae"}), "", "coil"},
          {first({"meshedit/teapot.dae"}), "", "teapot"}},
         3);
    md << R"(## Part 2: Bounding volume hierarchy

*Describe how you build the BVH (how you choose the split) and how traversal skips boxes.*
The table compares render times with and without the BVH; the time is under each render.

)";
    std::string big = first({"dense_mesh.dae"});
    std::string mid = first({"cornell_coil.dae"});
    std::string course = first({"sky/CBbunny.dae", "keenan/banana.dae"});
    std::vector<Cell> cells;
    if (!mid.empty()) {
      cells.push_back({mid, "", "coil, BVH"});
      cells.push_back({mid, "--bvh none", "coil, no BVH"});
    }
    if (!course.empty()) {
      cells.push_back({course, "", fs::path(course).stem().string() + ", BVH"});
      cells.push_back({course, "--bvh none -r 64 48", fs::path(course).stem().string() +
                                                          ", no BVH (64 × 48)"});
    }
    if (!big.empty()) {
      cells.push_back({big, "", "dense mesh (1M triangles), BVH"});
      cells.push_back({big, "--bvh none -r 32 24", "dense mesh, no BVH (32 × 24)"});
    } else {
      md << "*The dense mesh was not found: build it with `cmake --build build --target "
            "dense_mesh` and run `website init` again.*\n\n";
    }
    grid(md, "Large meshes with and without the BVH (normals, 1 sample per pixel).", std::string(kSmall) + " --normals",
         cells, 2);
    std::string cb = first({"cornell_spheres.dae", "sky/CBspheres_lambertian.dae"});
    md << R"(## Part 3: Direct illumination

*Explain uniform hemisphere sampling and light (importance) sampling, and why the second is less
noisy for the same number of samples.*

)";
    grid(md, "Hemisphere sampling against light sampling, 16 samples per pixel, 1 light ray.",
         std::string(kSmall) + " -s 16 -l 1 -m 1",
         {{cb, "-H", "uniform hemisphere (-H)"}, {cb, "", "light sampling"}}, 2);
    grid(md, "Light sampling with $l = 1, 4, 16, 64$ light rays, 1 sample per pixel.",
         std::string(kSmall) + " -s 1 -m 1",
         {{cb, "-l 1", "$l = 1$"}, {cb, "-l 4", "$l = 4$"}, {cb, "-l 16", "$l = 16$"},
          {cb, "-l 64", "$l = 64$"}},
         4);
    md << R"(## Part 4: Global illumination

*Explain how a path bounces, how Russian roulette ends it without bias, and what each bounce
adds.*

)";
    grid(md, "Direct light only against indirect light only (one bounce and more).",
         std::string(kSmall) + " -s 64 -l 4",
         {{cb, "-m 1", "direct ($m = 1$)"}, {cb, "-m 5 --bounce 2", "second bounce only"}}, 2);
    std::vector<Cell> depth;
    for (int m = 0; m <= 5; ++m) {
      depth.push_back({cb, "-m " + std::to_string(m), "$m = " + std::to_string(m) + "$"});
    }
    grid(md, "Maximum ray depth 0 to 5, 64 samples per pixel.",
         std::string(kSmall) + " -s 64 -l 4 --no-rr", depth, 3);
    std::vector<Cell> spp;
    for (int s : {1, 4, 16, 64, 256, 1024}) {
      spp.push_back({cb, "-s " + std::to_string(s), "$s = " + std::to_string(s) + "$"});
    }
    grid(md, "Samples per pixel from 1 to 1024, depth 5, 4 light rays.",
         std::string(kTiny) + " -m 5 -l 4", spp, 3);
    md << R"(## Part 5: Adaptive sampling

*Explain the per-pixel test that stops sampling a pixel once its confidence interval is small
enough, and where the sampler spends its samples.* Every fourth sample of a pixel only decides
when to stop and the others only form its value, so stopping early does not bias the image. The
sample-rate image shows, in colour, how many samples each pixel took (red many, blue few).

)";
    md << "```render scene=" << quote(cb) << " flags=\"" << kSmall
       << " -s 256 -l 2 -m 5 -a 64 0.05\" extras=yes caption=\"Adaptive sampling, at most 256 "
          "samples per pixel, and its sample-rate image.\"\n```\n\n";
    if (!opt_.convergence_table.empty()) {
      md << "```plot csv=" << quote(opt_.convergence_table.filename().string())
         << " x=seconds title=\"Error against render time\" caption=\"Relative MSE against "
            "the reference, for each strategy.\"\n```\n\n";
    } else {
      md << "<!-- When you have the convergence table (strategy,samples,seconds,relMSE), put it "
            "beside this file and plot it:\n```plot csv=convergence.csv x=seconds title=\"Error "
            "against render time\"\n```\n-->\n\n";
    }
    md << "## Collaboration\n\n*Who did what, what you learned, and any resources you used.*\n";
    return md.str();
  }

 private:
  /// One cell of a grid: a scene, its own flags, its caption.
  struct Cell {
    std::string scene, flags, caption;
  };

  static std::string quote(const std::string& s) {
    return s.find(' ') == std::string::npos ? s : "\"" + s + "\"";
  }

  void grid(std::ostringstream& md, const std::string& caption, const std::string& flags,
            const std::vector<Cell>& cells, int columns) {
    std::vector<Cell> present;
    for (const Cell& c : cells) {
      if (!c.scene.empty()) present.push_back(c);
    }
    if (present.empty()) {
      md << "*No scene for this figure was found (" << caption << ")*\n\n";
      return;
    }
    md << "```grid columns=" << columns << " flags=\"" << flags << "\" caption=\"" << caption
       << "\"\n";
    for (const Cell& c : present) {
      md << "scene=" << quote(c.scene);
      if (!c.flags.empty()) md << " flags=\"" << c.flags << "\"";
      md << " caption=\"" << c.caption << "\"\n";
    }
    md << "```\n\n";
  }

  const StarterOptions& opt_;
};

}  // namespace

std::string starter_markdown(const StarterOptions& options) { return StarterWriter(options).text(); }

fs::path write_starter(const StarterOptions& options) {
  fs::path file = options.dir / "writeup.md";
  if (fs::exists(file) && !options.force) {
    throw std::runtime_error(file.string() + " exists already; use --force to replace it");
  }
  fs::create_directories(options.dir);
  std::string md = starter_markdown(options);
  if (!options.convergence_table.empty()) {
    fs::copy_file(options.convergence_table, options.dir / options.convergence_table.filename(),
                  fs::copy_options::overwrite_existing);
  }
  std::ofstream out(file);
  out << md;
  if (!out) throw std::runtime_error("cannot write " + file.string());
  return file;
}

}  // namespace pt::web
