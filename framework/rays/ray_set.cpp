// Not needed for the assignment: the definitions of framework/rays/ray_set.h.
#include "framework/rays/ray_set.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace pt {

namespace {

constexpr size_t kMagicSize = 8;

// The format is little-endian, as is every machine this project builds on; a big-endian one
// would need byte swaps here and is refused at compile time instead.
static_assert(sizeof(float) == 4, "ray sets store IEEE float32");

std::vector<char> read_file(const std::string& path, const char* magic, size_t record_size,
                            uint64_t* count) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open the file");
  std::vector<char> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (data.size() < kMagicSize + 8 || std::memcmp(data.data(), magic, kMagicSize) != 0)
    throw std::runtime_error(path + ": not a " + std::string(magic, kMagicSize) +
                             " file (the first 8 bytes are not that magic)");
  std::memcpy(count, data.data() + kMagicSize, 8);
  const uint64_t payload = data.size() - kMagicSize - 8;
  if (*count > payload / record_size || *count * record_size != payload)
    throw std::runtime_error(path + ": the header says " + std::to_string(*count) +
                             " records of " + std::to_string(record_size) + " bytes but " +
                             std::to_string(payload) + " bytes follow");
  return data;
}

void write_file(const std::string& path, const char* magic, uint64_t count, const void* records,
                size_t bytes) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error(path + ": cannot create the file");
  out.write(magic, kMagicSize);
  out.write(reinterpret_cast<const char*>(&count), 8);
  out.write(static_cast<const char*>(records), std::streamsize(bytes));
  if (!out) throw std::runtime_error(path + ": write failed");
}

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

std::vector<Ray> read_ray_set(const std::string& path) {
  uint64_t count = 0;
  const std::vector<char> data = read_file(path, "PTRAYS01", 32, &count);
  std::vector<Ray> rays(count);
  const char* p = data.data() + kMagicSize + 8;
  for (uint64_t i = 0; i < count; ++i, p += 32) {
    float f[8];
    std::memcpy(f, p, 32);
    Ray& r = rays[i];
    r.o = glm::vec3(f[0], f[1], f[2]);
    r.d = glm::vec3(f[3], f[4], f[5]);
    r.tmin = f[6];
    r.tmax = f[7];
    if (!finite(r.o) || !finite(r.d) || std::isnan(r.tmin) || std::isnan(r.tmax))
      throw std::runtime_error(path + ": ray " + std::to_string(i) +
                               " has a non-finite origin or direction, or a NaN tmin/tmax");
  }
  return rays;
}

void write_ray_set(const std::string& path, const std::vector<Ray>& rays) {
  std::vector<float> f;
  f.reserve(rays.size() * 8);
  for (const Ray& r : rays) f.insert(f.end(), {r.o.x, r.o.y, r.o.z, r.d.x, r.d.y, r.d.z, r.tmin, r.tmax});
  write_file(path, "PTRAYS01", rays.size(), f.data(), f.size() * sizeof(float));
}

std::vector<float> read_hit_set(const std::string& path) {
  uint64_t count = 0;
  const std::vector<char> data = read_file(path, "PTHITS01", 4, &count);
  std::vector<float> hits(count);
  std::memcpy(hits.data(), data.data() + kMagicSize + 8, count * 4);
  for (uint64_t i = 0; i < count; ++i)
    if (std::isnan(hits[i]))
      throw std::runtime_error(path + ": answer " + std::to_string(i) + " is NaN");
  return hits;
}

void write_hit_set(const std::string& path, const std::vector<float>& hits) {
  write_file(path, "PTHITS01", hits.size(), hits.data(), hits.size() * sizeof(float));
}

}  // namespace pt
