// Reads the course's COLLADA 1.4 dialect into a world-space Scene (see collada_loader.h).
#include "framework/scene/collada_loader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <iostream>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <pugixml.hpp>

#include "framework/scene/scene_error.h"

namespace pt {
namespace {

constexpr uint32_t kNone = ~uint32_t(0);

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\t' || c == '\r'; }

/// A float source (COLLADA <source> seen through its accessor): `count` items of `stride`
/// floats starting at `offset` in `values`.
struct FloatSource {
  const std::vector<float>* values = nullptr;
  uint32_t count = 0, stride = 0, offset = 0;
  pugi::xml_node node;
  glm::vec3 vec3(uint32_t i) const {
    const float* v = values->data() + offset + size_t(i) * stride;
    return {v[0], v[1], v[2]};
  }
};

/// One <triangles>/<polylist>/<polygons> element, fan-triangulated: corners in threes.
struct MeshPart {
  std::string symbol;               ///< its material attribute (a symbol bound per instance)
  const FloatSource* positions = nullptr;
  const FloatSource* normals = nullptr;  ///< null: the part has no normals (flat shading)
  std::vector<uint32_t> pos;        ///< position index per corner
  std::vector<uint32_t> nrm;        ///< normal index per corner (empty without normals)
};

/// What a <geometry> holds: a mesh (parts) or a CGL sphere (radius > 0), parsed once however
/// often it is instanced.
struct GeometryData {
  std::vector<MeshPart> parts;
  float sphere_radius = 0.0f;
  bool is_sphere = false;
};

/// The loader's state for one file: the parsed document, an id index and caches, so that
/// arrays, geometries and materials shared by several instances are read once.
class ColladaReader {
 public:
  ColladaReader(std::string name, const WarningSink& warn) : name_(std::move(name)), warn_(warn) {}

  /// Parses XML held in memory.
  Scene read_string(const std::string& xml) {
    text_ = &xml;
    return read(doc_.load_buffer(xml.data(), xml.size()));
  }
  /// Parses a file. pugixml reads it into its own buffer; the text itself is only read again
  /// (text()) when a message needs a line number, so a large scene is not held twice.
  Scene read_file(const std::string& path) {
    path_ = path;
    return read(doc_.load_file(path.c_str()));
  }

 private:
  // --- messages ---
  size_t line_of(pugi::xml_node n) const {
    ptrdiff_t off = n.offset_debug();
    const std::string& t = text();
    if (off < 0 || size_t(off) > t.size()) return 0;
    return size_t(std::count(t.begin(), t.begin() + off, '\n')) + 1;
  }
  static std::string tag(pugi::xml_node n) {
    std::string s = "<" + std::string(n.name());
    for (const char* attr : {"id", "name", "material", "url", "symbol", "semantic", "sid"}) {
      pugi::xml_attribute a = n.attribute(attr);
      if (a) {
        s += " " + std::string(attr) + "=\"" + a.value() + "\"";
        break;
      }
    }
    return s + ">";
  }
  /// "<p> in <polylist material="x"> in <geometry id="g"> (line 12)": the element and enough of
  /// its ancestors to find it (up to the nearest one with an id).
  std::string where(pugi::xml_node n) const {
    if (!n) return "";
    std::string s = tag(n);
    pugi::xml_node a = n;
    int hops = 0;
    while (!a.attribute("id") && (a = a.parent()) && a.type() == pugi::node_element &&
           std::string_view(a.name()) != "COLLADA" && ++hops <= 6)
      s += " in " + tag(a);
    size_t line = line_of(n);
    if (line) s += " (line " + std::to_string(line) + ")";
    return s;
  }
  [[noreturn]] void fail(pugi::xml_node n, const std::string& msg) const {
    throw SceneError(name_, where(n), msg);
  }
  void warn(pugi::xml_node n, const std::string& msg) const {
    std::string s = name_ + ": " + (n ? where(n) + ": " : std::string()) + msg;
    if (warn_)
      warn_(s);
    else
      std::cerr << "warning: " << s << "\n";
  }
  void warn_unknown(pugi::xml_node n, const char* context) const {
    warn(n, std::string("unknown element in ") + context + ", skipped");
  }

  // --- numbers ---
  template <class T>
  void parse_list(pugi::xml_node el, std::vector<T>& out) const;
  std::vector<float> floats(pugi::xml_node el, size_t expect) const {
    std::vector<float> v;
    parse_list(el, v);
    if (expect && v.size() != expect)
      fail(el, "expected " + std::to_string(expect) + " numbers, found " + std::to_string(v.size()));
    return v;
  }
  float one_float(pugi::xml_node el) const { return floats(el, 1)[0]; }
  /// An RGB colour from 3 or 4 numbers (the alpha is ignored).
  glm::vec3 color(pugi::xml_node el) const {
    std::vector<float> v = floats(el, 0);
    if (v.size() != 3 && v.size() != 4)
      fail(el, "a colour needs 3 or 4 numbers, found " + std::to_string(v.size()));
    return {v[0], v[1], v[2]};
  }

  // --- references ---
  pugi::xml_node resolve(pugi::xml_node referrer, const char* attr) const {
    pugi::xml_attribute a = referrer.attribute(attr);
    std::string_view url = a.value();
    if (!a || url.empty()) fail(referrer, std::string("has no ") + attr + " attribute");
    if (url[0] != '#')
      fail(referrer, std::string(attr) + "=\"" + std::string(url) +
                         "\" points outside the file; only \"#id\" references are supported");
    auto it = ids_.find(url.substr(1));
    if (it == ids_.end())
      fail(referrer, std::string(attr) + "=\"" + std::string(url) + "\" points nowhere: no element has id \"" +
                         std::string(url.substr(1)) + "\"");
    return it->second;
  }
  pugi::xml_node expect(pugi::xml_node target, const char* name, pugi::xml_node referrer) const {
    if (std::string_view(target.name()) != name)
      fail(referrer, "points to " + tag(target) + ", expected a <" + name + ">");
    return target;
  }

