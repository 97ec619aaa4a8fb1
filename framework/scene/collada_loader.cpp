// Not needed for the assignment.
// Reads the course's COLLADA 1.4 dialect into a world-space Scene (see collada_loader.h).
#include "framework/scene/collada_loader.h"

#include <algorithm>
#include <charconv>
#include <cerrno>
#include <cctype>
#include <cmath>
#include <cstdlib>
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
#include <utility>

#include <glm/common.hpp>
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

/// Whether an <extra>'s <technique> holds the course's extensions: profile "CGL", or "CMU462",
/// the course's parent dialect, which puts the very same elements there.
bool is_course_profile(pugi::xml_node technique) {
  std::string_view profile = technique.attribute("profile").value();
  return profile == "CGL" || profile == "CMU462";
}

/// The deepest nodes may nest (through <instance_node> too).
constexpr int kMaxNodeDepth = 256;

/// The largest <input offset> taken: a vertex of more inputs than this is no mesh anyone made.
constexpr uint32_t kMaxInputOffset = 255;

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

/// One <triangles>/<polylist>/<polygons> element, fan-triangulated, in its geometry's own
/// numbering: three corners a triangle.
struct MeshPart {
  std::string symbol;            ///< its material attribute (a symbol bound per instance)
  /// Without normals (flat: each corner gets a vertex of its own, shaded by the face normal) an
  /// index into GeometryData::positions; with normals an index into GeometryData::vertices.
  std::vector<uint32_t> corners;
  bool flat = false;
};

/// A vertex shared by the corners that name the same position and the same normal.
struct MeshVertex {
  uint32_t position = 0;  ///< index into GeometryData::positions
  glm::vec3 normal{0.0f}; ///< the file's normal, in the geometry's own space
};

/// What a <geometry> holds, parsed once however often it is instanced: a mesh de-indexed into
/// its distinct positions (each (source, index) pair once, so every corner naming it gets the
/// very same floats after a transform: shared edges stay watertight) and vertices, or a CGL
/// sphere (radius > 0). What an instance costs is what the file's corners name, never the
/// length of a source they point into.
struct GeometryData {
  std::vector<glm::vec3> positions;
  std::vector<MeshVertex> vertices;
  std::vector<MeshPart> parts;
  size_t triangles = 0;
  float sphere_radius = 0.0f;
  bool is_sphere = false;
  uint64_t primitives() const { return is_sphere ? 1 : triangles; }
};

/// Numbers the distinct indices named in one source in the order they are first named. A table
/// as long as the source where that is not much more than the names to number, else a hash map,
/// so that a few corners pointing into a huge source do not cost its length.
class FirstUse {
 public:
  FirstUse(uint32_t source_count, size_t names) : dense_(source_count <= 4 * names + 64) {
    if (dense_) table_.assign(source_count, kNone);
  }
  /// Where the number given to `index` (< the source's count) is kept: kNone until it is given.
  uint32_t* slot(uint32_t index) {
    if (dense_) return &table_[index];
    return &map_.try_emplace(index, kNone).first->second;
  }

 private:
  bool dense_;
  std::vector<uint32_t> table_;
  std::unordered_map<uint32_t, uint32_t> map_;
};

/// The numbering a geometry's parts share while they are read (see read_part).
struct MeshNumbering {
  std::unordered_map<const FloatSource*, FirstUse> positions;  ///< per source: index -> position
  std::vector<uint32_t> head;  ///< per position: the last vertex made for it, or kNone
  std::vector<uint32_t> next;  ///< per vertex: the one made before it for the same position
  std::vector<const FloatSource*> normal_source;  ///< per vertex
  std::vector<uint32_t> normal_index;             ///< per vertex
};

/// What a node expands to once every instance in it is followed: the primitives and the node
/// instances (with the lights and cameras they hold). Sums saturate, so a chain of billions is a
/// large number, not an overflow.
struct Expansion {
  uint64_t primitives = 0, nodes = 0;
  void add(const Expansion& e) {
    primitives = saturating_add(primitives, e.primitives);
    nodes = saturating_add(nodes, e.nodes);
  }
  static uint64_t saturating_add(uint64_t a, uint64_t b) {
    return a > UINT64_MAX - b ? UINT64_MAX : a + b;
  }
};

