#include "render/golden.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "harness/tasks.h"

namespace a6::golden {
namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kFormat = "a6-golden-manifest";
constexpr int kVersion = 1;

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f%%", 100 * fraction);
  return text;
}

std::string joinPath(const std::string& folder, const std::string& file) {
  if (folder.empty()) return file;
  return (std::filesystem::path(folder) / file).string();
}

// One manifest entry from JSON; throws nlohmann's exceptions or std::runtime_error.
GoldenImage fromJson(const Json& j) {
  GoldenImage g;
  g.name = j.at("name").get<std::string>();
  g.scene = j.at("scene").get<std::string>();
  g.frame = j.at("frame").get<int>();
  g.time = j.value("time", 0.0);
  g.width = j.at("width").get<int>();
  g.height = j.at("height").get<int>();
  if (!parseCompareMode(j.value("compare", std::string("pixels")), &g.compare)) {
    throw std::runtime_error("compare must be \"pixels\" or \"density\"");
  }
  const Json& t = j.at("tolerance");
  g.tolerance.perChannel = t.at("perChannel").get<int>();
  g.tolerance.maxFraction = t.at("maxFraction").get<double>();
  g.tolerance.block = t.value("block", 16);
  g.task = j.at("task").get<int>();
  g.tasks = j.at("tasks").get<std::vector<int>>();
  g.shows = j.value("shows", std::string());
  g.hint = j.value("hint", std::string());
  g.studentFiles = j.value("studentFiles", std::string());
  g.renderer = j.value("renderer", std::string());
  g.baselines = j.at("baselines").get<std::vector<std::string>>();

  if (g.name.empty() || g.scene.empty()) throw std::runtime_error("empty name or scene");
  if (g.frame < 0) throw std::runtime_error("frame must be >= 0");
  if (g.width <= 0 || g.height <= 0) throw std::runtime_error("width and height must be > 0");
  if (g.tolerance.perChannel < 0 || g.tolerance.perChannel > 255) {
    throw std::runtime_error("tolerance.perChannel must be in [0, 255]");
  }
  if (!(g.tolerance.maxFraction >= 0 && g.tolerance.maxFraction <= 1)) {
    throw std::runtime_error("tolerance.maxFraction must be in [0, 1]");
  }
  if (g.tolerance.block < 1) throw std::runtime_error("tolerance.block must be >= 1");
  if (courseTasks().find(g.task) == nullptr) {
    throw std::runtime_error("task must be 1.." + std::to_string(courseTasks().count()));
  }
  if (!g.exercises(g.task)) throw std::runtime_error("tasks must include task");
  if (g.baselines.empty()) throw std::runtime_error("no baselines");
  return g;
}

Json toJson(const GoldenImage& g) {
  Json j;
  j["name"] = g.name;
  j["scene"] = g.scene;
  j["frame"] = g.frame;
  j["time"] = std::round(g.time * 1e6) / 1e6;  // readable: 1.0, not 0.9999999999999998
  j["width"] = g.width;
  j["height"] = g.height;
  j["compare"] = toString(g.compare);
  Json t;
  t["perChannel"] = g.tolerance.perChannel;
  t["maxFraction"] = g.tolerance.maxFraction;
  if (g.compare == CompareMode::Density) t["block"] = g.tolerance.block;
  j["tolerance"] = t;
  j["task"] = g.task;
  j["tasks"] = g.tasks;
  j["shows"] = g.shows;
  j["hint"] = g.hint;
  j["studentFiles"] = g.studentFiles;
  j["renderer"] = g.renderer;
  j["baselines"] = g.baselines;
  return j;
}

}  // namespace

const char* toString(CompareMode mode) {
  return mode == CompareMode::Density ? "density" : "pixels";
}

bool parseCompareMode(const std::string& text, CompareMode* mode) {
  if (text == "pixels") {
    *mode = CompareMode::Pixels;
  } else if (text == "density") {
    *mode = CompareMode::Density;
  } else {
    return false;
  }
  return true;
}

bool GoldenImage::exercises(int t) const {
  return std::find(tasks.begin(), tasks.end(), t) != tasks.end();
}

