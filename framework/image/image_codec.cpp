// Not needed for the assignment: the definitions of framework/image/image_codec.h.
#include "framework/image/image_codec.h"

#include <cstdlib>
#include <filesystem>

#include <dlfcn.h>

namespace pt {
namespace {

/// The folders the module is looked for in, in order (see load_image_codec).
std::vector<std::filesystem::path> module_folders() {
  std::vector<std::filesystem::path> folders;
  if (const char* dir = std::getenv("PT_IMAGE_MODULE_DIR"); dir && *dir) {
    folders.emplace_back(dir);
    return folders;  // asked for one place: look nowhere else
  }
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) folders.push_back(exe.parent_path());
#ifdef PT_IMAGE_MODULE_BUILD_DIR
  folders.emplace_back(PT_IMAGE_MODULE_BUILD_DIR);
#endif
  return folders;
}

}  // namespace

const ImageCodec& load_image_codec(const std::string& path) {
  std::string tried;
  for (const std::filesystem::path& folder : module_folders()) {
    const std::filesystem::path module = folder / kImageModuleName;
    std::error_code ec;
    if (!std::filesystem::exists(module, ec)) {
      tried += "\n  " + module.string() + ": no such file";
      continue;
    }
    // Never closed (RTLD_NODELETE): the image library keeps threads and caches of its own, and
    // opening it again is then a lookup of the loaded module, not a second load. Bound lazily:
    // binding every call of its 260 libraries up front is most of the cost of opening it, and an
    // image write calls few of them.
    void* handle = dlopen(module.c_str(), RTLD_LAZY | RTLD_LOCAL | RTLD_NODELETE);
    if (!handle) {
      const char* why = dlerror();
      tried += "\n  " + module.string() + ": " + (why ? why : "cannot be loaded");
      continue;
    }
    auto entry = reinterpret_cast<ImageCodecEntry>(dlsym(handle, PT_IMAGE_CODEC_ENTRY));
    const ImageCodec* codec = entry ? entry() : nullptr;
    if (codec) return *codec;
    tried += "\n  " + module.string() + ": has no " PT_IMAGE_CODEC_ENTRY " (a module of another version)";
  }
  throw ImageError(path, "cannot load the image module " + std::string(kImageModuleName) +
                             " (OpenImageIO) to read or write it; looked in:" +
                             (tried.empty() ? std::string("\n  (nowhere)") : tried));
}

}  // namespace pt