  // --- pieces ---
  const std::vector<float>& float_array(pugi::xml_node arr);
  const FloatSource& source(pugi::xml_node src);
  const GeometryData& geometry(pugi::xml_node geom);
  void read_part(pugi::xml_node prim, GeometryData& g);
  uint32_t material(pugi::xml_node mat);
  uint32_t default_material();
  void read_effect(pugi::xml_node effect, Material& m);
  glm::mat4 local_transform(pugi::xml_node node);
  void visit(pugi::xml_node node, const glm::mat4& parent, int depth);
  void instance_geometry(pugi::xml_node inst, const glm::mat4& m);
  void add_mesh(const GeometryData& g, pugi::xml_node geom, const glm::mat4& m,
                const std::vector<uint32_t>& part_material);
  void instance_light(pugi::xml_node inst, const glm::mat4& m);
  void instance_camera(pugi::xml_node inst, const glm::mat4& m);
  void default_camera();
  glm::vec3 up_vector() const {
    return scene_.up_axis == "Z_UP" ? glm::vec3(0, 0, 1)
         : scene_.up_axis == "X_UP" ? glm::vec3(1, 0, 0)
                                    : glm::vec3(0, 1, 0);
  }

  Scene read(pugi::xml_parse_result res);
  const std::string& text() const {
    if (!text_) {
      std::ifstream in(path_, std::ios::binary | std::ios::ate);
      std::streamoff size = in ? std::streamoff(in.tellg()) : 0;
      text_storage_.resize(size_t(std::max<std::streamoff>(size, 0)));
      in.seekg(0);
      in.read(text_storage_.data(), std::streamsize(text_storage_.size()));
      text_ = &text_storage_;
    }
    return *text_;
  }

