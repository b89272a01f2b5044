// The exact Euclidean distance transform of a binary image (shape_map.h squaredEdtBinary), after
// Felzenszwalb & Huttenlocher ("Distance transforms of sampled functions", Theory of Computing 2012,
// section 2): the squared distance is separable, min over columns of (min over rows).
// - Column pass: for a binary image the 1D transform along a column is the distance to the nearest
//   feature in that column. The image is cut into bands of whole rows (transform() below); each band
//   finds it by a sweep down and a sweep up over its own rows, seeded with the nearest feature row
//   above and below the band, so the bands run in parallel and a band's rows stay in cache.
// - Row pass: on each row of the band, the lower envelope of the parabolas (x - v)^2 + dy(v)^2, built
//   left to right in linear time with exact integer predicates (no division, no rounding), then
//   filled parabola by parabola over the texels where each is the lowest; the square root, when
//   wanted, is taken as each texel is written.
// Every value is an integer held exactly: column distances in uint32, squared distances in 64 bits
// while compared, in a double while filled and in uint32 when stored (2 x 32767^2 fits), so the
// result is exact for images up to 32767 texels a side; the float output is the correctly rounded
// square root of the exact squared distance. Bands depend on the image size only, so results never
// depend on the thread count.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "bake/revolution/shape_map.h"
#include "core/parallel.h"