/// The loader's state for one file: the parsed document, an id index and caches, so that
/// arrays, geometries and materials shared by several instances are read once.
class ColladaReader {
 public:
  ColladaReader(std::string name, const WarningSink& warn, const LoadLimits& limits)
      : name_(std::move(name)), warn_(warn), limits_(limits) {}

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
  /// The line holding byte `offset` of the text, by binary search in the offsets of its line
  /// starts, found once on the first message: a file with many warnings would otherwise be
  /// counted from its start for each.
  size_t line_at(size_t offset) const {
    const std::string& t = text();
    if (line_starts_.empty()) {
      line_starts_.push_back(0);
      for (const char* c = t.data(); (c = static_cast<const char*>(
                                          std::memchr(c, '\n', t.data() + t.size() - c)));)
        line_starts_.push_back(size_t(++c - t.data()));
    }
    return size_t(std::upper_bound(line_starts_.begin(), line_starts_.end(), offset) -
                  line_starts_.begin());
  }
  size_t line_of(pugi::xml_node n) const {
    ptrdiff_t off = n.offset_debug();
    if (off < 0 || size_t(off) > text().size()) return 0;
    return line_at(size_t(off));
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
    // An element of a library node instanced a million times says the same thing each time.
    if (!warned_.emplace(n.internal_object(), msg).second) return;
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
  /// An attribute that holds a whole number in [0, most]; `fallback` when it is absent.
  uint32_t uint_attribute(pugi::xml_node el, const char* name, uint32_t fallback,
                          uint32_t most) const {
    pugi::xml_attribute a = el.attribute(name);
    if (!a) return fallback;
    std::string_view v = a.value();
    while (!v.empty() && is_space(v.front())) v.remove_prefix(1);
    while (!v.empty() && is_space(v.back())) v.remove_suffix(1);
    unsigned long long n = 0;
    auto r = std::from_chars(v.data(), v.data() + v.size(), n);
    if (v.empty() || r.ec != std::errc() || r.ptr != v.data() + v.size() || n > most)
      fail(el, std::string(name) + "=\"" + a.value() + "\" is not a whole number from 0 to " +
                   std::to_string(most));
    return uint32_t(n);
  }
  /// An RGB colour from 3 or 4 numbers (the alpha is ignored).
  glm::vec3 color(pugi::xml_node el) const {
    std::vector<float> v = floats(el, 0);
    if (v.size() != 3 && v.size() != 4)
      fail(el, "a colour needs 3 or 4 numbers, found " + std::to_string(v.size()));
    return {v[0], v[1], v[2]};
  }

  /// The policy for physically impossible values (see collada_loader.h): a reflectance is
  /// clamped to [0, 1] per channel, an emitted quantity to 0 and above, each with a warning
  /// naming the element, the value and what was done.
  glm::vec3 reflectance(pugi::xml_node el, const char* what) const {
    glm::vec3 c = color(el);
    glm::vec3 clamped = glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f));
    if (clamped != c)
      warn(el, std::string("a ") + what + " of " + triple_text(c) +
                   " is impossible (a surface reflects between none and all of the light it "
                   "receives, per channel); clamped to " + triple_text(clamped));
    return clamped;
  }
  glm::vec3 emitted(pugi::xml_node el, const char* what) const {
    glm::vec3 c = color(el);
    glm::vec3 clamped = glm::max(c, glm::vec3(0.0f));
    if (clamped != c)
      warn(el, std::string("a negative ") + what + " (" + triple_text(c) +
                   ") is impossible; clamped to " + triple_text(clamped));
    return clamped;
  }
  static std::string number_text(float v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", double(v));
    return buffer;
  }
  static std::string triple_text(const glm::vec3& v) {
    return number_text(v.x) + " " + number_text(v.y) + " " + number_text(v.z);
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
  void read_part(pugi::xml_node prim, GeometryData& g, MeshNumbering& numbering);
  uint32_t material(pugi::xml_node mat);
  uint32_t default_material();
  void read_effect(pugi::xml_node effect, Material& m);
  glm::mat4 local_transform(pugi::xml_node node);
  /// What `node` expands to (memoised); fails on a cycle or nesting past kMaxNodeDepth.
  const Expansion& expansion(pugi::xml_node node, int depth);
  /// Fails, naming the node chain, when the visual scene `vs` expands past the instancing limits.
  void check_expansion(pugi::xml_node vs);
  void visit(pugi::xml_node node, const glm::mat4& parent, int depth);
  void instance_geometry(pugi::xml_node inst, const glm::mat4& m);
  void add_mesh(const GeometryData& g, pugi::xml_node geom, const glm::mat4& m,
                const std::vector<uint32_t>& part_material);
  void instance_light(pugi::xml_node inst, const glm::mat4& m);
  void instance_camera(pugi::xml_node inst, const glm::mat4& m);
  /// Leaves out (with a warning) the area lights whose lit side holds nothing of the scene.
  void drop_lights_facing_away();
  /// Places a camera outside the bounds, looking at their centre; fails on `vs` when that cannot
  /// be done in float.
  void default_camera(pugi::xml_node vs);
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

  /// The warnings given so far, by element and text.
  struct WarningKey {
    size_t operator()(const std::pair<const void*, std::string>& k) const {
      return std::hash<const void*>()(k.first) ^ std::hash<std::string>()(k.second);
    }
  };
  mutable std::unordered_set<std::pair<const void*, std::string>, WarningKey> warned_;
  mutable std::vector<size_t> line_starts_;  ///< offsets of the text's lines, once needed
  std::string path_;                      ///< the file, when reading one
  mutable std::string text_storage_;      ///< its text, read back for line numbers
  mutable const std::string* text_ = nullptr;
  std::string name_;
  const WarningSink& warn_;
  const LoadLimits limits_;
  pugi::xml_document doc_;
  std::unordered_map<std::string_view, pugi::xml_node> ids_;
  std::unordered_map<const void*, std::vector<float>> arrays_;
  std::unordered_map<const void*, FloatSource> sources_;
  std::unordered_map<const void*, GeometryData> geometries_;
  std::unordered_map<const void*, uint32_t> materials_;
  uint32_t default_material_ = kNone;
  std::unordered_map<const void*, Expansion> expansions_;
  std::unordered_set<const void*> expanding_;  ///< nodes whose expansion is being counted
  std::vector<pugi::xml_node> light_elements_;  ///< the <instance_light> of each scene light
  size_t drawable_ = 0;  ///< primitives Part 1 can draw (a normal, coordinates float can square)
  Scene scene_;
};

