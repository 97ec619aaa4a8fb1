// Small folders for the website's tests: the framework's temp folder, with a helper that writes
// real PNG and JPEG images.
#pragma once

#include <OpenImageIO/imageio.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "framework/testing/temp_folder.h"

namespace pt::web::testing {

/// A temporary folder that is deleted when the test ends, which also makes real images.
class TestFolder : public pt::test::TempFolder {
 public:
  TestFolder() : TempFolder("pt-website-test") {}

  /// A real 4x4 image in the format OIIO picks from `format_file`'s extension, saved as `rel`
  /// (so a JPEG can be saved under a .png name).
  std::filesystem::path image(const std::string& rel, const std::string& format_ext = "") {
    std::filesystem::path p = path() / rel;
    std::filesystem::create_directories(p.parent_path());
    std::string ext = format_ext.empty() ? p.extension().string() : format_ext;
    std::filesystem::path made = p.string() + ".tmp" + ext;
    auto out = OIIO::ImageOutput::create(made.string());
    OIIO::ImageSpec spec(4, 4, 3, OIIO::TypeDesc::UINT8);
    std::vector<unsigned char> px(4 * 4 * 3, 200);
    if (!out || !out->open(made.string(), spec) ||
        !out->write_image(OIIO::TypeDesc::UINT8, px.data()) || !out->close()) {
      std::abort();
    }
    std::filesystem::rename(made, p);
    std::filesystem::permissions(p, std::filesystem::perms(0644));
    return p;
  }
};

}  // namespace pt::web::testing
