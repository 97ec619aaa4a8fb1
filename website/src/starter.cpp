#include "website/src/starter.h"

#include <fstream>
#include <utility>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace pt::web {
namespace {

// Every figure a reader compares by eye is at least 320 pixels wide. The samples are chosen so
// that the whole write-up renders in a few minutes on two cores (the spheres at 1024 samples
// per pixel are half of it); `website build --quick` renders every image at half the size.
constexpr const char* kView = "-t 0 -r 320 240";
constexpr const char* kWide = "-t 0 -r 480 360";

/// The region a zoomed crop shows under each image of a figure (fractions of the image).
constexpr const char* kBunnyShadow = "0.5 0.72 0.25 0.25";
constexpr const char* kSphereShadow = "0.55 0.72 0.25 0.25";
constexpr const char* kBunnyShadowWide = "0.5 0.72 0.1667 0.1667";

/// Writes the Markdown of the starting write-up, section by section.
class StarterWriter {
 public:
  explicit StarterWriter(const StarterOptions& o) : opt_(o) {}

  std::string text() {
    intro();
    part1();
    part2();
    part3();
    part4();
    part5();
    md_ << "## Collaboration\n\n*Who did what, what you learned, and any resources you used.*\n";
    return md_.str();
  }

 private:
  /// One cell of a grid: a scene, its own flags, its caption, and optional extra attributes.
  struct Cell {
    Cell(std::string s, std::string f, std::string c, std::string m = "")
        : scene(std::move(s)), flags(std::move(f)), caption(std::move(c)), more(std::move(m)) {}
    std::string scene, flags, caption, more;
  };

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

  static std::string quote(const std::string& s) {
    return s.find(' ') == std::string::npos ? s : "\"" + s + "\"";
  }

  static std::string name(const std::string& scene) { return fs::path(scene).stem().string(); }

  void missing(const std::string& what) {
    md_ << "*No scene for this figure was found (" << what << ").*\n\n";
  }

  /// A block (grid or compare) of cells; cells whose scene is missing are left out.
  void block(const std::string& kind, const std::string& header, const std::vector<Cell>& cells,
             const std::string& caption) {
    std::vector<Cell> present;
    for (const Cell& c : cells) {
      if (!c.scene.empty()) present.push_back(c);
    }
    if (present.empty() || (kind == "compare" && present.size() != 2)) return missing(caption);
    md_ << "```" << kind << " " << header << " caption=\"" << caption << "\"\n";
    for (const Cell& c : present) {
      md_ << "scene=" << quote(c.scene);
      if (!c.flags.empty()) md_ << " flags=\"" << c.flags << "\"";
      if (!c.more.empty()) md_ << " " << c.more;
      md_ << " caption=\"" << c.caption << "\"\n";
    }
    md_ << "```\n\n";
  }

  void grid(const std::string& flags, const std::vector<Cell>& cells, const std::string& caption,
            int columns, const std::string& zoom = "") {
    std::string header = "columns=" + std::to_string(columns) + " flags=\"" + flags + "\"";
    if (!zoom.empty()) header += " zoom=\"" + zoom + "\"";
    block("grid", header, cells, caption);
  }

  void intro() {
    md_ << R"(# Path tracer write-up

*Your name, your partner's name.* Replace every paragraph in italics with your own words, keep the
figures, and add your own. Build the page with `website build writeup.md -o site` (add `--quick`
for a draft: every render at half its size, about a quarter of the time) and check the folder you
submit with `website check site`.

Each `render`, `grid`, `compare`, `timing` and `plot` block below names a scene and the
pathtracer's flags; a render is made again only when the scene, the flags or the pathtracer change.
A yellow frame on a render marks the region shown enlarged under it. Math is written as in LaTeX:
inline $L_o(p, \omega_o)$ or displayed:

$$L_o(p,\omega_o) = L_e(p,\omega_o) + \int_{H^2} f_r(p,\omega_i\to\omega_o)\,L_i(p,\omega_i)\,\cos\theta_i\,d\omega_i$$

)";
  }

  void part1() {
    md_ << R"(## Part 1: Ray generation and scene intersection

*Walk through the path of a camera ray: how a pixel sample becomes a ray in camera space and then
in world space, and how the pixel's estimate is averaged from its samples. Then explain your
ray–triangle test (Möller–Trumbore, or a watertight test, and what the barycentric coordinates are
for) and your ray–sphere test, and how each keeps only the nearest hit within the ray's range.*

The renders show each hit's shading normal $n$ as the colour $(n + 1)/2$.

)";
    std::vector<Cell> small;
    for (std::string s : {first({"sky/CBempty.dae", "cornell_empty.dae"}),
                          first({"sky/CBspheres_lambertian.dae", "cornell_spheres.dae"}),
                          first({"keenan/banana.dae", "cornell_coil.dae"}),
                          first({"meshedit/teapot.dae", "cornell_mirror_glass.dae"})}) {
      small.push_back({s, "", name(s)});
    }
    grid(std::string(kView) + " -s 4 --normals", small,
         "Small scenes with normal shading, 4 samples per pixel.", 2);
  }

  void part2() {
    md_ << R"(## Part 2: Bounding volume hierarchy

*Explain how you build the BVH: how a node's primitives are split (the midpoint of the longest
axis, or the surface area heuristic and why it is better), when a node becomes a leaf, and how
traversal skips boxes a ray misses and visits the nearer child first.*

