// Cheater (attacks the results themselves; replaces parts/1-raygen/sphere_intersect.cpp): carries
// its payload (kPayload: the bundle's test grades it with two payloads and counts every character
// in which the two results differ) out by every channel a process of it has. Each hit
// it returns has a t whose 23 mantissa bits are the payload's next bits (the judge prints the
// student's values); it prints the payload on lines made to look like a stub's; each process
// of the sphere's probe or of a render sleeps a payload-chosen time, the probe then crashes by a
// payload-chosen signal and the render exits with a payload-chosen status. Everything else of
// Part 1 stays as the stubs leave it.
#include "parts/1-raygen/sphere_intersect.h"

#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace pt {
namespace {

// The payload, in hex after "PAYLOAD:": the bundle's test writes 4 KB of its own in its place.
const char kPayload[] = "PAYLOAD:00112233445566778899aabbccddeeff";

unsigned byte_at(size_t k) {
  const char* hex = kPayload + 8;
  const size_t bytes = (sizeof kPayload - 9) / 2;
  k %= bytes;
  char pair[3] = {hex[2 * k], hex[2 * k + 1], 0};
  return unsigned(std::strtoul(pair, nullptr, 16));
}

size_t next_bit = 0;

/// The payload's next `n` bits.
uint32_t bits(int n) {
  uint32_t v = 0;
  for (int i = 0; i < n; ++i, ++next_bit) v = (v << 1) | ((byte_at(next_bit / 8) >> (7 - next_bit % 8)) & 1u);
  return v;
}

std::string program() {
  char self[4096] = {0};
  ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  return n > 0 ? std::string(self, size_t(n)) : "";
}

/// Which process this is: the sphere's probe, a render, or another of Part 1's (left alone).
const std::string kProgram = program();
const bool kSphereProbe = kProgram.find("sphere") != std::string::npos;
const bool kRender = kProgram.find("pathtracer") != std::string::npos;

void at_exit() {
  if (kRender) _exit(int(1 + byte_at(7) % 254));
  const int signals[] = {SIGSEGV, SIGABRT, SIGFPE, SIGBUS, SIGILL, SIGTRAP, SIGSYS, SIGUSR1};
  std::signal(signals[byte_at(8) % 8], SIG_DFL);
  std::raise(signals[byte_at(8) % 8]);
}

struct Channels {
  Channels() {
    if (!kSphereProbe && !kRender) return;
    // A line that looks like a stub's, with the payload for its line number and after it.
    std::printf("part 1 not implemented: intersect_sphere at parts/1-raygen/sphere_intersect.cpp:%u %s\n",
                byte_at(0) * 256 + byte_at(1), kPayload);
    std::fprintf(stderr, "part 1 not implemented: %s\n", kPayload + 8);
    std::fflush(stdout);
    usleep(useconds_t(1000 * byte_at(2)));
    std::atexit(at_exit);
  }
} channels;

}  // namespace

bool intersect_sphere(const Ray&, const Sphere&, float* t) {
  // In [1, 2), its mantissa the payload's: the same hit or miss, whatever the payload says.
  const uint32_t word = 0x3f800000u | bits(23);
  std::memcpy(t, &word, sizeof word);
  return true;
}

}  // namespace pt