/// Reads the real number at p (no space before it, NUL-terminated after `end`) as std::from_chars
/// reads one: decimal or "inf"/"nan", no '+', no hexadecimal (of "0x1" only the "0" is read),
/// correctly rounded; ec is result_out_of_range when it is too large for T or rounds to zero.
/// std::strtod does the reading, since libc++ (macOS's standard library) has no floating-point
/// from_chars; it reads in the C locale, which this program never changes.
template <class T>
std::from_chars_result read_real(const char* p, const char* end, T& value) {
  const char* digits = p + (p < end && *p == '-' ? 1 : 0);
  if (digits < end && (*digits == '+' || std::isspace(static_cast<unsigned char>(*digits))))
    return {p, std::errc::invalid_argument};
  if (digits + 1 < end && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
    value = p == digits ? T(0) : -T(0);
    return {digits + 1, std::errc()};
  }
  char* stop = nullptr;
  errno = 0;
  const T v = std::is_same_v<T, float> ? T(std::strtof(p, &stop)) : T(std::strtod(p, &stop));
  if (stop == p) return {p, std::errc::invalid_argument};
  if (errno == ERANGE && (v == T(0) || std::isinf(v))) return {stop, std::errc::result_out_of_range};
  value = v;
  return {stop, std::errc()};
}

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
      r = read_real(p, end, value);
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
  const bool counted = bool(arr.attribute("count"));
  const uint32_t count = uint_attribute(arr, "count", 0, UINT32_MAX);
  // Reserve what the count promises, but never more than the text can hold (a number takes at
  // least two characters with its separator), so a lying count cannot ask for gigabytes.
  if (counted) v.reserve(std::min<size_t>(count, std::strlen(arr.child_value()) / 2 + 1));
  parse_list(arr, v);
  if (counted && v.size() != count)
    fail(arr, "count=\"" + std::to_string(count) + "\" but the array holds " +
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
  if (!acc.attribute("count")) fail(acc, "has no count attribute");
  s.count = uint_attribute(acc, "count", 0, UINT32_MAX);
  s.stride = uint_attribute(acc, "stride", 1, UINT32_MAX);
  s.offset = uint_attribute(acc, "offset", 0, UINT32_MAX);
  if (s.stride < 3) fail(acc, "stride " + std::to_string(s.stride) + " is too small for 3D vectors");
  size_t need = size_t(s.offset) + (s.count ? size_t(s.count - 1) * s.stride + 3 : 0);
  if (need > s.values->size())
    fail(acc, "needs " + std::to_string(need) + " numbers (count " + std::to_string(s.count) +
                  ", stride " + std::to_string(s.stride) + ", offset " + std::to_string(s.offset) +
                  ") but " + tag(arr) + " holds only " + std::to_string(s.values->size()));
  return sources_.emplace(src.internal_object(), s).first->second;
}

