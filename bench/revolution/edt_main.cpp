// bench-revolution-edt: the exact binary EDT behind shape maps from binary images (libbake
// distanceEdtBinary, edt_binary.cpp) against OpenCV's exact distance transform (cv::distanceTransform,
// DIST_L2 with DIST_MASK_PRECISE) on the same images: random discs on square images. Both go from the
// 8-bit image (features = its zero texels) to float distances and use all hardware threads. Medians
// of --repeats runs; the figure to quote is the ratio from one run.
// Correctness is checked apart from OpenCV (which is wrong beyond 4096 wide): at 4,096 random texels
// plus the corners of every image, ours must equal the square root of the brute-force squared distance
// to the feature texels that border a non-feature texel (the nearest feature always does), computed
// here in 64-bit integers. --check-sizes adds sizes that are only checked, not timed against OpenCV.
// Output: CSV on stdout, one row per size.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "bake/revolution/shape_map.h"

namespace {

// Features (value 0) inside random discs, 255 elsewhere: OpenCV's convention (distance to zeros).
cv::Mat randomDiscs(int size, unsigned seed) {
  cv::Mat image(size, size, CV_8UC1, cv::Scalar(255));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> centre(0.0, size), radius(0.01 * size, 0.08 * size);
  for (int k = 0; k < 24; ++k) {
    const double cx = centre(rng), cy = centre(rng), r = radius(rng);
    const int y0 = std::max(0, int(cy - r)), y1 = std::min(size - 1, int(cy + r) + 1);
    const int x0 = std::max(0, int(cx - r)), x1 = std::min(size - 1, int(cx + r) + 1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        if ((x + 0.5 - cx) * (x + 0.5 - cx) + (y + 0.5 - cy) * (y + 0.5 - cy) <= r * r) image.at<unsigned char>(y, x) = 0;
  }
  return image;
}

double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

void ours(const cv::Mat& image, std::vector<float>& out) {
  out.resize(std::size_t(image.cols) * image.rows);
  bake::revolution::distanceEdtBinary(image.data, bake::revolution::FeatureTexels::zero, image.cols, image.rows, out.data());
}

// The check described above: texels checked and texels that differ.
std::pair<int, int> checkAgainstBruteForce(const cv::Mat& image, const std::vector<float>& mine, unsigned seed) {
  const int w = image.cols, h = image.rows;
  auto isFeature = [&](int x, int y) { return image.at<unsigned char>(y, x) == 0; };
  std::vector<std::pair<int, int>> border;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!isFeature(x, y)) continue;
      const bool edge = (x > 0 && !isFeature(x - 1, y)) || (x + 1 < w && !isFeature(x + 1, y)) ||
                        (y > 0 && !isFeature(x, y - 1)) || (y + 1 < h && !isFeature(x, y + 1));
      if (edge) border.push_back({x, y});
    }
  std::vector<std::pair<int, int>> probes{{0, 0}, {w - 1, 0}, {0, h - 1}, {w - 1, h - 1}};
  std::mt19937 rng(seed);
  for (int k = 0; k < 4096; ++k) probes.push_back({int(rng() % unsigned(w)), int(rng() % unsigned(h))});
  int wrong = 0;
  for (const auto& [x, y] : probes) {
    std::uint64_t best = isFeature(x, y) ? 0 : std::numeric_limits<std::uint64_t>::max();
    for (const auto& [bx, by] : border) {
      if (best == 0) break;
      const std::int64_t dx = bx - x, dy = by - y;
      best = std::min(best, std::uint64_t(dx * dx + dy * dy));
    }
    const float expected = best == std::numeric_limits<std::uint64_t>::max() ? std::numeric_limits<float>::infinity()
                                                                               : float(std::sqrt(double(best)));
    if (mine[std::size_t(y) * w + x] != expected) ++wrong;
  }
  return {int(probes.size()), wrong};
}

}  // namespace

std::vector<int> parseSizes(const std::string& list) {
  std::vector<int> sizes;
  for (std::size_t at = 0; at < list.size();) {
    const std::size_t comma = list.find(',', at);
    sizes.push_back(std::atoi(list.substr(at, comma == std::string::npos ? std::string::npos : comma - at).c_str()));
    at = comma == std::string::npos ? list.size() : comma + 1;
  }
  return sizes;
}

int main(int argc, char** argv) {
  std::vector<int> sizes{512, 1024, 2048, 4096, 8192}, checkSizes;
  int repeats = 5;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--repeats" && k + 1 < argc) {
      repeats = std::max(1, std::atoi(argv[++k]));
    } else if (arg == "--sizes" && k + 1 < argc) {
      sizes = parseSizes(argv[++k]);
    } else if (arg == "--check-sizes" && k + 1 < argc) {
      checkSizes = parseSizes(argv[++k]);
    } else {
      std::fprintf(stderr, "usage: bench-revolution-edt [--sizes 512,1024,...] [--check-sizes 16384] [--repeats N]\n");
      return 1;
    }
  }
  std::printf("size,ours_ms,opencv_ms,ours_over_opencv,max_abs_diff_opencv,checked,wrong,threads\n");
  for (int size : sizes) {
    const cv::Mat image = randomDiscs(size, 1234u + unsigned(size));
    std::vector<double> oursTimes, peerTimes;
    std::vector<float> mine;
    cv::Mat theirs;
    for (int r = 0; r < repeats; ++r) {
      auto t0 = std::chrono::steady_clock::now();
      ours(image, mine);
      auto t1 = std::chrono::steady_clock::now();
      cv::distanceTransform(image, theirs, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
      auto t2 = std::chrono::steady_clock::now();
      oursTimes.push_back(seconds(t0, t1));
      peerTimes.push_back(seconds(t1, t2));
    }
    double worst = 0;
    for (int y = 0; y < size; ++y) {
      const float* row = theirs.ptr<float>(y);
      for (int x = 0; x < size; ++x)
        worst = std::max(worst, double(std::abs(row[x] - mine[std::size_t(y) * size + x])));
    }
    const auto [checked, wrong] = checkAgainstBruteForce(image, mine, unsigned(size));
    const double a = median(oursTimes) * 1e3, b = median(peerTimes) * 1e3;
    std::printf("%d,%.3f,%.3f,%.3f,%.3g,%d,%d,%d\n", size, a, b, a / b, worst, checked, wrong, cv::getNumThreads());
    std::fflush(stdout);
  }
  for (int size : checkSizes) {
    const cv::Mat image = randomDiscs(size, 1234u + unsigned(size));
    std::vector<float> mine;
    auto t0 = std::chrono::steady_clock::now();
    ours(image, mine);
    const double a = seconds(t0, std::chrono::steady_clock::now()) * 1e3;
    const auto [checked, wrong] = checkAgainstBruteForce(image, mine, unsigned(size));
    std::printf("%d,%.3f,,,,%d,%d,%d\n", size, a, checked, wrong, cv::getNumThreads());
    std::fflush(stdout);
  }
  return 0;
}
