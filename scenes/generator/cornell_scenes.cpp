#include "scenes/generator/cornell_scenes.h"

#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace scenegen {
namespace {

// A matrix as COLLADA writes it, row by row.
glm::mat4 rows(const std::array<float, 16>& m) { return glm::transpose(glm::make_mat4(m.data())); }

// Blender's Y-up mesh data placed in the Z-up world, as the course's walls are (without the
// round-off the course's exporter left in its matrices, so the walls stay exactly axis-aligned).
const glm::mat4 kYUpToZUp = rows({-1, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 1});

Material diffuse(const std::string& name, const glm::vec3& albedo) {
  Material m;
  m.name = name;
  m.diffuse = albedo;
  return m;
}

void add_mesh(Document& doc, MeshGeometry geometry, const std::string& material, const glm::mat4& transform) {
  Node n;
  n.name = geometry.name;
  n.transform = transform;
  n.kind = Node::Kind::geometry;
  n.instance = geometry.name;
  n.material = material;
  doc.meshes.push_back(std::move(geometry));
  doc.nodes.push_back(std::move(n));
}

void add_sphere(Document& doc, const std::string& name, float radius, const glm::vec3& center,
                const std::string& material) {
  doc.spheres.push_back({name, radius});
  Node n;
  n.name = name;
  n.transform = glm::translate(glm::mat4(1.0f), center);
  n.kind = Node::Kind::geometry;
  n.instance = name;
  n.material = material;
  doc.nodes.push_back(std::move(n));
}

// A wall in the box's Y-up local frame; its texcoords are Blender's placeholders, kept so the
// walls read like the course's (three inputs per corner).
void add_wall(Document& doc, const std::string& name, const std::array<glm::vec3, 4>& corners,
              const glm::vec3& inward) {
  MeshGeometry g;
  g.name = name;
  g.mesh = make_quad(corners[0], corners[1], corners[2], corners[3], inward);
  g.texcoords = true;
  add_mesh(doc, std::move(g), name, kYUpToZUp);
}

// The two spheres' places in the course's CBspheres, radius 0.3, resting on the floor. The camera
// looks along −y with its right towards −x: one sphere is front right, the other back left.
const glm::vec3 kFrontRightSphere{-0.4f, 0.3f, 0.3f};
const glm::vec3 kBackLeftSphere{0.4f, -0.3f, 0.3f};

// A bumpy sphere of radius `scale` (before its bumps) resting on the floor at (x, y).
void add_bumpy_sphere(Document& doc, const std::string& name, const DenseParams& params, float scale,
                      float x, float y) {
  MeshGeometry g;
  g.name = name;
  g.mesh = make_dense_sphere(params);
  const float lift = scale * float(1.0 + params.bump_amplitude) + 0.005f;
  add_mesh(doc, std::move(g), "dense",
           glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(x, y, lift)), glm::vec3(scale)));
}

// The million-triangle benchmark scene. Real scenes are not one evenly tessellated surface: a few
// large triangles (floor, walls) bound the room, the objects in it differ in size and in
// tessellation density by orders of magnitude, some surfaces are long thin slivers, and most of
// the room is empty. That mix is what a split heuristic has to cope with (and what the surface
// area heuristic was designed for), so the scene has one of each, scattered so that each kind is
// seen by the camera: a detailed bumpy statue of most of the triangles (back left), three small
// pebbles tessellated much more finely for their size (front), a coil of mid-sized triangles
// (back right), and two columns floor to ceiling made only of slivers thousands of times longer
// than they are wide (corners). Everything is procedural and deterministic.
Document dense_room(Document doc, const SceneOptions& options) {
  doc.materials.push_back(diffuse("dense", glm::vec3(0.75f)));
  add_bumpy_sphere(doc, "statue", options.statue, 0.32f, 0.42f, -0.4f);
  const int pebble_resolutions[3] = {40, 48, 64};
  const float pebble_sizes[3] = {0.03f, 0.05f, 0.08f};
  const glm::vec2 pebble_places[3] = {{0.1f, 0.55f}, {-0.25f, 0.35f}, {-0.55f, 0.6f}};
  for (int i = 0; i < 3; ++i) {
    DenseParams p;
    p.resolution = pebble_resolutions[i];
    p.bump_frequency = 13.0;
    add_bumpy_sphere(doc, "pebble" + std::to_string(i + 1), p, pebble_sizes[i], pebble_places[i].x,
                     pebble_places[i].y);
  }
  MeshGeometry coil;
  coil.name = "coil";
  coil.mesh = make_coil(options.room_coil);
  add_mesh(doc, std::move(coil), "dense",
           glm::translate(glm::mat4(1.0f), glm::vec3(-0.45f, -0.35f, float(options.room_coil.tube_radius) + 0.005f)));
  const glm::vec2 column_places[2] = {{0.78f, 0.62f}, {-0.8f, -0.72f}};
  for (int i = 0; i < 2; ++i) {
    MeshGeometry column;
    column.name = "column" + std::to_string(i + 1);
    column.mesh = make_column(options.column);
    add_mesh(doc, std::move(column), "dense",
             glm::translate(glm::mat4(1.0f), glm::vec3(column_places[i], 0.0f)));
  }
  return doc;
}

}  // namespace