Large meshes, with normal shading, that only the BVH makes quick to render:

)";
    std::vector<Cell> big;
    for (const char* s : {"sky/CBbunny.dae", "sky/bunny.dae"}) {
      if (have(s)) big.push_back({s, "", name(s)});
    }
    if (big.size() < 2 && have("cornell_coil.dae")) big.push_back({"cornell_coil.dae", "", "coil"});
    if (have("dense_mesh.dae")) {
      big.push_back({"dense_mesh.dae", "", "the dense mesh, a million triangles"});
    } else {
      md_ << "*The dense mesh was not found: build it with `cmake --build build --target "
             "dense_mesh` and run `website init` again.*\n\n";
    }
    grid(std::string(kView) + " -s 4 --normals", big,
         "Large meshes with the BVH, 4 samples per pixel.", 3);
    md_ << R"(*Compare the render times with and without the BVH on these moderately complex scenes, and
say what the speed-up grows with.* Without the BVH every ray tests every triangle, so those renders
are smaller; the table compares camera rays a second, which does not depend on the size.

)";
    std::vector<Cell> rows;
    // The project's bumpy sphere (780 triangles) beside its coil (6,380), so that the table shows
    // the speed-up growing with the triangle count even where the course's meshes are absent.
    for (const char* s : {"cornell_smooth.dae", "keenan/banana.dae", "meshedit/teapot.dae",
                          "cornell_coil.dae", "sky/CBbunny.dae"}) {
      if (have(s)) rows.push_back({s, "", name(s)});
    }
    if (rows.empty()) return missing("render times with and without the BVH");
    md_ << "```timing flags=\"" << kView << " -s 16 --normals\" versus=\"-r 80 60 -s 1 --bvh none\" "
           "names=\"with the BVH|without\" caption=\"Normal shading with and without the BVH.\"\n";
    for (const Cell& c : rows) md_ << "scene=" << quote(c.scene) << " caption=\"" << c.caption << "\"\n";
    md_ << "```\n\n";
  }

  void part3() {
    const std::string bunny = first({"sky/CBbunny.dae", "cornell_spheres.dae"});
    const std::string spheres = first({"sky/CBspheres_lambertian.dae", "cornell_spheres.dae"});
    md_ << R"(## Part 3: Direct illumination

*Explain both ways of estimating direct light: sampling directions uniformly on the hemisphere,
and sampling points on the lights (importance sampling), with the probability density each
estimate divides by. Say why the second is less noisy for the same number of samples, and what
the first can render that the second cannot.*

Drag the slider (or the picture) to move between the two; the crops below show the shadow
enlarged.

)";
    block("compare",
          "flags=\"" + std::string(kWide) + " -s 16 -l 8 -m 1\" zoom=\"" + kBunnyShadowWide + "\"",
          {{bunny, "-H", "uniform hemisphere (-H)"}, {bunny, "", "light sampling"}},
          "Uniform hemisphere sampling against light sampling, 16 samples per pixel, 8 light "
          "rays, direct light only.");
    grid(std::string(kView) + " -s 16 -l 8 -m 1",
         {{spheres, "-H", "uniform hemisphere (-H)"}, {spheres, "", "light sampling"}},
         "The same comparison on the spheres.", 2, kSphereShadow);
    md_ << R"(*Compare the noise in the soft shadows with 1, 4, 16 and 64 light rays at one sample per