  std::string path_;                      ///< the file, when reading one
  mutable std::string text_storage_;      ///< its text, read back for line numbers
  mutable const std::string* text_ = nullptr;
  std::string name_;
  const WarningSink& warn_;
  pugi::xml_document doc_;
  std::unordered_map<std::string_view, pugi::xml_node> ids_;
  std::unordered_map<const void*, std::vector<float>> arrays_;
  std::unordered_map<const void*, FloatSource> sources_;
  std::unordered_map<const void*, GeometryData> geometries_;
  std::unordered_map<const void*, uint32_t> materials_;
  uint32_t default_material_ = kNone;
  Scene scene_;
};

template <class T>
void ColladaReader::parse_list(pugi::xml_node el, std::vector<T>& out) const {
  const char* p = el.child_value();
  const char* end = p + std::strlen(p);
  size_t index = 0;
  while (true) {
    while (p < end && is_space(*p)) ++p;
    if (p == end) break;
    const char* start = p;
    if (*p == '+' && p + 1 < end && !is_space(p[1])) ++p;  // from_chars takes no '+'
    T value{};
    std::from_chars_result r;
    if constexpr (std::is_floating_point_v<T>) {
      r = std::from_chars(p, end, value);
    } else {
      long long v = 0;
      r = std::from_chars(p, end, v);
      if (r.ec == std::errc() && (v < 0 || v > (long long)kNone - 1) &&
          (r.ptr == end || is_space(*r.ptr)))
        fail(el, "value " + std::to_string(index) + " (" + std::to_string(v) +
                     ") is not a valid index (negative or too large)");
      value = T(v);
    }
    if (r.ec != std::errc() || (r.ptr != end && !is_space(*r.ptr))) {
      const char* tok_end = start;
      while (tok_end < end && !is_space(*tok_end)) ++tok_end;
      std::string tok(start, std::min<size_t>(tok_end - start, 40));
      fail(el, "value " + std::to_string(index) + " \"" + tok + "\" is not a" +
                   (std::is_floating_point_v<T> ? " number" : "n integer index"));
    }
    if constexpr (std::is_floating_point_v<T>) {
      if (!std::isfinite(value)) {
        std::string tok(start, r.ptr - start);
        fail(el, "value " + std::to_string(index) + " \"" + tok + "\" is not a finite number");
      }
    }
    out.push_back(value);
    p = r.ptr;
    ++index;
  }
}

const std::vector<float>& ColladaReader::float_array(pugi::xml_node arr) {
  auto it = arrays_.find(arr.internal_object());
  if (it != arrays_.end()) return it->second;
  std::vector<float> v;
  pugi::xml_attribute count = arr.attribute("count");
  // Reserve what the count promises, but never more than the text can hold (a number takes at
  // least two characters with its separator), so a lying count cannot ask for gigabytes.
  if (count) v.reserve(std::min<size_t>(count.as_ullong(), std::strlen(arr.child_value()) / 2 + 1));
  parse_list(arr, v);
  if (count && v.size() != count.as_ullong())
    fail(arr, "count=\"" + std::string(count.value()) + "\" but the array holds " +
                  std::to_string(v.size()) + " numbers");
  return arrays_.emplace(arr.internal_object(), std::move(v)).first->second;
}

const FloatSource& ColladaReader::source(pugi::xml_node src) {
  auto it = sources_.find(src.internal_object());
  if (it != sources_.end()) return it->second;
  pugi::xml_node acc = src.child("technique_common").child("accessor");
  if (!acc) fail(src, "has no <technique_common><accessor> saying how to read it");
  pugi::xml_node arr = resolve(acc, "source");
  if (std::string_view(arr.name()) != "float_array")
    fail(acc, "source points to " + tag(arr) + ", expected a <float_array>");
  FloatSource s;
  s.values = &float_array(arr);
  s.node = acc;
  s.count = acc.attribute("count").as_uint();
  s.stride = acc.attribute("stride").as_uint(1);
  s.offset = acc.attribute("offset").as_uint(0);
  if (!acc.attribute("count")) fail(acc, "has no count attribute");
  if (s.stride < 3) fail(acc, "stride " + std::to_string(s.stride) + " is too small for 3D vectors");
  size_t need = size_t(s.offset) + (s.count ? size_t(s.count - 1) * s.stride + 3 : 0);
  if (need > s.values->size())
    fail(acc, "needs " + std::to_string(need) + " numbers (count " + std::to_string(s.count) +
                  ", stride " + std::to_string(s.stride) + ", offset " + std::to_string(s.offset) +
                  ") but " + tag(arr) + " holds only " + std::to_string(s.values->size()));
  return sources_.emplace(src.internal_object(), s).first->second;
}

void ColladaReader::read_part(pugi::xml_node prim, GeometryData& g) {
  std::string_view kind = prim.name();
  MeshPart part;
  part.symbol = prim.attribute("material").value();
  uint32_t stride = 0;
  int vertex_offset = -1, normal_offset = -1;
  for (pugi::xml_node in : prim.children("input")) {
    uint32_t off = in.attribute("offset").as_uint(0);
    stride = std::max(stride, off + 1);
    std::string_view sem = in.attribute("semantic").value();
    if (sem == "VERTEX") {
      pugi::xml_node verts = expect(resolve(in, "source"), "vertices", in);
      vertex_offset = int(off);
      for (pugi::xml_node vin : verts.children("input")) {
        std::string_view vsem = vin.attribute("semantic").value();
        if (vsem == "POSITION")
          part.positions = &source(expect(resolve(vin, "source"), "source", vin));
        else if (vsem == "NORMAL" && normal_offset < 0)
          part.normals = &source(expect(resolve(vin, "source"), "source", vin));
      }
      if (!part.positions) fail(verts, "has no POSITION input");
    } else if (sem == "NORMAL") {
      part.normals = &source(expect(resolve(in, "source"), "source", in));
      normal_offset = int(off);
    }
  }
  if (vertex_offset < 0) fail(prim, "has no VERTEX input");
  // A NORMAL inside <vertices> is indexed like the positions.
  if (part.normals && normal_offset < 0) normal_offset = vertex_offset;

  // Corner lists: the <p> of <triangles>/<polylist>, or one <p> per polygon in <polygons>.
  std::vector<uint32_t> idx, vcount;
  uint32_t count = prim.attribute("count").as_uint();
  if (!prim.attribute("count")) fail(prim, "has no count attribute");
  if (kind == "polygons") {
    for (pugi::xml_node p : prim.children()) {
      if (std::string_view(p.name()) == "ph") {
        warn(p, "polygons with holes are not supported, skipped");
        continue;
      }
      if (std::string_view(p.name()) != "p") continue;
      size_t before = idx.size();
      parse_list(p, idx);
      if ((idx.size() - before) % stride) fail(p, "holds a partial vertex");
      vcount.push_back(uint32_t((idx.size() - before) / stride));
    }
  } else {
    pugi::xml_node p = prim.child("p");
    if (!p && count) fail(prim, "has no <p>");
    idx.reserve(std::min<size_t>(size_t(count) * 3 * stride, std::strlen(p.child_value()) / 2 + 1));
    parse_list(p, idx);
    if (kind == "polylist") {
      pugi::xml_node vc = prim.child("vcount");
      if (!vc) fail(prim, "has no <vcount>");
      vcount.reserve(std::min<size_t>(count, std::strlen(vc.child_value()) / 2 + 1));
      parse_list(vc, vcount);
      if (vcount.size() != count)
        fail(vc, "holds " + std::to_string(vcount.size()) + " polygon sizes but count=\"" +
                     std::to_string(count) + "\"");
    } else {
      vcount.assign(count, 3);
    }
  }
  size_t corners = 0;
  for (uint32_t n : vcount) {
    if (n < 3) fail(prim, "has a polygon with " + std::to_string(n) + " vertices (needs 3 or more)");
    corners += n;
  }
  pugi::xml_node pnode = prim.child("p");
  if (idx.size() != corners * stride)
    fail(pnode ? pnode : prim,
         "holds " + std::to_string(idx.size()) + " indices, but " + std::to_string(vcount.size()) +
             " polygons of " + std::to_string(corners) + " corners with " +
             std::to_string(stride) + " inputs each need " + std::to_string(corners * stride));

  auto check = [&](uint32_t value, size_t at, const FloatSource* s, const char* what) {
    if (value >= s->count)
      fail(pnode ? pnode : prim,
           std::string(what) + " index " + std::to_string(value) + " (value " +
               std::to_string(at) + " of <p>) is out of range: " + where(s->node) + " has count " +
               std::to_string(s->count));
  };
  size_t tris = corners - 2 * vcount.size();
  part.pos.reserve(tris * 3);
  if (part.normals) part.nrm.reserve(tris * 3);
  size_t c = 0;  // first corner of the current polygon
  for (uint32_t n : vcount) {
    for (uint32_t k = 0; k < n; ++k) {
      size_t at = (c + k) * stride;
      check(idx[at + vertex_offset], at + vertex_offset, part.positions, "position");
      if (part.normals) check(idx[at + normal_offset], at + normal_offset, part.normals, "normal");
    }
    for (uint32_t k = 1; k + 1 < n; ++k)  // fan: (0, k, k+1)
      for (uint32_t corner : {0u, k, k + 1}) {
        size_t at = (c + corner) * stride;
        part.pos.push_back(idx[at + vertex_offset]);
        if (part.normals) part.nrm.push_back(idx[at + normal_offset]);
      }
    c += n;
  }
  g.parts.push_back(std::move(part));
}

const GeometryData& ColladaReader::geometry(pugi::xml_node geom) {
  auto it = geometries_.find(geom.internal_object());
  if (it != geometries_.end()) return it->second;
  GeometryData g;
  bool known = false;
  for (pugi::xml_node child : geom.children()) {
    std::string_view n = child.name();
    if (n == "mesh") {
      known = true;
      for (pugi::xml_node prim : child.children()) {
        std::string_view pn = prim.name();
        if (pn == "triangles" || pn == "polylist" || pn == "polygons")
          read_part(prim, g);
        else if (pn == "lines" || pn == "linestrips")
          warn(prim, "lines have no surface to render, skipped");
        else if (pn == "tristrips" || pn == "trifans")
          warn(prim, "triangle strips and fans are not supported, skipped");
        else if (pn != "source" && pn != "vertices" && pn != "extra")
          warn_unknown(prim, "a <mesh>");
      }
    } else if (n == "extra") {
      for (pugi::xml_node tech : child.children("technique")) {
        if (std::string_view(tech.attribute("profile").value()) != "CGL") continue;
        if (pugi::xml_node sphere = tech.child("sphere")) {
          pugi::xml_node r = sphere.child("radius");
          if (!r) fail(sphere, "has no <radius>");
          g.sphere_radius = one_float(r);
          if (!(g.sphere_radius > 0.0f))
            fail(r, "sphere radius " + std::string(r.child_value()) + " is not positive");
          g.is_sphere = true;
          known = true;
        }
      }
    } else if (n == "convex_mesh" || n == "spline" || n == "brep") {
      known = true;
      warn(child, "this kind of geometry is not supported, skipped");
    } else if (n != "asset") {
      warn_unknown(child, "a <geometry>");
    }
  }
  if (!known) warn(geom, "holds neither a <mesh> nor a CGL <sphere>; nothing to render");
  return geometries_.emplace(geom.internal_object(), std::move(g)).first->second;
}

void ColladaReader::read_effect(pugi::xml_node effect, Material& m) {
  auto cgl_techniques = [&](pugi::xml_node parent, auto&& fn) {
    for (pugi::xml_node extra : parent.children("extra"))
      for (pugi::xml_node tech : extra.children("technique"))
        if (std::string_view(tech.attribute("profile").value()) == "CGL") fn(tech);
  };
  pugi::xml_node common = effect.child("profile_COMMON");
  pugi::xml_node technique = common.child("technique");
  for (pugi::xml_node shading : technique.children()) {
    std::string_view sn = shading.name();
    if (sn != "phong" && sn != "lambert" && sn != "blinn" && sn != "constant") continue;
    if (pugi::xml_node diffuse = shading.child("diffuse")) {
      if (pugi::xml_node c = diffuse.child("color"))
        m.albedo = color(c);
      else if (pugi::xml_node t = diffuse.child("texture"))
        warn(t, "textures are not supported; material \"" + m.name + "\" uses 0.8 grey"),
            m.albedo = glm::vec3(0.8f);
    }
    if (pugi::xml_node c = shading.child("emission").child("color")) m.emission = color(c);
  }
  auto read_cgl = [&](pugi::xml_node tech) {
    for (pugi::xml_node bsdf : tech.children()) {
      std::string_view kind = bsdf.name();
      auto vec = [&](const char* field, glm::vec3& out) {
        if (pugi::xml_node e = bsdf.child(field)) out = color(e);
      };
      auto num = [&](const char* field, float& out) {
        if (pugi::xml_node e = bsdf.child(field)) out = one_float(e);
      };
      if (kind == "emission") {
        // The course's emission BSDF: it glows and reflects nothing. The phong diffuse colour
        // Blender writes beside it is kept in albedo but not rendered.
        m.kind = MaterialKind::emission;
        vec("radiance", m.emission);
      } else if (kind == "mirror") {
        m.kind = MaterialKind::mirror;
        vec("reflectance", m.reflectance);
      } else if (kind == "glass") {
        m.kind = MaterialKind::glass;
        vec("reflectance", m.reflectance);
        vec("transmittance", m.transmittance);
        num("ior", m.ior);
        num("roughness", m.roughness);
        if (!(m.ior > 0.0f)) fail(bsdf.child("ior"), "index of refraction must be positive");
      } else if (kind == "microfacet") {
        m.kind = MaterialKind::microfacet;
        num("alpha", m.roughness);
        vec("eta", m.eta);
        vec("k", m.k);
      } else if (kind == "diffuse") {
        m.kind = MaterialKind::diffuse;
        vec("albedo", m.albedo);
        vec("reflectance", m.albedo);
      } else {
        warn(bsdf, "unknown CGL material, drawn as diffuse");
      }
    }
  };
  cgl_techniques(effect, read_cgl);
  cgl_techniques(common, read_cgl);
  cgl_techniques(technique, read_cgl);
}

uint32_t ColladaReader::material(pugi::xml_node mat) {
  auto it = materials_.find(mat.internal_object());
  if (it != materials_.end()) return it->second;
  Material m;
  m.name = mat.attribute("name") ? mat.attribute("name").value() : mat.attribute("id").value();
  if (pugi::xml_node ie = mat.child("instance_effect"))
    read_effect(expect(resolve(ie, "url"), "effect", ie), m);
  else
    warn(mat, "has no <instance_effect>; drawn as 0.8 grey diffuse");
  uint32_t index = uint32_t(scene_.materials.size());
  scene_.materials.push_back(std::move(m));
  materials_.emplace(mat.internal_object(), index);
  return index;
}

uint32_t ColladaReader::default_material() {
  if (default_material_ == kNone) {
    default_material_ = uint32_t(scene_.materials.size());
    Material m;
    m.name = "default";
    scene_.materials.push_back(m);
  }
  return default_material_;
}

glm::mat4 ColladaReader::local_transform(pugi::xml_node node) {
  glm::mat4 m(1.0f);
  for (pugi::xml_node t : node.children()) {
    std::string_view n = t.name();
    if (n == "matrix") {
      // A matrix with a number missing occurs in a course scene (CBgems' camera): read what is
      // there, say so, and let the camera code recover the lost axis rather than refuse the file.
      std::vector<float> v = floats(t, 0);
      if (v.size() != 16)
        warn(t, "expected 16 numbers, found " + std::to_string(v.size()) +
                    "; the missing ones are taken from the identity");
      glm::mat4 a(1.0f);
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)  // COLLADA is row-major, GLM column-major
          if (size_t(r * 4 + c) < v.size()) a[c][r] = v[r * 4 + c];
      if (a[0][3] != 0.0f || a[1][3] != 0.0f || a[2][3] != 0.0f || a[3][3] != 1.0f) {
        warn(t, "the bottom row is not (0 0 0 1); a projective transform makes no sense for a "
                "scene, so it is taken as (0 0 0 1)");
        a[0][3] = a[1][3] = a[2][3] = 0.0f;
        a[3][3] = 1.0f;
      }
      m = m * a;
    } else if (n == "translate") {
      std::vector<float> v = floats(t, 3);
      m = glm::translate(m, glm::vec3(v[0], v[1], v[2]));
    } else if (n == "rotate") {
      std::vector<float> v = floats(t, 4);
      glm::vec3 axis(v[0], v[1], v[2]);
      if (v[3] != 0.0f) {
        if (glm::length(axis) == 0.0f) fail(t, "rotation axis is zero");
        m = glm::rotate(m, glm::radians(v[3]), glm::normalize(axis));
      }
    } else if (n == "scale") {
      std::vector<float> v = floats(t, 3);
      m = glm::scale(m, glm::vec3(v[0], v[1], v[2]));
    } else if (n == "lookat") {
      std::vector<float> v = floats(t, 9);
      glm::vec3 eye(v[0], v[1], v[2]), at(v[3], v[4], v[5]), up(v[6], v[7], v[8]);
      glm::vec3 z = eye - at, x = glm::cross(up, z);
      if (glm::length(z) == 0.0f || glm::length(x) == 0.0f)
        fail(t, "eye, target and up do not define a direction");
      z = glm::normalize(z);
      x = glm::normalize(x);
      glm::mat4 a(glm::vec4(x, 0), glm::vec4(glm::cross(z, x), 0), glm::vec4(z, 0), glm::vec4(eye, 1));
      m = m * a;
    } else if (n == "skew") {
      warn(t, "skew transforms are not supported, skipped");
    }
  }
  return m;
}

void ColladaReader::visit(pugi::xml_node node, const glm::mat4& parent, int depth) {
  if (depth > 256) fail(node, "nodes nest more than 256 deep (an <instance_node> cycle?)");
  glm::mat4 m = parent * local_transform(node);
  for (pugi::xml_node child : node.children()) {
    std::string_view n = child.name();
    if (n == "node")
      visit(child, m, depth + 1);
    else if (n == "instance_geometry")
      instance_geometry(child, m);
    else if (n == "instance_light")
      instance_light(child, m);
    else if (n == "instance_camera")
      instance_camera(child, m);
    else if (n == "instance_node")
      visit(expect(resolve(child, "url"), "node", child), m, depth + 1);
    else if (n == "instance_controller")
      warn(child, "skinned and morphed meshes (controllers) are not supported, skipped");
    else if (n != "matrix" && n != "translate" && n != "rotate" && n != "scale" && n != "lookat" &&
             n != "skew" && n != "asset" && n != "extra")
      warn_unknown(child, "a <node>");
  }
}

void ColladaReader::instance_geometry(pugi::xml_node inst, const glm::mat4& m) {
  pugi::xml_node geom = expect(resolve(inst, "url"), "geometry", inst);
  const GeometryData& g = geometry(geom);
  // symbol -> material, as this instance binds them.
  std::unordered_map<std::string, uint32_t> bound;
  for (pugi::xml_node im :
       inst.child("bind_material").child("technique_common").children("instance_material"))
    bound[im.attribute("symbol").value()] = material(expect(resolve(im, "target"), "material", im));
  auto material_for = [&](const std::string& symbol) {
    if (bound.empty()) return default_material();
    auto it = bound.find(symbol);
    if (it != bound.end()) return it->second;
    if (bound.size() == 1 && symbol.empty()) return bound.begin()->second;
    warn(inst, "binds no material to symbol \"" + symbol + "\"; drawn as 0.8 grey diffuse");
    return default_material();
  };
  if (g.is_sphere) {
    glm::vec3 scale(glm::length(glm::vec3(m[0])), glm::length(glm::vec3(m[1])),
                    glm::length(glm::vec3(m[2])));
    float mean = (scale.x + scale.y + scale.z) / 3.0f;
    if (std::max({scale.x, scale.y, scale.z}) - std::min({scale.x, scale.y, scale.z}) > 1e-4f * mean)
      warn(inst, "a sphere scaled non-uniformly stays a sphere; using the mean scale");
    Sphere s;
    s.center = glm::vec3(m * glm::vec4(0, 0, 0, 1));
    s.radius = g.sphere_radius * mean;
    if (!(s.radius > 0.0f) || !std::isfinite(s.radius))
      fail(inst, "the node transform scales the sphere to radius " + std::to_string(s.radius));
    if (!std::isfinite(s.center.x + s.center.y + s.center.z))
      fail(inst, "the sphere's centre is not finite after the node transform");
    s.material = material_for(bound.size() == 1 ? bound.begin()->first : std::string());
    scene_.spheres.push_back(s);
    return;
  }
  std::vector<uint32_t> part_material;
  for (const MeshPart& part : g.parts) part_material.push_back(material_for(part.symbol));
  add_mesh(g, geom, m, part_material);
}

void ColladaReader::add_mesh(const GeometryData& g, pugi::xml_node geom, const glm::mat4& m,
                             const std::vector<uint32_t>& part_material) {
  glm::mat3 linear(m);
  glm::mat3 normal_matrix = glm::transpose(glm::inverse(linear));
  // A mirroring transform turns the winding around; swap two corners so that the winding still
  // agrees with the (correctly transformed) shading normals.
  bool flip = glm::determinant(linear) < 0.0f;
  size_t bad_normals = 0;

  // World positions once per source, so every corner that names a position gets the very same
  // floats (shared edges stay watertight whichever vertex record they land in).
  std::unordered_map<const FloatSource*, std::vector<glm::vec3>> world;
  for (size_t pi = 0; pi < g.parts.size(); ++pi) {
    const MeshPart& part = g.parts[pi];
    std::vector<glm::vec3>& wp = world[part.positions];
    if (wp.empty()) {
      wp.resize(part.positions->count);
      for (uint32_t i = 0; i < part.positions->count; ++i) {
        wp[i] = glm::vec3(m * glm::vec4(part.positions->vec3(i), 1.0f));
        if (!std::isfinite(wp[i].x + wp[i].y + wp[i].z))  // finite numbers can overflow float
          fail(geom, "position " + std::to_string(i) + " is not finite after the node transform");
      }
    }
  }
  // De-indexing tables: for each position index, a chain of the vertices made for it so far
  // (one per distinct normal index), per normal source.
  struct Table {
    std::vector<uint32_t> head;          ///< position index -> first record, or kNone
    std::vector<uint32_t> next, normal_index, global;  ///< per record
  };
  std::unordered_map<const FloatSource*, Table> tables;

  // At most one vertex record per corner; grow geometrically so many small instances stay linear.
  size_t corners = 0;
  for (const MeshPart& part : g.parts) corners += part.pos.size();
  auto make_room = [&](auto& v) {
    if (v.capacity() < v.size() + corners) v.reserve(std::max(v.size() + corners, v.capacity() * 3 / 2));
  };
  make_room(scene_.positions);
  make_room(scene_.normals);

  for (size_t pi = 0; pi < g.parts.size(); ++pi) {
    const MeshPart& part = g.parts[pi];
    const std::vector<glm::vec3>& wp = world[part.positions];
    Table* tab = nullptr;
    if (part.normals) {
      tab = &tables[part.normals];
      if (tab->head.empty()) {
        tab->head.assign(part.positions->count, kNone);
        tab->next.reserve(part.pos.size());
        tab->normal_index.reserve(part.pos.size());
        tab->global.reserve(part.pos.size());
      }
    }
    size_t ntri = part.pos.size() / 3;
    scene_.triangles.reserve(scene_.triangles.size() + ntri);
    for (size_t t = 0; t < ntri; ++t) {
      uint32_t c[3] = {0, 1, 2};
      if (flip) std::swap(c[1], c[2]);
      uint32_t pidx[3];
      for (int k = 0; k < 3; ++k) pidx[k] = part.pos[3 * t + c[k]];
      glm::vec3 a = wp[pidx[0]], b = wp[pidx[1]], d = wp[pidx[2]];
      glm::vec3 face = glm::cross(b - a, d - a);
      float len = glm::length(face);
      face = (len > 0.0f && std::isfinite(len)) ? face / len : glm::vec3(0, 0, 1);
      Triangle tri;
      tri.material = part_material[pi];
      for (int k = 0; k < 3; ++k) {
        if (!tab) {  // flat: a vertex record per corner, same position floats
          tri.v[k] = uint32_t(scene_.positions.size());
          scene_.positions.push_back(wp[pidx[k]]);
          scene_.normals.push_back(face);
          continue;
        }
        uint32_t nidx = part.nrm[3 * t + c[k]];
        uint32_t r = tab->head[pidx[k]];
        while (r != kNone && tab->normal_index[r] != nidx) r = tab->next[r];
        if (r == kNone) {
          r = uint32_t(tab->global.size());
          tab->next.push_back(tab->head[pidx[k]]);
          tab->normal_index.push_back(nidx);
          tab->global.push_back(uint32_t(scene_.positions.size()));
          tab->head[pidx[k]] = r;
          glm::vec3 n = normal_matrix * part.normals->vec3(nidx);
          float nl = glm::length(n);
          if (nl > 0.0f && std::isfinite(nl)) {
            n /= nl;
          } else {
            n = face;
            ++bad_normals;
          }
          scene_.positions.push_back(wp[pidx[k]]);
          scene_.normals.push_back(n);
        }
        tri.v[k] = tab->global[r];
      }
      scene_.triangles.push_back(tri);
    }
  }
  if (bad_normals)
    warn(geom, std::to_string(bad_normals) +
                   " normals are zero or degenerate after the transform; using face normals there");
}

void ColladaReader::instance_light(pugi::xml_node inst, const glm::mat4& m) {
  pugi::xml_node el = expect(resolve(inst, "url"), "light", inst);
  Light light;
  light.name = el.attribute("name") ? el.attribute("name").value() : el.attribute("id").value();
  glm::mat3 linear(m);
  light.position = glm::vec3(m * glm::vec4(0, 0, 0, 1));
  if (!std::isfinite(light.position.x + light.position.y + light.position.z))
    fail(inst, "the light's position is not finite after the node transform");
  glm::vec3 dir = linear * glm::vec3(0, 0, -1);
  if (!(glm::length(dir) > 0.0f)) fail(inst, "the node transform collapses the light's direction");
  light.direction = glm::normalize(dir);

  // The CGL area light wins over the technique_common stand-in beside it.
  pugi::xml_node area;
  for (pugi::xml_node tech : el.child("extra").children("technique"))
    if (std::string_view(tech.attribute("profile").value()) == "CGL" && tech.child("area"))
      area = tech.child("area");
  if (area) {
    light.kind = LightKind::area;
    if (pugi::xml_node c = area.child("color")) light.radiance = color(c);
    light.edge_u = linear * glm::vec3(1, 0, 0);
    light.edge_v = linear * glm::vec3(0, 1, 0);
    if (!(glm::length(glm::cross(light.edge_u, light.edge_v)) > 0.0f))
      fail(inst, "the area light " + tag(el) + " has zero area after the node transform");
    scene_.lights.push_back(light);
    return;
  }
  pugi::xml_node kind;
  for (pugi::xml_node k : el.child("technique_common").children()) {
    std::string_view n = k.name();
    if (n == "point" || n == "spot" || n == "directional" || n == "ambient") {
      kind = k;
      break;
    }
    warn_unknown(k, "a light's <technique_common>");
  }
  if (!kind) {
    warn(el, "has no point, spot, directional, ambient or CGL area light; skipped");
    return;
  }
  std::string_view n = kind.name();
  light.kind = n == "point" ? LightKind::point
             : n == "spot" ? LightKind::spot
             : n == "directional" ? LightKind::directional
                                  : LightKind::ambient;
  if (pugi::xml_node c = kind.child("color")) light.radiance = color(c);
  auto num = [&](const char* field, float& out) {
    if (pugi::xml_node e = kind.child(field)) out = one_float(e);
  };
  num("constant_attenuation", light.constant_attenuation);
  num("linear_attenuation", light.linear_attenuation);
  num("quadratic_attenuation", light.quadratic_attenuation);
  num("falloff_angle", light.falloff_degrees);
  num("falloff_exponent", light.falloff_exponent);
  scene_.lights.push_back(light);
}

void ColladaReader::instance_camera(pugi::xml_node inst, const glm::mat4& m) {
  pugi::xml_node el = expect(resolve(inst, "url"), "camera", inst);
  if (scene_.has_camera) {
    warn(inst, "a second camera; the first one is used");
    return;
  }
  Camera cam;
  pugi::xml_node optics = el.child("optics").child("technique_common");
  if (pugi::xml_node persp = optics.child("perspective")) {
    pugi::xml_node xfov = persp.child("xfov"), yfov = persp.child("yfov"),
                   aspect = persp.child("aspect_ratio");
    auto fov = [&](pugi::xml_node e) {
      float f = one_float(e);
      if (!(f > 0.0f && f < 180.0f)) fail(e, "field of view must be between 0 and 180 degrees");
      return glm::radians(f);
    };
    if (aspect) {
      cam.aspect = one_float(aspect);
      if (!(cam.aspect > 0.0f)) fail(aspect, "aspect ratio must be positive");
    }
    if (xfov && yfov && !aspect)
      cam.aspect = std::tan(fov(xfov) / 2) / std::tan(fov(yfov) / 2);
    if (xfov)
      cam.hfov_degrees = glm::degrees(fov(xfov));
    else if (yfov)
      cam.hfov_degrees = glm::degrees(2.0f * std::atan(std::tan(fov(yfov) / 2) * cam.aspect));
    if (pugi::xml_node z = persp.child("znear")) cam.znear = one_float(z);
    if (pugi::xml_node z = persp.child("zfar")) cam.zfar = one_float(z);
  } else if (optics.child("orthographic")) {
    warn(optics.child("orthographic"), "orthographic cameras are not supported; using a perspective one");
  } else {
    warn(el, "has no <optics><technique_common><perspective>; using a default field of view");
  }
  // Keep the rotation and translation only: a scaled camera node would scale the rays.
  glm::vec3 z(m[2]), y(m[1]), x(m[0]);
  if (!(glm::length(z) > 0.0f)) fail(inst, "the node transform collapses the camera's view axis");
  z = glm::normalize(z);
  if (!(glm::length(glm::cross(y, z)) > 1e-6f * glm::length(y))) {
    y = up_vector();
    if (glm::length(glm::cross(y, z)) < 1e-3f) y = glm::vec3(y.z, y.x, y.y);
    x = glm::cross(y, z);
    warn(inst, "the node transform gives the camera no up axis; using the file's up axis " +
                   scene_.up_axis);
  }
  y = glm::normalize(y - glm::dot(y, z) * z);
  glm::vec3 right = glm::cross(y, z);
  if (glm::dot(right, x) < 0.0f) warn(inst, "the camera's node transform mirrors; the mirror is dropped");
  cam.camera_to_world = glm::mat4(glm::vec4(right, 0), glm::vec4(y, 0), glm::vec4(z, 0), m[3]);
  cam.camera_to_world[3].w = 1.0f;
  scene_.camera = cam;
  scene_.has_camera = true;
}

void ColladaReader::default_camera() {
  Bounds3 b = scene_.bounds();
  glm::vec3 up = up_vector(), back(0, 0, 1);  // Y_UP, X_UP: look down -Z
  if (scene_.up_axis == "Z_UP") back = glm::vec3(0, -1, 0);  // Z_UP: look down +Y
  Camera cam;
  float radius = std::max(0.5f * glm::length(b.extent()), 1e-3f);
  float vfov = 2.0f * std::atan(std::tan(glm::radians(cam.hfov_degrees) / 2) / cam.aspect);
  float half = 0.5f * std::min(glm::radians(cam.hfov_degrees), vfov);
  float distance = 1.1f * radius / std::sin(half);
  glm::vec3 eye = b.center() + distance * back;
  glm::vec3 right = glm::cross(up, back);
  cam.camera_to_world = glm::mat4(glm::vec4(right, 0), glm::vec4(up, 0), glm::vec4(back, 0),
                                  glm::vec4(eye, 1));
  cam.znear = std::max(1e-3f, distance - 2 * radius);
  cam.zfar = distance + 2 * radius;
  scene_.camera = cam;
  warn({}, "no camera in the file; placed one that frames the scene");
}

Scene ColladaReader::read(pugi::xml_parse_result res) {
  if (res.status == pugi::status_file_not_found || res.status == pugi::status_io_error ||
      res.status == pugi::status_out_of_memory)
    throw SceneError(name_, "", std::string("cannot be read: ") + res.description());
  if (!res) {
    const std::string& text_ = text();
    size_t line = size_t(std::count(text_.begin(), text_.begin() + std::min<size_t>(res.offset, text_.size()), '\n')) + 1;
    // Name the innermost element that was still open where the parser stopped.
    pugi::xml_node open = doc_.document_element();
    for (pugi::xml_node n = open; n; n = n.last_child())
      if (n.type() == pugi::node_element) open = n;
    // Truncated: the parser stopped with no tag left to close after the place it stopped.
    bool at_end = res.offset >= 0 && text_.find('>', size_t(res.offset)) == std::string::npos;
    std::string elem = open ? tag(open) + " (line " + std::to_string(line) + ")"
                            : "line " + std::to_string(line);
    if (res.status == pugi::status_no_document_element)
      throw SceneError(name_, "", "is not XML: it holds no element at all");
    if (at_end)
      throw SceneError(name_, elem, std::string("the XML ends before this element is closed (truncated file?): ") +
                                        res.description());
    throw SceneError(name_, elem, std::string("is not well-formed XML: ") + res.description());
  }
  pugi::xml_node root = doc_.document_element();
  if (std::string_view(root.name()) != "COLLADA")
    fail(root, "the root element is " + tag(root) + ", not <COLLADA>: not a COLLADA file");
  for (pugi::xpath_node xn : doc_.select_nodes("//*[@id]"))
    ids_.emplace(xn.node().attribute("id").value(), xn.node());

  if (pugi::xml_node up = root.child("asset").child("up_axis")) {
    std::string v = up.child_value();
    v.erase(std::remove_if(v.begin(), v.end(), is_space), v.end());
    if (v != "X_UP" && v != "Y_UP" && v != "Z_UP")
      warn(up, "unknown up axis \"" + v + "\"; assuming Y_UP");
    else
      scene_.up_axis = v;
  }
  static const std::unordered_set<std::string_view> known_top = {
      "asset", "extra", "scene", "library_animations", "library_animation_clips",
      "library_cameras", "library_controllers", "library_effects", "library_force_fields",
      "library_geometries", "library_images", "library_lights", "library_materials",
      "library_nodes", "library_physics_materials", "library_physics_models",
      "library_physics_scenes", "library_visual_scenes", "library_formulas",
      "library_articulated_systems", "library_kinematics_models", "library_kinematics_scenes",
      "library_joints"};
  static const std::pair<const char*, const char*> libraries[] = {
      {"library_geometries", "geometry"}, {"library_lights", "light"},
      {"library_cameras", "camera"}, {"library_materials", "material"},
      {"library_effects", "effect"}, {"library_visual_scenes", "visual_scene"},
      {"library_nodes", "node"}};
  for (pugi::xml_node child : root.children()) {
    if (child.type() != pugi::node_element) continue;
    std::string_view n = child.name();
    if (!known_top.count(n)) {
      warn_unknown(child, "<COLLADA>");
      continue;
    }
    for (const auto& [lib, item] : libraries)
      if (n == lib)
        for (pugi::xml_node e : child.children())
          if (e.type() == pugi::node_element && std::string_view(e.name()) != item &&
              std::string_view(e.name()) != "asset" && std::string_view(e.name()) != "extra")
            warn_unknown(e, ("<" + std::string(lib) + ">").c_str());
  }

  pugi::xml_node vs;
  if (pugi::xml_node ivs = root.child("scene").child("instance_visual_scene"))
    vs = expect(resolve(ivs, "url"), "visual_scene", ivs);
  else if ((vs = root.child("library_visual_scenes").child("visual_scene")))
    warn(root.child("scene") ? root.child("scene") : root,
         "no <scene><instance_visual_scene>; using the first visual scene");
  if (!vs) throw SceneError(name_, tag(root), "the file holds no <visual_scene>: nothing to render");

  for (pugi::xml_node child : vs.children()) {
    std::string_view n = child.name();
    if (n == "node")
      visit(child, glm::mat4(1.0f), 0);
    else if (n != "asset" && n != "extra" && n != "evaluate_scene")
      warn_unknown(child, "a <visual_scene>");
  }
  if (scene_.primitive_count() == 0)
    fail(vs, "the scene holds no triangle and no sphere: nothing to render");
  if (!scene_.has_camera) default_camera();
  scene_.source = name_;
  return std::move(scene_);
}

}  // namespace

Scene load_collada_string(const std::string& xml, const std::string& name, const WarningSink& warn) {
  ColladaReader reader(name, warn);
  return reader.read_string(xml);
}

Scene load_collada(const std::string& path, const WarningSink& warn) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st)) throw SceneError(path, "", "no such file");
  if (fs::is_directory(st)) throw SceneError(path, "", "is a directory, not a scene file");
  if (!std::ifstream(path, std::ios::binary))
    throw SceneError(path, "", "cannot be opened for reading (permissions?)");
  ColladaReader reader(path, warn);
  return reader.read_file(path);
}

}  // namespace pt