std::vector<SceneEntry> scene_entries() {
  return {
      {"cornell_empty", "the Cornell box alone: walls, light panel, area light, camera", true},
      {"cornell_spheres", "the box with two diffuse spheres", true},
      {"cornell_mirror_glass", "the box with a mirror sphere and a glass sphere (ior 1.5)", true},
      {"cornell_coil", "the box with a closed tube coiled along a helix (smooth normals)", true},
      {"cornell_smooth",
       "the box with a coarse bumpy sphere (768 triangles, smooth per-vertex normals): its "
       "facets show wherever a face normal stands in for the interpolated one",
       true},
      {"cornell_small",
       "cornell_smooth at 1/20 scale (a box 0.1 wide, the sphere 1.5 thousandths over the "
       "floor): the same image, but a fixed shadow-ray offset of 0.05 or 0.2 skips the occluders",
       true},
      {"dense_mesh",
       "the box with a million triangles of very different sizes: a detailed bumpy statue, "
       "pebbles, a coil and two thin columns",
       false},
      {"dense_sphere", "the box with one bumpy sphere of a million near-equal triangles", false},
  };
}

Document cornell_box() {
  Document doc;
  doc.lights.push_back({"Area", glm::vec3(10.0f)});
  doc.cameras.push_back({"Camera"});

  Material light = diffuse("light", glm::vec3(0.8f));
  light.emission = glm::vec3(10.0f);
  doc.materials = {diffuse("ceiling", glm::vec3(0.6f)), light,
                   diffuse("floor", glm::vec3(0.6f)),   diffuse("leftWall", {0.6f, 0.2f, 0.2f}),
                   diffuse("rightWall", {0.2f, 0.2f, 0.6f}), diffuse("backWall", glm::vec3(0.6f))};

  // The area light is a unit square scaled to the panel's 0.8 × 0.6 and placed where it is.
  doc.nodes.push_back({"Area", rows({0.8f, 0, 0, 0, 0, 0.6f, 0, 0, 0, 0, 1, 1.49f, 0, 0, 0, 1}),
                       Node::Kind::light, "Area", ""});
  doc.nodes.push_back({"Camera", rows({-1, 0, 0, 0, 0, 0, 1, 3, 0, 1, 0, 0, 0, 0, 0, 1}),
                       Node::Kind::camera, "Camera", ""});

  add_wall(doc, "ceiling", {{{1, 1.5f, -1}, {-1, 1.5f, -1}, {-1, 1.5f, 1}, {1, 1.5f, 1}}}, {0, -1, 0});
  add_wall(doc, "light", {{{0.4f, 1.49f, -0.3f}, {0.4f, 1.49f, 0.3f}, {-0.4f, 1.49f, 0.3f}, {-0.4f, 1.49f, -0.3f}}},
           {0, -1, 0});
  add_wall(doc, "floor", {{{1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, {-1, 0, -1}}}, {0, 1, 0});
  add_wall(doc, "leftWall", {{{-1, 1.5f, -1}, {-1, 0, -1}, {-1, 0, 1}, {-1, 1.5f, 1}}}, {1, 0, 0});
  add_wall(doc, "rightWall", {{{1, 1.5f, 1}, {1, 0, 1}, {1, 0, -1}, {1, 1.5f, -1}}}, {-1, 0, 0});
  add_wall(doc, "backWall", {{{1, 1.5f, -1}, {1, 0, -1}, {-1, 0, -1}, {-1, 1.5f, -1}}}, {0, 0, 1});
  return doc;
}

Document build_scene(const std::string& name, const SceneOptions& options) {
  Document doc = cornell_box();
  if (name == "cornell_empty") return doc;
  if (name == "cornell_spheres") {
    doc.materials.push_back(diffuse("lambertian", glm::vec3(0.8f)));
    add_sphere(doc, "Sphere1", 0.3f, kFrontRightSphere, "lambertian");
    add_sphere(doc, "Sphere2", 0.3f, kBackLeftSphere, "lambertian");
    return doc;
  }
  if (name == "cornell_mirror_glass") {
    Material mirror = diffuse("chrome", glm::vec3(0.64f));
    mirror.model = Material::Model::mirror;
    Material glass = diffuse("glass", glm::vec3(0.64f));
    glass.model = Material::Model::glass;
    glass.ior = 1.5f;
    doc.materials.push_back(mirror);
    doc.materials.push_back(glass);
    add_sphere(doc, "Sphere1", 0.3f, kFrontRightSphere, "glass");
    add_sphere(doc, "Sphere2", 0.3f, kBackLeftSphere, "chrome");
    return doc;
  }
  if (name == "cornell_coil") {
    doc.materials.push_back(diffuse("coil", {0.8f, 0.6f, 0.2f}));
    MeshGeometry g;
    g.name = "coil";
    g.mesh = make_coil(options.coil);
    g.faces = MeshGeometry::Faces::triangles;
    // The helix rises from z = 0 about the Z axis; lift it so its lowest point clears the floor.
    add_mesh(doc, std::move(g), "coil",
             glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, float(options.coil.tube_radius) + 0.03f)));
    return doc;
  }
  if (name == "cornell_smooth") {
    doc.materials.push_back(diffuse("smooth", glm::vec3(0.75f)));
    MeshGeometry g;
    g.name = "smoothSphere";
    // Coarse on purpose: 8 x 8 quads a cube face, so a face normal differs from the
    // interpolated one by up to about 20 degrees across most of each facet.
    g.mesh = make_dense_sphere(DenseParams{8, 0.08, 3.0});
    const float scale = 0.45f;
    const float lift = scale * 1.08f + 0.03f;
    add_mesh(doc, std::move(g), "smooth",
             glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, lift)), glm::vec3(scale)));
    return doc;
  }
  if (name == "cornell_small") {
    // Radiance does not change with scale, so this is cornell_smooth's image; only a renderer
    // that offsets its shadow rays by a fixed distance (instead of the hit point's error
    // bound) sees the difference, as light leaking past the sphere and under it.
    Document small = build_scene("cornell_smooth", options);
    const glm::mat4 shrink = glm::scale(glm::mat4(1.0f), glm::vec3(0.05f));
    for (Node& n : small.nodes) n.transform = shrink * n.transform;
    return small;
  }
  if (name == "dense_mesh") return dense_room(std::move(doc), options);
  if (name == "dense_sphere") {
    doc.materials.push_back(diffuse("dense", glm::vec3(0.75f)));
    MeshGeometry g;
    g.name = "denseSphere";
    g.mesh = make_dense_sphere(options.dense);
    // Unit-radius bumpy sphere, scaled to sit on the floor in the middle of the box.
    const float scale = 0.45f;
    const float lift = scale * float(1.0 + options.dense.bump_amplitude) + 0.03f;
    glm::mat4 m = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, lift)), glm::vec3(scale));
    add_mesh(doc, std::move(g), "dense", m);
    return doc;
  }
  throw std::invalid_argument("unknown scene '" + name + "'");
}

}  // namespace scenegen