const GoldenImage* Manifest::find(const std::string& name) const {
  for (const GoldenImage& image : images) {
    if (image.name == name) return &image;
  }
  return nullptr;
}

ManifestResult readManifest(const std::string& path) {
  ManifestResult result;
  std::ifstream in(path);
  if (!in) {
    result.error = "cannot open the golden-image manifest " + path;
    return result;
  }
  Json j;
  try {
    j = Json::parse(in);
  } catch (const std::exception& e) {
    result.error = path + ": not valid JSON: " + e.what();
    return result;
  }
  if (j.value("format", std::string()) != kFormat || j.value("version", 0) != kVersion) {
    result.error =
        path + ": not an " + std::string(kFormat) + " of version " + std::to_string(kVersion);
    return result;
  }
  result.manifest.folder = std::filesystem::path(path).parent_path().string();
  std::set<std::string> names;
  const Json& images = j.value("images", Json::array());
  for (std::size_t k = 0; k < images.size(); ++k) {
    try {
      GoldenImage image = fromJson(images[k]);
      if (!names.insert(image.name).second) throw std::runtime_error("duplicate name");
      result.manifest.images.push_back(std::move(image));
    } catch (const std::exception& e) {
      const std::string name = images[k].is_object() ? images[k].value("name", std::string()) : "";
      result.error = path + ": image " + std::to_string(k) +
                     (name.empty() ? "" : " (" + name + ")") + ": " + e.what();
      result.manifest.images.clear();
      return result;
    }
  }
  return result;
}

std::string writeManifest(const Manifest& manifest, const std::string& path) {
  Json j;
  j["format"] = kFormat;
  j["version"] = kVersion;
  j["about"] =
      "Reference images of the scenes (docs/rendering.md). Re-render the primary baselines "
      "with: a6_render_solution --goldens";
  Json images = Json::array();
  for (const GoldenImage& image : manifest.images) images.push_back(toJson(image));
  j["images"] = images;
  std::ofstream out(path);
  out << j.dump(2) << "\n";
  out.close();
  if (!out) return "cannot write the golden-image manifest " + path;
  return "";
}

std::string describeTasks(const GoldenImage& image) {
  std::string text =
      "task " + std::to_string(image.task) + " (" + courseTasks().file(image.task) + ")";
  std::string others;
  for (int t : image.tasks) {
    if (t == image.task) continue;
    others += (others.empty() ? "" : ", ") + std::string("task ") + std::to_string(t) + " (" +
              courseTasks().file(t) + ")";
  }
  if (!others.empty()) text += ", on top of " + others;
  return text;
}

Image blockAverage(const Image& image, int block) {
  block = std::max(block, 1);
  const int w = (image.width + block - 1) / block, h = (image.height + block - 1) / block;
  Image out(w, h);
  for (int by = 0; by < h; ++by) {
    for (int bx = 0; bx < w; ++bx) {
      const int x0 = bx * block, x1 = std::min(x0 + block, image.width);
      const int y0 = by * block, y1 = std::min(y0 + block, image.height);
      long sum[4] = {0, 0, 0, 0};
      for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
          const Rgba p = image.at(x, y);
          sum[0] += p.r, sum[1] += p.g, sum[2] += p.b, sum[3] += p.a;
        }
      }
      const long count = long(x1 - x0) * (y1 - y0);
      auto mean = [count](long s) { return static_cast<std::uint8_t>((s + count / 2) / count); };
      out.set(bx, by, Rgba{mean(sum[0]), mean(sum[1]), mean(sum[2]), mean(sum[3])});
    }
  }
  return out;
}

