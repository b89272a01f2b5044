// bench-revolution-edt: the exact binary EDT behind shape maps from binary images (libbake
// squaredEdt2d, Felzenszwalb & Huttenlocher 2012) against OpenCV's exact distance transform
// (cv::distanceTransform, DIST_L2 with DIST_MASK_PRECISE) on the same images: random discs on square
// images of 512^2 ... 4096^2. Both produce the Euclidean distance of every texel to the nearest
// feature texel (the discs' texels); ours includes the conversion to 0/inf and the final square
// root, so both columns time "uint8 image in, float distances out". Medians of --repeats runs; the
// figure to quote is the ratio from one run. Both sides use all hardware threads.
// Output: CSV on stdout, one row per size.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "bake/revolution/shape_map.h"
#include "core/parallel.h"

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

// Conversion and square root are part of our pipeline (distanceFromBinary does the same), so they
// run in parallel too.
void ours(const cv::Mat& image, std::vector<float>& out) {
  const int w = image.cols, h = image.rows;
  out.resize(std::size_t(w) * h);
  bake::parallelForBlocks(std::size_t(h), std::max<std::size_t>(1, (std::size_t(1) << 20) / w), 0, [&](std::size_t begin, std::size_t end) {
    for (std::size_t y = begin; y < end; ++y) {
      const unsigned char* row = image.ptr<unsigned char>(int(y));
      float* dst = out.data() + y * w;
      for (int x = 0; x < w; ++x) dst[x] = row[x] == 0 ? 0.0f : std::numeric_limits<float>::infinity();
    }
  });
  bake::revolution::squaredEdt2d(out, w, h);
  bake::parallelForBlocks(out.size(), std::size_t(1) << 20, 0, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) out[k] = std::sqrt(out[k]);
  });
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes{512, 1024, 2048, 4096};
  int repeats = 5;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--repeats" && k + 1 < argc) {
      repeats = std::max(1, std::atoi(argv[++k]));
    } else if (arg == "--sizes" && k + 1 < argc) {
      sizes.clear();
      std::string list = argv[++k];
      for (std::size_t at = 0; at < list.size();) {
        const std::size_t comma = list.find(',', at);
        sizes.push_back(std::atoi(list.substr(at, comma - at).c_str()));
        at = comma == std::string::npos ? list.size() : comma + 1;
      }
    } else {
      std::fprintf(stderr, "usage: bench-revolution-edt [--sizes 512,1024,...] [--repeats N]\n");
      return 1;
    }
  }
  std::printf("size,ours_ms,opencv_ms,ours_over_opencv,max_abs_diff_texels,opencv_threads\n");
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
    const double a = median(oursTimes) * 1e3, b = median(peerTimes) * 1e3;
    std::printf("%d,%.3f,%.3f,%.3f,%.3g,%d\n", size, a, b, a / b, worst, cv::getNumThreads());
    std::fflush(stdout);
  }
  return 0;
}