pixel, and say why the light rays matter most where a point sees only part of the light.*

)";
    std::vector<Cell> lights;
    for (int l : {1, 4, 16, 64}) {
      lights.push_back({bunny, "-l " + std::to_string(l), "$l = " + std::to_string(l) + "$"});
    }
    grid(std::string(kView) + " -s 1 -m 1", lights,
         "Light sampling with $l = 1, 4, 16, 64$ light rays, 1 sample per pixel.", 2, kBunnyShadow);
  }

  void part4() {
    const std::string bunny = first({"sky/CBbunny.dae", "cornell_spheres.dae"});
    const std::string spheres = first({"sky/CBspheres_lambertian.dae", "cornell_spheres.dae"});
    // The spheres' series below renders these same global images, so they are made once.
    const std::string global = std::string(kView) + " -l 4 -m 5";
    md_ << R"(## Part 4: Global illumination

*Explain how a path gathers light bounce by bounce: where the direct light of each bounce is
added, how the next direction is sampled, and how Russian roulette ends paths without biasing the
image (the survivors' weight). Say what the maximum ray depth cuts off.*

*Compare direct light alone with indirect light alone on the same scene, and say where each one
comes from.* Indirect light here is the global render minus the direct one, pixel by pixel in
linear values. The two renders' noise does not cancel: a pixel can come out negative (it is shown
black), and the light's edge, which their pixel samples cover differently, flickers.

)";
    std::vector<Cell> split;
    for (int s : {4, 16, 64}) {
      std::string n = std::to_string(s);
      split.push_back({spheres, "-s " + n + " -m 1", "direct, $s = " + n + "$"});
      split.push_back({spheres, "-s " + n, "indirect, $s = " + n + "$", "minus=\"-m 1\""});
      split.push_back({spheres, "-s " + n, "both, $s = " + n + "$"});
    }
    grid(global, split,
         "Direct light only, indirect light only, and both, at 4, 16 and 64 samples per pixel "
         "with 4 light rays.",
         3);
    md_ << R"(*Compare the renders with maximum ray depth 0, 1, 2, 3, 4, 5 and 100: what does each further
bounce add, and why does 100 cost little more than 5?* The second series keeps only the light that
took exactly $k$ bounces (`--bounce k`).

)";
    std::vector<Cell> depth, bounce;
    for (int m : {0, 1, 2, 3, 4, 5, 100}) {
      std::string n = std::to_string(m);
      depth.push_back({bunny, "-m " + n, "$m = " + n + "$"});
    }
    for (int k = 0; k <= 5; ++k) {
      std::string n = std::to_string(k);
      bounce.push_back({bunny, "-m 5 --bounce " + n, "bounce " + n + " only"});
    }
    grid(std::string(kView) + " -s 32 -l 4", depth,
         "Maximum ray depth $m$ from 0 to 100, 32 samples per pixel, 4 light rays.", 3);
    grid(std::string(kView) + " -s 32 -l 4", bounce,
         "Only the light that took exactly $k$ bounces, for $k$ from 0 to 5.", 3);
    md_ << R"(*Compare the renders with 1, 2, 4, 8, 16, 64 and 1024 samples per pixel (4 light rays), and
say how the noise falls with the number of samples.*

)";
    std::vector<Cell> spp;
    for (int s : {1, 2, 4, 8, 16, 64, 1024}) {
      std::string n = std::to_string(s);
      spp.push_back({spheres, "-s " + n, "$s = " + n + "$"});
    }
    grid(global, spp, "Samples per pixel from 1 to 1024, depth 5, 4 light rays.", 3, kSphereShadow);
  }

  void part5() {
    const std::string bunny = first({"sky/CBbunny.dae", "cornell_spheres.dae"});
    md_ << R"(## Part 5: Adaptive sampling

*Explain the test that stops sampling a pixel: the confidence interval of its mean from the
samples so far, checked every batch of samples against the tolerance. Say where the sampler spends
its samples and why.* Every fourth sample of a pixel only decides when to stop and the others only
form its value, so stopping early does not bias the image.

The sample-rate image shows in colour how many samples each pixel took, from blue (few) through
green to red (the maximum, 1024 here).

)";
    md_ << "```render scene=" << quote(bunny) << " flags=\"" << kView
        << " -s 1024 -a 32 0.1 -l 1 -m 5\" extras=yes caption=\"Adaptive sampling: at most 1024 "
           "samples per pixel, a batch of 32, tolerance 0.1; the render and its sample-rate "
           "image.\"\n```\n\n";
    md_ << R"(*Read the plot: how fast does each strategy's error fall as it is given more time, and how
much time does each need to reach the same error?* Error is the relative mean squared error
against a reference render with many more samples.

)";
    if (!opt_.convergence_table.empty()) {
      md_ << "```plot csv=" << quote(opt_.convergence_table.filename().string())
          << " x=seconds title=\"Error against render time\" caption=\"Relative MSE against the "
             "reference, for each strategy.\"\n```\n\n";
      return;
    }
    const std::string spheres = first({"sky/CBspheres_lambertian.dae", "cornell_spheres.dae"});
    md_ << "```plot scene=" << quote(spheres)
        << " flags=\"-r 120 90 -m 5 -l 1 --budgets 1,2,4,8,16,32 --reference-spp 512 "
           "--speedup-budget -1\" x=seconds title=\"Error against render time: "
        << name(spheres)
        << "\" caption=\"Relative MSE against a 512-sample reference, for uniform hemisphere "
           "sampling, light sampling, multiple importance sampling and adaptive sampling, "
           "measured when the page is built.\"\n```\n\n";
  }

  const StarterOptions& opt_;
  std::ostringstream md_;
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