Verdict compareWithBaselines(const Image& actual, const GoldenImage& image,
                             const std::string& folder) {
  Verdict verdict;
  std::vector<Image> loaded(image.baselines.size());
  // Exact first, on decoded pixels.
  for (std::size_t k = 0; k < image.baselines.size(); ++k) {
    BaselineCheck check;
    check.file = image.baselines[k];
    ImageResult read = readPng(joinPath(folder, check.file), image.width, image.height);
    if (!read) {
      check.error = read.error;
    } else {
      loaded[k] = std::move(read.image);
      check.result = compare(actual, loaded[k], image.tolerance.perChannel);
      if (check.result.identical) {
        check.passed = true;
        if (verdict.matched < 0) {
          verdict.matched = static_cast<int>(k);
          verdict.identical = true;
        }
      }
    }
    verdict.checks.push_back(std::move(check));
  }
  // Then with the tolerance, block means in density mode.
  const bool density = image.compare == CompareMode::Density;
  const Image actualBlocks = density ? blockAverage(actual, image.tolerance.block) : Image();
  double fewest = 2;
  for (std::size_t k = 0; k < loaded.size(); ++k) {
    BaselineCheck& check = verdict.checks[k];
    if (!check.error.empty()) continue;
    if (density) {
      check.result = compare(actualBlocks, blockAverage(loaded[k], image.tolerance.block),
                             image.tolerance.perChannel);
      check.result.identical = check.result.identical && check.passed;
    }
    check.passed = check.passed || check.result.within(image.tolerance.maxFraction);
    if (check.passed && verdict.matched < 0) verdict.matched = static_cast<int>(k);
    if (check.result.fractionOverTolerance < fewest) {
      fewest = check.result.fractionOverTolerance;
      verdict.closest = static_cast<int>(k);
    }
  }
  verdict.passed = verdict.matched >= 0;
  const int shown = verdict.matched >= 0 ? verdict.matched : verdict.closest;
  if (shown >= 0) verdict.expected = std::move(loaded[shown]);
  return verdict;
}

std::string describeChecks(const GoldenImage& image, const Verdict& verdict) {
  std::ostringstream out;
  const bool density = image.compare == CompareMode::Density;
  const std::string unit = density ? "blocks of " + std::to_string(image.tolerance.block) + "x" +
                                         std::to_string(image.tolerance.block) + " px"
                                   : "pixels";
  for (const BaselineCheck& check : verdict.checks) {
    out << "    " << check.file << ": ";
    if (!check.error.empty()) {
      out << check.error << "\n";
      continue;
    }
    if (check.result.identical) {
      out << "identical\n";
      continue;
    }
    out << percent(check.result.fractionOverTolerance) << " of " << unit << " differ by more than "
        << image.tolerance.perChannel << " (limit " << percent(image.tolerance.maxFraction)
        << "), largest channel difference " << check.result.maxChannelDiff
        << (check.passed ? ": passes\n" : "\n");
  }
  return out.str();
}

FailureFiles writeFailureImages(const GoldenImage& image, const Image& actual,
                                const Image& expected, const std::string& folder) {
  FailureFiles files;
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) {
    files.error = "cannot create " + folder + ": " + ec.message();
    return files;
  }
  files.actual = joinPath(folder, image.name + ".actual.png");
  files.expected = joinPath(folder, image.name + ".expected.png");
  files.difference = joinPath(folder, image.name + ".diff.png");
  Image difference;
  if (image.compare == CompareMode::Density && !expected.empty()) {
    // The difference of the block means, each block drawn at its full size.
    const int block = image.tolerance.block;
    const Image small = differenceImage(blockAverage(actual, block), blockAverage(expected, block));
    difference = Image(actual.width, actual.height);
    for (int y = 0; y < small.height; ++y) {
      for (int x = 0; x < small.width; ++x) {
        difference.fillRect(x * block, y * block, block, block, small.at(x, y));
      }
    }
  } else {
    difference = differenceImage(actual, expected);
  }
  for (const auto& [file, picture] :
       {std::pair<const std::string&, const Image&>{files.actual, actual},
        {files.expected, expected},
        {files.difference, difference}}) {
    if (picture.empty()) continue;  // no readable baseline: nothing to show as expected
    const std::string error = writePng(picture, file);
    if (!error.empty() && files.error.empty()) files.error = error;
  }
  return files;
}

void removeFailureImages(const GoldenImage& image, const std::string& folder) {
  std::error_code ec;
  for (const char* suffix : {".actual.png", ".expected.png", ".diff.png"}) {
    std::filesystem::remove(joinPath(folder, image.name + suffix), ec);
  }
}

}  // namespace a6::golden