void ColladaReader::read_part(pugi::xml_node prim, GeometryData& g, MeshNumbering& numbering) {
  std::string_view kind = prim.name();
  MeshPart part;
  part.symbol = prim.attribute("material").value();
  const FloatSource* positions = nullptr;
  const FloatSource* normals = nullptr;  // null: the part has no normals (flat shading)
  uint32_t stride = 0;
  int vertex_offset = -1, normal_offset = -1;
  for (pugi::xml_node in : prim.children("input")) {
    uint32_t off = uint_attribute(in, "offset", 0, kMaxInputOffset);
    stride = std::max(stride, off + 1);
    std::string_view sem = in.attribute("semantic").value();
    if (sem == "VERTEX") {
      pugi::xml_node verts = expect(resolve(in, "source"), "vertices", in);
      vertex_offset = int(off);
      for (pugi::xml_node vin : verts.children("input")) {
        std::string_view vsem = vin.attribute("semantic").value();
        if (vsem == "POSITION")
          positions = &source(expect(resolve(vin, "source"), "source", vin));
        else if (vsem == "NORMAL" && normal_offset < 0)
          normals = &source(expect(resolve(vin, "source"), "source", vin));
      }
      if (!positions) fail(verts, "has no POSITION input");
    } else if (sem == "NORMAL") {
      normals = &source(expect(resolve(in, "source"), "source", in));
      normal_offset = int(off);
    }
  }
  if (vertex_offset < 0) fail(prim, "has no VERTEX input");
  // A NORMAL inside <vertices> is indexed like the positions.
  if (normals && normal_offset < 0) normal_offset = vertex_offset;

  // Corner lists: the <p> of <triangles>/<polylist>, or one <p> per polygon in <polygons>. The
  // count is checked against what they hold before anything is sized by it.
  std::vector<uint32_t> idx, vcount;
  if (!prim.attribute("count")) fail(prim, "has no count attribute");
  const uint32_t count = uint_attribute(prim, "count", 0, UINT32_MAX);
  pugi::xml_node pnode = prim.child("p");
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
    size_t holes = 0;
    for (pugi::xml_node ph : prim.children("ph")) holes += bool(ph);
    if (vcount.size() + holes != count)
      fail(prim, "count=\"" + std::to_string(count) + "\" but it holds " +
                     std::to_string(vcount.size() + holes) + " polygons");
  } else {
    if (!pnode && count) fail(prim, "has no <p>");
    parse_list(pnode, idx);
    if (kind == "polylist") {
      pugi::xml_node vc = prim.child("vcount");
      if (!vc) fail(prim, "has no <vcount>");
      parse_list(vc, vcount);
      if (vcount.size() != count)
        fail(vc, "holds " + std::to_string(vcount.size()) + " polygon sizes but count=\"" +
                     std::to_string(count) + "\"");
    } else {
      if (idx.size() != size_t(count) * 3 * stride)
        fail(pnode ? pnode : prim,
             "holds " + std::to_string(idx.size()) + " indices, but count=\"" +
                 std::to_string(count) + "\" triangles with " + std::to_string(stride) +
                 " inputs each need " + std::to_string(size_t(count) * 3 * stride));
      vcount.assign(count, 3);
    }
  }
  size_t corners = 0;
  for (uint32_t n : vcount) {
    if (n < 3) fail(prim, "has a polygon with " + std::to_string(n) + " vertices (needs 3 or more)");
    corners += n;
    if (corners > idx.size()) break;  // too few indices, said below; no sum can overflow
  }
  if (corners > idx.size())
    fail(pnode ? pnode : prim, "holds " + std::to_string(idx.size()) + " indices, fewer than the " +
                                   std::to_string(vcount.size()) + " polygons have corners");
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
  const size_t tris = corners - 2 * vcount.size();
  part.flat = !normals;
  part.corners.reserve(tris * 3);
  // Positions are numbered by (source, index) and vertices by (position, normal source, normal
  // index), across every part of the geometry: two parts that share a normal source but not a
  // position source (or the reverse) get vertices of their own.
  FirstUse& position_numbers =
      numbering.positions.try_emplace(positions, positions->count, corners).first->second;
  auto position_of = [&](uint32_t index) {
    uint32_t* n = position_numbers.slot(index);
    if (*n == kNone) {
      *n = uint32_t(g.positions.size());
      g.positions.push_back(positions->vec3(index));
      numbering.head.push_back(kNone);
    }
    return *n;
  };
  auto vertex_of = [&](uint32_t position, uint32_t normal) {
    uint32_t v = numbering.head[position];
    while (v != kNone && !(numbering.normal_source[v] == normals && numbering.normal_index[v] == normal))
      v = numbering.next[v];
    if (v == kNone) {
      v = uint32_t(g.vertices.size());
      g.vertices.push_back({position, normals->vec3(normal)});
      numbering.next.push_back(numbering.head[position]);
      numbering.normal_source.push_back(normals);
      numbering.normal_index.push_back(normal);
      numbering.head[position] = v;
    }
    return v;
  };
  size_t c = 0;  // first corner of the current polygon
  for (uint32_t n : vcount) {
    for (uint32_t k = 0; k < n; ++k) {
      size_t at = (c + k) * stride;
      check(idx[at + vertex_offset], at + vertex_offset, positions, "position");
      if (normals) check(idx[at + normal_offset], at + normal_offset, normals, "normal");
    }
    for (uint32_t k = 1; k + 1 < n; ++k)  // fan: (0, k, k+1)
      for (uint32_t corner : {0u, k, k + 1}) {
        size_t at = (c + corner) * stride;
        uint32_t position = position_of(idx[at + vertex_offset]);
        part.corners.push_back(normals ? vertex_of(position, idx[at + normal_offset]) : position);
      }
    c += n;
  }
  g.triangles += tris;
  g.parts.push_back(std::move(part));
}

