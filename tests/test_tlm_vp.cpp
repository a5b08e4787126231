// The example virtual platform (examples/virtual_platform): the image the CPU renders
// by driving the IP over the bus equals, byte for byte, the one rendered directly with
// Core::run on the same quantised inputs (the scene's header), and a few pixels agree
// with a geometry and formula written here independently, in double.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "../examples/virtual_platform/scene.h"
#include "specular/core.h"
#include "specular/reference.h"
#include "support/scratch.h"

namespace fs = std::filesystem;

namespace {

using namespace specular;

const std::string vp = std::string(SPECULAR_BINARY_DIR) + "/examples/virtual_platform/specular_vp";

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  unsigned char at(int x, int y, int ch) const { return rgb[3 * (static_cast<std::size_t>(y) * width + x) + ch]; }
};

/// Runs specular_vp in the folder of `log` (its scratch folder: a relative --out lands there).
int run_vp(const std::string& arguments, const fs::path& log) {
  const std::string command = "cd '" + log.parent_path().string() + "' && '" + vp + "' " + arguments +
                              " >'" + log.string() + "' 2>&1";
  const int raw = std::system(command.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

Image read_ppm(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int max = 0;
  Image image;
  in >> magic >> image.width >> image.height >> max;
  in.get();  // the single whitespace after the header
  EXPECT_EQ(magic, "P6");
  EXPECT_EQ(max, 255);
  image.rgb.resize(3ull * image.width * image.height);
  in.read(reinterpret_cast<char*>(image.rgb.data()), static_cast<std::streamsize>(image.rgb.size()));
  EXPECT_EQ(in.gcount(), static_cast<std::streamsize>(image.rgb.size())) << "truncated";
  return image;
}

/// The picture without the bus: scene.h's inputs, Core::run, scene.h's compositing.
Image render_directly(int size, const Config& config) {
  const Core core(config);
  Image image;
  image.width = size * static_cast<int>(vp::panel_n.size());
  image.height = size;
  image.rgb.resize(3ull * image.width * size);
  for (std::size_t p = 0; p < vp::panel_n.size(); ++p)
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        unsigned char* pixel = &image.rgb[3 * (static_cast<std::size_t>(y) * image.width + p * size + x)];
        vp::Vec normal{};
        if (!vp::normal_at(x, y, size, normal)) {
          for (int ch = 0; ch < 3; ++ch) pixel[ch] = vp::background[ch];
          continue;
        }
        Operands op;
        op.cos = vp::cos_code(normal);
        op.n = vp::panel_n[p];
        op.rgb = {vp::light_rgb[0], vp::light_rgb[1], vp::light_rgb[2]};
        const Result r = core.run(op);
        const auto base = vp::base_colour(normal);
        for (int ch = 0; ch < 3; ++ch)
          pixel[ch] = vp::add_specular(base[ch], static_cast<std::int32_t>(r.out[ch]));
      }
  return image;
}

fs::path scratch(const std::string& name) { return specular::testing_support::scratch_subdir(name); }

/// Runs specular_vp with `arguments`; its image must equal the direct rendering under
/// `config`. Returns the image.
Image expect_same_as_direct(const std::string& arguments, int size, const Config& config,
                            const std::string& name) {
  const fs::path dir = scratch(name);
  const fs::path ppm = dir / "image.ppm";
  const int status = run_vp("--out '" + ppm.string() + "' " + arguments, dir / "log.txt");
  EXPECT_EQ(status, 0) << std::ifstream(dir / "log.txt").rdbuf();
  if (status != 0) return {};
  const Image got = read_ppm(ppm);
  EXPECT_EQ(got.width, 4 * size);
  EXPECT_EQ(got.height, size);
  if (got.width != 4 * size || got.height != size) return got;
  const Image expected = render_directly(size, config);
  std::size_t differences = 0;
  for (std::size_t i = 0; i < got.rgb.size(); ++i) differences += got.rgb[i] != expected.rgb[i];
  EXPECT_EQ(differences, 0u) << "bytes that differ from the direct rendering";
  EXPECT_FALSE(fs::exists(dir / "image.ppm.tmp"));
  return got;
}

TEST(TlmVirtualPlatform, ImageEqualsTheCoreRenderingByteForByte) {
  Config config;
  config.normalisation = Normalisation::none;  // the platform's default
  expect_same_as_direct("", 256, config, "default");
}

// Issue 61: the frame's energy, per pixel and per frame, as the IP's model prices it.
TEST(TlmVirtualPlatform, ReportsTheFramesEnergyPerPixelAndPerFrame) {
  const fs::path dir = scratch("energy");
  ASSERT_EQ(run_vp("--out '" + (dir / "image.ppm").string() + "' --size 32", dir / "log.txt"), 0);
  std::ifstream in(dir / "log.txt");
  const std::string log((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::smatch m;
  ASSERT_TRUE(std::regex_search(log, m, std::regex(R"(energy ([0-9.e+]+) pJ per pixel, ([0-9.e+]+) uJ per frame \(operations ([0-9.e+]+) uJ)")))
      << log;
  const double per_pixel = std::stod(m[1]), per_frame_uj = std::stod(m[2]), operations_uj = std::stod(m[3]);
  const double pixels = 4 * 32 * 32;
  EXPECT_NEAR(per_frame_uj * 1e6, per_pixel * pixels, 1e-3 * per_frame_uj * 1e6);
  // Every pixel is one operation: more than nothing, less than the gate-level mean of
  // random operands (4 789 pJ, docs/design_space/energy_per_result.md) with room: a
  // sphere in raster order toggles fewer bits than random operands.
  EXPECT_GT(operations_uj * 1e6 / pixels, 500.0) << log;
  EXPECT_LT(operations_uj * 1e6 / pixels, 1.2 * 4789) << log;
  EXPECT_GT(per_frame_uj, operations_uj) << log;  // the bus and the clocks on top
}

TEST(TlmVirtualPlatform, PatentPolicyAtAnotherSizeToo) {
  Config config;
  config.normalisation = Normalisation::patent;
  expect_same_as_direct("--size 80 --policy patent", 80, config, "patent");
}

// --constants reaches the IP: under each constants policy the image equals Core's
// rendering under that policy, byte for byte, and differs from the patent constants'.
TEST(TlmVirtualPlatform, ConstantsPolicyReachesTheIp) {
  for (const Constants constants : {Constants::minimax_half, Constants::minimax}) {
    SCOPED_TRACE(to_string(constants));
    Config config;
    config.normalisation = Normalisation::patent;
    config.constants = constants;
    const Image got = expect_same_as_direct(
        std::string("--size 40 --policy patent --constants ") + to_string(constants), 40, config,
        std::string("constants_") + to_string(constants));
    Config patent_constants = config;
    patent_constants.constants = Constants::patent;
    const Image patent_image = render_directly(40, patent_constants);
    ASSERT_EQ(got.rgb.size(), patent_image.rgb.size());
    std::size_t differences = 0;
    for (std::size_t i = 0; i < got.rgb.size(); ++i) differences += got.rgb[i] != patent_image.rgb[i];
    EXPECT_GT(differences, 100u) << "the constants should change the highlights";
  }
  const fs::path dir = scratch("constants_bad");
  EXPECT_EQ(run_vp("--out x.ppm --constants schlick", dir / "log.txt"), 2);
  std::stringstream log;
  log << std::ifstream(dir / "log.txt").rdbuf();
  EXPECT_NE(log.str().find("'schlick' is not one of: patent, minimax-half, minimax"),
            std::string::npos)
      << log.str();
}

// Independent of scene.h: the sphere, the half-way vector and the formula written
// again here; the specular part of a few unsaturated pixels within one level.
TEST(TlmVirtualPlatform, PixelsAgreeWithAnIndependentDoubleComputation) {
  const fs::path dir = scratch("double");
  const int size = 256;
  ASSERT_EQ(run_vp("--out '" + (dir / "i.ppm").string() + "'", dir / "log.txt"), 0);
  const Image image = read_ppm(dir / "i.ppm");
  const double lx = -0.45, ly = 0.55, lz = 0.70;
  const double ll = std::sqrt(lx * lx + ly * ly + lz * lz);
  double hx = lx / ll, hy = ly / ll, hz = lz / ll + 1;
  const double hl = std::sqrt(hx * hx + hy * hy + hz * hz);
  hx /= hl, hy /= hl, hz /= hl;
  const unsigned ns[4] = {1, 10, 100, 1000};
  const double light[3] = {255, 244, 224};
  int checked = 0;
  for (int panel = 1; panel < 4; ++panel)
    for (int y = 20; y < size; y += 23)
      for (int x = 20; x < size; x += 19) {
        const double u = (x + 0.5 - 128) / (0.45 * 256), v = (128 - (y + 0.5)) / (0.45 * 256);
        if (u * u + v * v >= 1) continue;
        const double nz = std::sqrt(1 - u * u - v * v);
        const double cos = std::max(0.0, u * hx + v * hy + nz * hz);
        const double cos_q = std::round(cos * 65536) / 65536;
        const unsigned n = ns[panel];
        const double log2_cos = cos_q == 0 ? -16 : std::log2(cos_q);
        const double a = std::max(0.0, 1 - 0.5 * std::log2(1 - n * log2_cos));  // K = 1
        const double diffuse = std::max(0.0, (u * lx + v * ly + nz * lz) / ll);
        const double albedo[3] = {70, 90, 140};
        for (int ch = 0; ch < 3; ++ch) {
          const double expected = std::round(albedo[ch] * (0.15 + 0.85 * diffuse)) + a * light[ch];
          if (expected > 254) continue;  // saturated: nothing to compare
          EXPECT_NEAR(image.at(panel * size + x, y, ch), expected, 1.0)
              << "panel n = " << n << ", pixel " << x << "," << y << ", channel " << ch;
          ++checked;
        }
      }
  EXPECT_GT(checked, 300);
}

TEST(TlmVirtualPlatform, BadArgumentsAreRefused) {
  const fs::path dir = scratch("bad");
  for (const std::string& arguments :
       {std::string(""), std::string("--out x.ppm --size 8"), std::string("--out x.ppm --size 2000"),
        std::string("--out x.ppm --size 12a"), std::string("--out x.ppm --policy fancy"),
        std::string("--out x.ppm --colour 3"), std::string("--out"),
        std::string("--out x.ppm --constants schlick"), std::string("--out x.ppm --constants")}) {
    SCOPED_TRACE(arguments);
    EXPECT_EQ(run_vp(arguments, dir / "log.txt"), 2);
    std::stringstream log;
    log << std::ifstream(dir / "log.txt").rdbuf();
    EXPECT_NE(log.str().find("specular_vp: error: "), std::string::npos) << log.str();
  }
  EXPECT_EQ(run_vp("--out '" + (dir / "no" / "such" / "dir.ppm").string() + "'", dir / "log.txt"), 1);
}

}  // namespace
