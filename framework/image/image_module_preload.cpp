// Not needed for the assignment: the definitions of framework/image/image_module_preload.h.
#include "framework/image/image_module_preload.h"

#include <exception>
#include <utility>

#include "framework/image/image_codec.h"

namespace pt {

ImageModulePreload::ImageModulePreload(std::string path)
    : thread_([path = std::move(path)] {
        try {
          load_image_codec(path);
        } catch (const std::exception&) {
          // The write asks again and throws the same error, where it can be reported.
        }
      }) {}

ImageModulePreload::~ImageModulePreload() { wait(); }

void ImageModulePreload::wait() {
  if (thread_.joinable()) thread_.join();
}

}  // namespace pt
