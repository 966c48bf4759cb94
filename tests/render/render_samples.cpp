// Writes the sample snapshots as PNGs, to look at: a6_render_samples [folder] [backend]
//   cloth_types.png, cloth_strain.png, box2d.png, fire.png, test_snapshot.png, sizes.png (the test
//   snapshot at 128, 256 and 512 px), zoom.png and cloth_zoom.png
//   (close-ups), and contact_sheet.png (all of them, labelled).
#include <cstdio>
#include <string>

#include "contexts/gl_context.h"
#include "render/renderer.h"
#include "sample_snapshots.h"

namespace {

// The w x h pixels at (x, y), each drawn as a factor x factor block: to inspect edges.
a6::Image zoom(const a6::Image& image, int x, int y, int w, int h, int factor) {
  a6::Image out(w * factor, h * factor);
  for (int row = 0; row < h; ++row) {
    for (int col = 0; col < w; ++col) {
      out.fillRect(col * factor, row * factor, factor, factor, image.at(x + col, y + row));
    }
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace a6;
  const std::string folder = argc > 1 ? argv[1] : ".";
  HeadlessBackend backend = HeadlessBackend::Auto;
  if (argc > 2 && !parseHeadlessBackend(argv[2], &backend)) {
    std::fprintf(stderr, "unknown backend '%s' (auto, osmesa, egl)\n", argv[2]);
    return 2;
  }
  ContextResult context = makeHeadlessContext(512, 512, backend);
  if (!context) {
    std::fprintf(stderr, "%s\n", context.error.c_str());
    return 1;
  }
  std::printf("%s: %s\n", context.context->backend().c_str(),
              context.context->description().c_str());
  Renderer renderer(*context.context);
  if (!renderer.ok()) {
    std::fprintf(stderr, "%s\n", renderer.error().c_str());
    return 1;
  }
  std::vector<Image> all;
  std::vector<std::string> labels;
  auto save = [&](const std::string& name, const Image& image) {
    if (image.empty()) {
      std::fprintf(stderr, "%s: %s\n", name.c_str(), renderer.error().c_str());
      return false;
    }
    const std::string error = writePng(image, folder + "/" + name + ".png");
    if (!error.empty()) std::fprintf(stderr, "%s\n", error.c_str());
    all.push_back(image);
    labels.push_back(name);
    return error.empty();
  };
  bool ok = true;
  RenderOptions strain;
  strain.colorSpringsByStrain = true;
  ok &= save("cloth_types", renderer.render(test::clothSnapshot(), 480, 480));
  ok &= save("cloth_zoom", zoom(all.back(), 84, 64, 80, 60, 6));
  ok &= save("cloth_strain", renderer.render(test::clothSnapshot(), 480, 480, strain));
  ok &= save("box2d", renderer.render(test::box2dSnapshot(), 640, 480));
  ok &= save("fire", renderer.render(test::fireSnapshot(), 360, 480));
  ok &= save("test_snapshot", renderer.render(test::testSnapshot(), 256, 256));
  std::vector<Image> sizes;
  for (int size : {128, 256, 512})
    sizes.push_back(renderer.render(test::testSnapshot(), size, size));
  ok &= save("sizes", contactSheet(sizes, 3, {"128", "256", "512"}));
  // Close-ups of the 256 px test snapshot: the pinned corner, the Box2D circle, the hot particle.
  ok &= save("zoom",
             contactSheet({zoom(sizes[1], 24, 24, 48, 48, 8), zoom(sizes[1], 52, 156, 48, 48, 8),
                           zoom(sizes[1], 136, 72, 48, 24, 8)},
                          3, {"pinned A, A-B, A-D", "circle shape", "F and H"}));
  const std::string error = writePng(contactSheet(all, 3, labels), folder + "/contact_sheet.png");
  if (!error.empty()) std::fprintf(stderr, "%s\n", error.c_str());
  return ok && error.empty() ? 0 : 1;
}