namespace bake::revolution {
namespace {

constexpr std::size_t kBandTexels = std::size_t(1) << 17;

// The distance stored between the passes for "no feature in this column": larger than any real one,
// yet small enough that adding 1 never overflows.
constexpr std::uint32_t kNoneInColumn = std::uint32_t(1) << 30;

// Scratch of one row: the envelope's parabolas (apex v, g = dy^2 + v^2) and the first texel each is
// the lowest at.
struct Envelope {
  std::vector<int> v;
  std::vector<std::int64_t> g;
  std::vector<int> from;
};

// floor(a / b) for b > 0.
std::int64_t floorDivide(std::int64_t a, std::int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

// Row pass over one row: `column` holds the column distances (kNoneInColumn for none), `row` receives
// store(squared distance) per texel, or store(none) where the row sees no feature at all.
// Parabola k on the stack is hidden by the new one q when their meeting point is not right of where k
// took over from k - 1: (g_q - g_k)(v_k - v_{k-1}) <= (g_k - g_{k-1})(q - v_k), exact in 64 bits.
// Parabola j + 1 is then the lower one from the first integer x with
// 2 x (v_{j+1} - v_j) >= g_{j+1} - g_j, so each is filled over its own run of texels.
template <class T, class Store>
void rowEnvelope(const std::uint32_t* column, T* row, int n, Envelope& e, Store store) {
  int* v = e.v.data();
  std::int64_t* g = e.g.data();
  int k = -1;
  for (int q = 0; q < n; ++q) {
    const std::uint32_t dy = column[q];
    if (dy >= kNoneInColumn) continue;
    const std::int64_t gq = std::int64_t(dy) * dy + std::int64_t(q) * q;
    while (k >= 1 && (gq - g[k]) * (v[k] - v[k - 1]) <= (g[k] - g[k - 1]) * (q - v[k])) --k;
    ++k;
    v[k] = q;
    g[k] = gq;
  }
  if (k < 0) {
    for (int q = 0; q < n; ++q) row[q] = store.none();
    return;
  }
  int* from = e.from.data();
  from[0] = 0;
  for (int j = 0; j < k; ++j) {
    const std::int64_t twice = 2 * std::int64_t(v[j + 1] - v[j]);
    const std::int64_t first = -floorDivide(g[j] - g[j + 1], twice);  // ceil((g[j+1] - g[j]) / twice)
    from[j + 1] = int(std::clamp<std::int64_t>(first, from[j], n));
  }
  from[k + 1] = n;
  for (int j = 0; j <= k; ++j) {
    const double apex = v[j], lift = double(g[j] - std::int64_t(v[j]) * v[j]);  // dy^2: exact in a double
    for (int q = from[j]; q < from[j + 1]; ++q) {
      const double dx = q - apex;
      row[q] = store(dx * dx + lift);
    }
  }
}

// Squared distances below 2^53 are held exactly by a double.
struct StoreSquared {
  std::uint32_t operator()(double squared) const { return std::uint32_t(squared); }
  std::uint32_t none() const { return kNoFeature; }
};

struct StoreDistance {
  // The double square root rounded to float is the correctly rounded float square root.
  float operator()(double squared) const { return float(std::sqrt(squared)); }
  float none() const { return std::numeric_limits<float>::infinity(); }
};

// Whether an image byte is a feature texel; `zeroIsFeature` is 1 for FeatureTexels::zero.
inline bool isFeature(std::uint8_t byte, std::uint8_t zeroIsFeature) { return (byte != 0) != zeroIsFeature; }

// The image in bands of whole rows. Per band and column, the first and last feature row in the band
// (step 1, bands in parallel); then, per band, the nearest feature row above it and below it in every
// column, by running those along the bands (step 2); then each band alone (step 3, in parallel): the
// column distances of its rows by a sweep down and a sweep up seeded with the rows found in step 2,
// and the row pass on each of its rows while they are still in cache. The image is read twice and
// the output written once.
// "No feature row above / below": far enough that the distance to it is >= kNoneInColumn from every
// row, and near enough that computing it never overflows.
constexpr int kNoRowAbove = -(1 << 30), kNoRowBelow = 0x7fffffff;

struct Bands {
  int rows = 0, count = 0;
  std::vector<int> firstRow, lastRow;  // per band x column; after step 2: nearest below / above the band
};

void featureRowsPerBand(const std::uint8_t* feature, FeatureTexels which, std::size_t w, int height, Bands& b) {
  const std::uint8_t flip = which == FeatureTexels::zero ? 1 : 0;
  b.firstRow.assign(std::size_t(b.count) * w, kNoRowBelow);
  b.lastRow.assign(std::size_t(b.count) * w, kNoRowAbove);
  parallelForBlocks(std::size_t(b.count), 1, 0, [&](std::size_t band, std::size_t) {
    int* first = b.firstRow.data() + band * w;
    int* last = b.lastRow.data() + band * w;
    const int begin = int(band) * b.rows, end = std::min(height, begin + b.rows);
    for (int j = begin; j < end; ++j) {
      const std::uint8_t* f = feature + std::size_t(j) * w;
      for (std::size_t i = 0; i < w; ++i) {
        const bool hit = isFeature(f[i], flip);
        first[i] = hit ? std::min(first[i], j) : first[i];
        last[i] = hit ? j : last[i];
      }
    }
  });
  // Step 2: lastRow[band] becomes the last feature row above the band, firstRow[band] the first below.
  std::vector<int> above(w, kNoRowAbove), below(w, kNoRowBelow);
  for (int band = 0; band < b.count; ++band) {
    int* last = b.lastRow.data() + std::size_t(band) * w;
    for (std::size_t i = 0; i < w; ++i) {
      const int inBand = last[i];
      last[i] = above[i];
      above[i] = std::max(above[i], inBand);
    }
  }
  for (int band = b.count - 1; band >= 0; --band) {
    int* first = b.firstRow.data() + std::size_t(band) * w;
    for (std::size_t i = 0; i < w; ++i) {
      const int inBand = first[i];
      first[i] = below[i];
      below[i] = std::min(below[i], inBand);
    }
  }
}

// Step 3 for one band: the column distances of its rows into `dy` (the band's rows, in cache), then
// the row pass on each row, into `out`.
template <class T, class Store>
void transformBand(const std::uint8_t* feature, FeatureTexels which, std::size_t w, int height, const Bands& b,
                   int band, T* out, std::vector<int>& nearest, std::vector<std::uint32_t>& dy, Envelope& e,
                   Store store) {
  const int begin = band * b.rows, end = std::min(height, begin + b.rows);
  const std::uint8_t flip = which == FeatureTexels::zero ? 1 : 0;
  int* row = nearest.data();
  std::copy_n(b.lastRow.data() + std::size_t(band) * w, w, row);
  for (int j = begin; j < end; ++j) {
    const std::uint8_t* f = feature + std::size_t(j) * w;
    std::uint32_t* d = dy.data() + std::size_t(j - begin) * w;
    for (std::size_t i = 0; i < w; ++i) {
      row[i] = isFeature(f[i], flip) ? j : row[i];
      d[i] = std::min(std::uint32_t(j - row[i]), kNoneInColumn);
    }
  }
  std::copy_n(b.firstRow.data() + std::size_t(band) * w, w, row);
  for (int j = end - 1; j >= begin; --j) {
    const std::uint8_t* f = feature + std::size_t(j) * w;
    std::uint32_t* d = dy.data() + std::size_t(j - begin) * w;
    for (std::size_t i = 0; i < w; ++i) {
      row[i] = isFeature(f[i], flip) ? j : row[i];
      d[i] = std::min(d[i], std::min(std::uint32_t(row[i] - j), kNoneInColumn));
    }
  }
  for (int j = begin; j < end; ++j) rowEnvelope(dy.data() + std::size_t(j - begin) * w, out + std::size_t(j) * w, int(w), e, store);
}

template <class T, class Store>
void transform(const std::uint8_t* feature, FeatureTexels which, int width, int height, T* out, Store store) {
  if (width <= 0 || height <= 0) return;
  const std::size_t w = std::size_t(width);
  // Bands depend on the image alone (about 2^17 texels, so a band stays in cache).
  Bands bands;
  bands.rows = int(std::clamp<std::size_t>(kBandTexels / w, 4, 256));
  bands.count = (height + bands.rows - 1) / bands.rows;
  featureRowsPerBand(feature, which, w, height, bands);
  parallelForBlocks(std::size_t(bands.count), 1, 0, [&](std::size_t begin, std::size_t end) {
    std::vector<int> nearest(w);
    std::vector<std::uint32_t> dy(w * std::size_t(bands.rows));
    Envelope e{std::vector<int>(w), std::vector<std::int64_t>(w), std::vector<int>(w + 1)};
    for (std::size_t band = begin; band < end; ++band)
      transformBand(feature, which, w, height, bands, int(band), out, nearest, dy, e, store);
  });
}

}  // namespace

void squaredEdtBinary(const std::uint8_t* image, FeatureTexels which, int width, int height, std::uint32_t* out) {
  transform(image, which, width, height, out, StoreSquared{});
}

void distanceEdtBinary(const std::uint8_t* image, FeatureTexels which, int width, int height, float* out) {
  transform(image, which, width, height, out, StoreDistance{});
}

}  // namespace bake::revolution
