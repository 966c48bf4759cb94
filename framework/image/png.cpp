// PNG files through stb_image / stb_image_write (Debian's libstb-dev headers).
//
// The only translation unit with stb's implementation. It is compiled `static` (STB_*_STATIC)
// so that it cannot clash with Debian's libstb.so, which Dear ImGui links in the viewer.
// Files are read and written here, not by stb, so that errors can say what went wrong.
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

#include "image/image.h"

// stb compiled static leaves unused functions; its structs skip some initialisers.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_NO_STDIO
#include <stb_image.h>
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb_image_write.h>
#pragma GCC diagnostic pop

namespace a6 {
namespace {

void appendBytes(void* context, void* data, int size) {
  auto* bytes = static_cast<std::vector<unsigned char>*>(context);
  const auto* begin = static_cast<const unsigned char*>(data);
  bytes->insert(bytes->end(), begin, begin + size);
}

std::string size(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

}  // namespace

std::string writePng(const Image& image, const std::string& path) {
  if (image.empty() || image.pixels.size() != static_cast<size_t>(image.width) * image.height * 4) {
    return "writePng " + path + ": the image is empty or malformed (" +
           size(image.width, image.height) + ", " + std::to_string(image.pixels.size()) + " bytes)";
  }
  // Encode in memory, then write: a failed write then names the file and the reason.
  std::vector<unsigned char> bytes;
  if (!stbi_write_png_to_func(appendBytes, &bytes, image.width, image.height, 4,
                              image.pixels.data(), image.width * 4)) {
    return "writePng " + path + ": PNG encoding failed";
  }
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file) {
    return "writePng: cannot open " + path + " for writing (" + std::strerror(errno) +
           "): does its folder exist and is it writable?";
  }
  file.write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
  file.close();
  if (!file) return "writePng: writing " + path + " failed (" + std::strerror(errno) + ")";
  return "";
}

ImageResult readPng(const std::string& path, int expectedWidth, int expectedHeight) {
  ImageResult result;
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    result.error = "readPng: cannot open " + path + " (" + std::strerror(errno) + ")";
    return result;
  }
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(file)),
                                         std::istreambuf_iterator<char>());
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kSignature, 8) != 0) {
    result.error = "readPng: " + path + " is not a PNG file (" + std::to_string(bytes.size()) +
                   " bytes, no PNG signature)";
    return result;
  }
  int w = 0, h = 0, channels = 0;
  unsigned char* data =
      stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &w, &h, &channels, 4);
  if (data == nullptr) {
    result.error = "readPng: " + path + " is a damaged PNG (" + stbi_failure_reason() + ")";
    return result;
  }
  result.image.width = w;
  result.image.height = h;
  result.image.pixels.assign(data, data + static_cast<size_t>(w) * h * 4);
  stbi_image_free(data);
  if (expectedWidth > 0 && expectedHeight > 0 && (w != expectedWidth || h != expectedHeight)) {
    result.error = "readPng: " + path + " is " + size(w, h) + ", expected " +
                   size(expectedWidth, expectedHeight);
  }
  return result;
}

}  // namespace a6