const GeometryData& ColladaReader::geometry(pugi::xml_node geom) {
  auto it = geometries_.find(geom.internal_object());
  if (it != geometries_.end()) return it->second;
  GeometryData g;
  MeshNumbering numbering;
  bool known = false;
  for (pugi::xml_node child : geom.children()) {
    std::string_view n = child.name();
    if (n == "mesh") {
      known = true;
      for (pugi::xml_node prim : child.children()) {
        std::string_view pn = prim.name();
        if (pn == "triangles" || pn == "polylist" || pn == "polygons")
          read_part(prim, g, numbering);
        else if (pn == "lines" || pn == "linestrips")
          warn(prim, "lines have no surface to render, skipped");
        else if (pn == "tristrips" || pn == "trifans")
          warn(prim, "triangle strips and fans are not supported, skipped");
        else if (pn != "source" && pn != "vertices" && pn != "extra")
          warn_unknown(prim, "a <mesh>");
      }
    } else if (n == "extra") {
      for (pugi::xml_node tech : child.children("technique")) {
        if (!is_course_profile(tech)) continue;
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
        if (is_course_profile(tech)) fn(tech);
  };
  pugi::xml_node common = effect.child("profile_COMMON");
  pugi::xml_node technique = common.child("technique");
  for (pugi::xml_node shading : technique.children()) {
    std::string_view sn = shading.name();
    if (sn != "phong" && sn != "lambert" && sn != "blinn" && sn != "constant") continue;
    if (pugi::xml_node diffuse = shading.child("diffuse")) {
      if (pugi::xml_node c = diffuse.child("color"))
        m.albedo = reflectance(c, "diffuse colour");
      else if (pugi::xml_node t = diffuse.child("texture"))
        warn(t, "textures are not supported; material \"" + m.name + "\" uses 0.8 grey"),
            m.albedo = glm::vec3(0.8f);
    }
    if (pugi::xml_node c = shading.child("emission").child("color"))
      m.emission = emitted(c, "emission");
  }
  auto read_cgl = [&](pugi::xml_node tech) {
    for (pugi::xml_node bsdf : tech.children()) {
      std::string_view kind = bsdf.name();
      auto vec = [&](const char* field, glm::vec3& out) {
        if (pugi::xml_node e = bsdf.child(field)) out = color(e);
      };
      auto fraction = [&](const char* field, glm::vec3& out) {
        if (pugi::xml_node e = bsdf.child(field)) out = reflectance(e, field);
      };
      auto num = [&](const char* field, float& out) {
        if (pugi::xml_node e = bsdf.child(field)) out = one_float(e);
      };
      auto roughness = [&](const char* field) {
        num(field, m.roughness);
        if (m.roughness < 0.0f) {
          warn(bsdf.child(field), std::string("a negative ") + field + " (" +
                                      number_text(m.roughness) + ") is impossible; clamped to 0");
          m.roughness = 0.0f;
        }
      };
      if (kind == "emission") {
        // The course's emission BSDF: it glows and reflects nothing. The phong diffuse colour
        // Blender writes beside it is kept in albedo but not rendered.
        m.kind = MaterialKind::emission;
        if (pugi::xml_node e = bsdf.child("radiance")) m.emission = emitted(e, "radiance");
      } else if (kind == "mirror") {
        m.kind = MaterialKind::mirror;
        fraction("reflectance", m.reflectance);
      } else if (kind == "glass") {
        m.kind = MaterialKind::glass;
        fraction("reflectance", m.reflectance);
        fraction("transmittance", m.transmittance);
        num("ior", m.ior);
        roughness("roughness");
        if (!(m.ior > 0.0f)) fail(bsdf.child("ior"), "index of refraction must be positive");
      } else if (kind == "microfacet") {
        m.kind = MaterialKind::microfacet;
        roughness("alpha");
        // The conductor's complex index of refraction, per channel: neither part is negative.
        for (auto [field, out] : {std::pair<const char*, glm::vec3*>{"eta", &m.eta}, {"k", &m.k}}) {
          vec(field, *out);
          if (out->x < 0.0f || out->y < 0.0f || out->z < 0.0f) {
            warn(bsdf.child(field), std::string("a negative ") + field + " is impossible; clamped to 0");
            *out = glm::max(*out, glm::vec3(0.0f));
          }
        }
      } else if (kind == "diffuse") {
        m.kind = MaterialKind::diffuse;
        fraction("albedo", m.albedo);
        fraction("reflectance", m.albedo);
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

const Expansion& ColladaReader::expansion(pugi::xml_node node, int depth) {
  auto it = expansions_.find(node.internal_object());
  if (it != expansions_.end()) return it->second;
  if (depth > kMaxNodeDepth)
    fail(node, "nodes nest more than " + std::to_string(kMaxNodeDepth) + " deep");
  if (!expanding_.insert(node.internal_object()).second)
    fail(node, "instances itself: an <instance_node> cycle");
  Expansion e;
  e.nodes = 1;
  for (pugi::xml_node child : node.children()) {
    std::string_view n = child.name();
    if (n == "node") {
      e.add(expansion(child, depth + 1));
    } else if (n == "instance_node") {
      e.add(expansion(expect(resolve(child, "url"), "node", child), depth + 1));
    } else if (n == "instance_geometry") {
      e.primitives = Expansion::saturating_add(
          e.primitives, geometry(expect(resolve(child, "url"), "geometry", child)).primitives());
    } else if (n == "instance_light" || n == "instance_camera") {
      e.nodes = Expansion::saturating_add(e.nodes, 1);
    }
  }
  expanding_.erase(node.internal_object());
  return expansions_.emplace(node.internal_object(), e).first->second;
}

void ColladaReader::check_expansion(pugi::xml_node vs) {
  Expansion total;
  std::vector<pugi::xml_node> top;
  for (pugi::xml_node child : vs.children("node")) {
    total.add(expansion(child, 0));
    top.push_back(child);
  }
  const bool too_many_primitives = total.primitives > limits_.primitives;
  if (!too_many_primitives && total.nodes <= limits_.nodes) return;
  // Name the way down to where the expansion fans out: from the top, the node that expands to
  // the most, as long as that alone is past the limit.
  auto size = [&](const Expansion& e) { return too_many_primitives ? e.primitives : e.nodes; };
  const uint64_t limit = too_many_primitives ? limits_.primitives : limits_.nodes;
  std::vector<std::pair<pugi::xml_node, uint64_t>> chain;
  std::vector<pugi::xml_node> children = top;
  for (;;) {
    pugi::xml_node heaviest;
    uint64_t most = 0;
    for (pugi::xml_node c : children)
      if (size(expansion(c, 0)) > most) heaviest = c, most = size(expansion(c, 0));
    if (!heaviest || most <= limit || chain.size() > size_t(kMaxNodeDepth)) break;
    chain.emplace_back(heaviest, most);
    children.clear();
    for (pugi::xml_node c : heaviest.children()) {
      std::string_view n = c.name();
      if (n == "node") children.push_back(c);
      if (n == "instance_node") children.push_back(resolve(c, "url"));
    }
  }
  auto number = [](uint64_t n) { return n == UINT64_MAX ? "more than 10^19" : std::to_string(n); };
  std::string what = too_many_primitives ? "primitives (triangles and spheres)"
                                         : "node instances (with their lights and cameras)";
  std::string msg = "instancing makes " + number(size(total)) + " " + what + ", more than the " +
                    std::to_string(limit) + " a scene may hold";
  if (!chain.empty()) {
    msg += "; the node chain that makes them: ";
    for (size_t i = 0; i < chain.size(); ++i) {
      if (chain.size() > 8 && i == 4) {
        msg += "... (" + std::to_string(chain.size() - 6) + " more) > ";
        i = chain.size() - 3;
      }
      msg += tag(chain[i].first) + " " + number(chain[i].second) + (i + 1 < chain.size() ? " > " : "");
    }
  }
  fail(chain.empty() ? vs : chain.back().first, msg);
}

void ColladaReader::visit(pugi::xml_node node, const glm::mat4& parent, int depth) {
  if (depth > kMaxNodeDepth)
    fail(node, "nodes nest more than " + std::to_string(kMaxNodeDepth) + " deep");
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
    // Part 1's sphere test squares distances of the order of the radius and the centre.
    constexpr float kLargest = 1e18f;
    if (s.radius > kLargest || std::max({std::abs(s.center.x), std::abs(s.center.y),
                                         std::abs(s.center.z)}) > kLargest)
      warn(inst, "a sphere this large or this far out (beyond 1e18) is too large for float "
                 "arithmetic: it cannot be drawn");
    else
      ++drawable_;
    scene_.spheres.push_back(s);
    return;
  }
  std::vector<uint32_t> part_material;
  for (const MeshPart& part : g.parts) part_material.push_back(material_for(part.symbol));
  add_mesh(g, geom, m, part_material);
}

namespace {

/// Makes room for `more` elements at the end of `v`, growing its capacity geometrically: one
/// instance at a time, an exact reserve would copy the whole array for each (quadratic time for
/// a file of many small instances).
template <class T>
void reserve_more(std::vector<T>& v, size_t more) {
  if (v.capacity() - v.size() < more) v.reserve(std::max(v.size() + more, 2 * v.capacity()));
}

}  // namespace

void ColladaReader::add_mesh(const GeometryData& g, pugi::xml_node geom, const glm::mat4& m,
                             const std::vector<uint32_t>& part_material) {
  glm::mat3 linear(m);
  glm::mat3 normal_matrix = glm::transpose(glm::inverse(linear));
  // A mirroring transform turns the winding around; swap two corners so that the winding still
  // agrees with the (correctly transformed) shading normals.
  bool flip = glm::determinant(linear) < 0.0f;
  size_t bad_normals = 0, too_large = 0;

  // World positions once per position of the geometry, so every corner that names a position
  // gets the very same floats (shared edges stay watertight whichever vertex record they land in).
  std::vector<glm::vec3> world(g.positions.size());
  for (size_t i = 0; i < g.positions.size(); ++i) {
    world[i] = glm::vec3(m * glm::vec4(g.positions[i], 1.0f));
    if (!std::isfinite(world[i].x + world[i].y + world[i].z))  // finite numbers can overflow float
      fail(geom, "a position is not finite after the node transform");
  }
  // Each vertex's record in the scene, made the first time a triangle names it.
  std::vector<uint32_t> global(g.vertices.size(), kNone);
  size_t flat_corners = 0;
  for (const MeshPart& part : g.parts) flat_corners += part.flat ? part.corners.size() : 0;
  reserve_more(scene_.positions, g.vertices.size() + flat_corners);
  reserve_more(scene_.normals, g.vertices.size() + flat_corners);
  reserve_more(scene_.triangles, g.triangles);

  for (size_t pi = 0; pi < g.parts.size(); ++pi) {
    const MeshPart& part = g.parts[pi];
    const size_t ntri = part.corners.size() / 3;
    for (size_t t = 0; t < ntri; ++t) {
      uint32_t c[3] = {0, 1, 2};
      if (flip) std::swap(c[1], c[2]);
      uint32_t corner[3], position[3];
      for (int k = 0; k < 3; ++k) {
        corner[k] = part.corners[3 * t + c[k]];
        position[k] = part.flat ? corner[k] : g.vertices[corner[k]].position;
      }
      glm::vec3 a = world[position[0]], b = world[position[1]], d = world[position[2]];
      glm::vec3 face = glm::cross(b - a, d - a);
      float len = glm::length(face);
      // The very test Part 1 shades by: a normal that overflows float cannot be drawn.
      too_large += !std::isfinite(len);
      drawable_ += len > 0.0f && std::isfinite(len);
      face = (len > 0.0f && std::isfinite(len)) ? face / len : glm::vec3(0, 0, 1);
      Triangle tri;
      tri.material = part_material[pi];
      for (int k = 0; k < 3; ++k) {
        if (part.flat) {  // a vertex record per corner, same position floats
          tri.v[k] = uint32_t(scene_.positions.size());
          scene_.positions.push_back(world[position[k]]);
          scene_.normals.push_back(face);
          continue;
        }
        uint32_t& made = global[corner[k]];
        if (made == kNone) {
          made = uint32_t(scene_.positions.size());
          glm::vec3 n = normal_matrix * g.vertices[corner[k]].normal;
          float nl = glm::length(n);
          if (nl > 0.0f && std::isfinite(nl)) {
            n /= nl;
          } else {
            n = face;
            ++bad_normals;
          }
          scene_.positions.push_back(world[position[k]]);
          scene_.normals.push_back(n);
        }
        tri.v[k] = made;
      }
      scene_.triangles.push_back(tri);
    }
  }
  if (bad_normals)
    warn(geom, std::to_string(bad_normals) +
                   " normals are zero or degenerate after the transform; using face normals there");
  if (too_large)
    warn(geom, std::to_string(too_large) +
                   " triangles are too large for float arithmetic after the node transform (their "
                   "normal overflows): they cannot be drawn");
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
    if (is_course_profile(tech) && tech.child("area"))
      area = tech.child("area");
  pugi::xml_node colour;
  if (area) {
    light.kind = LightKind::area;
    if ((colour = area.child("color"))) light.radiance = emitted(colour, "radiance");
    light.edge_u = linear * glm::vec3(1, 0, 0);
    light.edge_v = linear * glm::vec3(0, 1, 0);
    if (!(glm::length(glm::cross(light.edge_u, light.edge_v)) > 0.0f))
      fail(inst, "the area light " + tag(el) + " has zero area after the node transform");
  } else {
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
    if ((colour = kind.child("color")))
      light.radiance = emitted(colour, n == "point" || n == "spot" ? "intensity"
                                       : n == "directional"        ? "irradiance"
                                                                   : "radiance");
    auto num = [&](const char* field, float& out) {
      if (pugi::xml_node e = kind.child(field)) out = one_float(e);
    };
    num("constant_attenuation", light.constant_attenuation);
    num("linear_attenuation", light.linear_attenuation);
    num("quadratic_attenuation", light.quadratic_attenuation);
    num("falloff_angle", light.falloff_degrees);
    num("falloff_exponent", light.falloff_exponent);
    if (light.kind == LightKind::point || light.kind == LightKind::spot) {
      for (auto [field, value] : {std::pair{"constant_attenuation", &light.constant_attenuation},
                                  std::pair{"linear_attenuation", &light.linear_attenuation},
                                  std::pair{"quadratic_attenuation", &light.quadratic_attenuation}})
        if (*value < 0.0f) {
          warn(kind.child(field), "a negative attenuation (" + number_text(*value) +
                                      ") would make the light brighter with distance; clamped to 0");
          *value = 0.0f;
        }
      if (light.constant_attenuation == 0.0f && light.linear_attenuation == 0.0f &&
          light.quadratic_attenuation == 0.0f) {
        warn(kind, "every attenuation is 0, which divides the light by zero; constant_attenuation "
                   "set to 1");
        light.constant_attenuation = 1.0f;
      }
    }
    if (light.kind == LightKind::spot && !(light.falloff_degrees > 0.0f)) {
      warn(kind.child("falloff_angle") ? kind.child("falloff_angle") : kind,
           "a spot light whose cone has an angle of " + number_text(light.falloff_degrees) +
               " degrees lights nothing; left out");
      return;
    }
    if (light.kind == LightKind::spot && light.falloff_exponent < 0.0f) {
      warn(kind.child("falloff_exponent"), "a negative falloff exponent (" +
                                               number_text(light.falloff_exponent) +
                                               ") brightens the cone's rim without bound; clamped to 0");
      light.falloff_exponent = 0.0f;
    }
  }
  if (!(light.radiance.x > 0.0f || light.radiance.y > 0.0f || light.radiance.z > 0.0f)) {
    warn(colour ? colour : el, "the light emits nothing (colour 0 0 0); left out");
    return;
  }
  scene_.lights.push_back(light);
  light_elements_.push_back(inst);
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

void ColladaReader::drop_lights_facing_away() {
  const Bounds3 b = scene_.bounds();
  size_t kept = 0;
  for (size_t i = 0; i < scene_.lights.size(); ++i) {
    const Light& l = scene_.lights[i];
    bool lights_something = true;
    if (l.kind == LightKind::area) {
      // One-sided: it lights what lies in front of its plane, and the bounds hold everything.
      const glm::dvec3 n = glm::cross(glm::dvec3(l.edge_u), glm::dvec3(l.edge_v));
      const glm::dvec3 front = glm::dot(n, glm::dvec3(l.direction)) < 0.0 ? -n : n;
      lights_something = false;
      for (int c = 0; c < 8; ++c) {
        const glm::dvec3 corner((c & 1) ? b.hi.x : b.lo.x, (c & 2) ? b.hi.y : b.lo.y,
                                (c & 4) ? b.hi.z : b.lo.z);
        lights_something |= glm::dot(corner - glm::dvec3(l.position), front) > 0.0;
      }
    }
    if (!lights_something) {
      warn(light_elements_[i], "the area light faces away from everything in the scene, so it "
                               "lights nothing; left out");
      continue;
    }
    light_elements_[kept] = light_elements_[i];
    scene_.lights[kept++] = l;
  }
  scene_.lights.resize(kept);
  light_elements_.resize(kept);
}

void ColladaReader::default_camera(pugi::xml_node vs) {
  const Bounds3 b = scene_.bounds();
  const glm::dvec3 up(up_vector());
  // Which side to look from: the one the scene's surfaces face most. Their vector area (each
  // triangle's area along the normal its shading normals give it) is zero for closed surfaces
  // whichever way they face, and points out of an open box (the course's Cornell boxes) through
  // its open side, where a camera sees into it; from any other side it would see the outside of
  // a wall. Only the four sides around the up axis are candidates, the file's usual view first.
  glm::dvec3 facing(0.0);
  double total = 0.0;
  for (const Triangle& t : scene_.triangles) {
    const glm::dvec3 p0(scene_.positions[t.v[0]]), p1(scene_.positions[t.v[1]]),
        p2(scene_.positions[t.v[2]]);
    glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
    const glm::dvec3 shading = glm::dvec3(scene_.normals[t.v[0]]) +
                               glm::dvec3(scene_.normals[t.v[1]]) + glm::dvec3(scene_.normals[t.v[2]]);
    if (glm::dot(n, shading) < 0.0) n = -n;
    facing += 0.5 * n;
    total += 0.5 * glm::length(n);
  }
  glm::dvec3 back = scene_.up_axis == "Z_UP" ? glm::dvec3(0, -1, 0) : glm::dvec3(0, 0, 1);
  const glm::dvec3 side = glm::cross(up, back);
  double best = glm::dot(facing, back);
  for (const glm::dvec3& w : {-back, side, -side})
    if (glm::dot(facing, w) > best + 1e-6 * total) back = w, best = glm::dot(facing, w);

  // In double: a scene of huge (finite) coordinates overflows float on the way (its diagonal's
  // square), which would give the camera infinite or NaN numbers. The result must be float.
  Camera cam;
  const glm::dvec3 lo(b.lo), hi(b.hi), centre = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * glm::length(hi - lo), 1e-3);
  const double vfov = 2.0 * std::atan(std::tan(glm::radians(double(cam.hfov_degrees)) / 2) / cam.aspect);
  const double half = 0.5 * std::min(glm::radians(double(cam.hfov_degrees)), vfov);
  const double distance = 1.1 * radius / std::sin(half);
  const glm::dvec3 eye = centre + distance * back;
  const glm::dvec3 right = glm::cross(up, back);
  cam.camera_to_world = glm::mat4(glm::vec4(glm::vec3(right), 0), glm::vec4(glm::vec3(up), 0),
                                  glm::vec4(glm::vec3(back), 0), glm::vec4(glm::vec3(eye), 1));
  cam.znear = float(std::max(1e-3, distance - 2 * radius));
  cam.zfar = float(distance + 2 * radius);
  const glm::vec3 e(eye);
  if (!std::isfinite(e.x + e.y + e.z) || !std::isfinite(cam.zfar))
    fail(vs, "no camera in the file, and the scene spans " + number_text(float(2 * radius)) +
                 " units: too far for a camera placed outside it to have float coordinates");
  scene_.camera = cam;
  const char* axis = back.x > 0.5 ? "+X" : back.x < -0.5 ? "-X" : back.y > 0.5 ? "+Y"
                   : back.y < -0.5 ? "-Y" : back.z > 0.5 ? "+Z" : "-Z";
  warn({}, std::string("no camera in the file; placed one outside the scene's bounds on their ") +
               axis + " side, looking at their centre");
}

Scene ColladaReader::read(pugi::xml_parse_result res) {
  if (res.status == pugi::status_file_not_found || res.status == pugi::status_io_error ||
      res.status == pugi::status_out_of_memory)
    throw SceneError(name_, "", std::string("cannot be read: ") + res.description());
  if (!res) {
    const std::string& text_ = text();
    size_t line = line_at(std::min<size_t>(size_t(std::max<ptrdiff_t>(res.offset, 0)), text_.size()));
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

  check_expansion(vs);
  for (pugi::xml_node child : vs.children()) {
    std::string_view n = child.name();
    if (n == "node")
      visit(child, glm::mat4(1.0f), 0);
    else if (n != "asset" && n != "extra" && n != "evaluate_scene")
      warn_unknown(child, "a <visual_scene>");
  }
  if (scene_.primitive_count() == 0)
    fail(vs, "the scene holds no triangle and no sphere: nothing to render");
  if (drawable_ == 0)
    fail(vs, "none of the scene's " + std::to_string(scene_.primitive_count()) +
                 " primitives can be drawn (degenerate, or too large for float arithmetic): "
                 "nothing to render");
  drop_lights_facing_away();
  if (!scene_.has_camera) default_camera(vs);
  scene_.source = name_;
  return std::move(scene_);
}

}  // namespace

Scene load_collada_string(const std::string& xml, const std::string& name, const WarningSink& warn,
                          const LoadLimits& limits) {
  ColladaReader reader(name, warn, limits);
  return reader.read_string(xml);
}

Scene load_collada(const std::string& path, const WarningSink& warn, const LoadLimits& limits) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st)) throw SceneError(path, "", "no such file");
  if (fs::is_directory(st)) throw SceneError(path, "", "is a directory, not a scene file");
  // A device or a pipe (/dev/zero) would be read for ever.
  if (!fs::is_regular_file(st))
    throw SceneError(path, "", "is not a regular file (a device or a pipe?), not a scene file");
  if (!std::ifstream(path, std::ios::binary))
    throw SceneError(path, "", "cannot be opened for reading (permissions?)");
  ColladaReader reader(path, warn, limits);
  return reader.read_file(path);
}

}  // namespace pt
