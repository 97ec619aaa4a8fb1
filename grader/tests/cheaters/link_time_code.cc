// Cheater (replaces parts/1-raygen/sphere_intersect.cpp): an object that carries link-time code.
// The grader links a part's probes with its own rights, and a linker with GCC's plugin compiles
// the .gnu.lto_* sections an object carries, whatever flags built it: a slim LTO object's
// sections written out as raw bytes by a top-level asm, whose own asm .incbin's a protected file,
// would be compiled, and the file read, by the grader at link time. Any such section makes the
// object refused before the link; this one needs no working payload to show it.
#include "parts/1-raygen/sphere_intersect.h"

asm(".section .gnu.lto_.symtab.0,\"e\",@progbits\n.byte 0\n.previous\n");

namespace pt {
bool intersect_sphere(const Ray&, const Sphere&, float*) { return false; }
}  // namespace pt
