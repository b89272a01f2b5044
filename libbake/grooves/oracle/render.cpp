// The rendering model of formats/groove-scene.md: views, the one material model, image output and
// image error figures, shared by the seed's method, the reference and the benchmark.
#include "grooves/oracle/render.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>


namespace bake::grooves {
namespace {

double dot(const Vec3& a, const Vec3& b) { return a.u * b.u + a.v * b.v + a.w * b.w; }

Vec3 normalised(const Vec3& a) {
  const double n = std::sqrt(dot(a, a));
  return n > 0 ? Vec3{a.u / n, a.v / n, a.w / n} : a;
}

}  // namespace

Footprint View::pixel(int x, int y) const {
  Footprint f;
  f.centre = {origin.u + (x + 0.5) * axisX.u + (y + 0.5) * axisY.u,
              origin.v + (x + 0.5) * axisX.v + (y + 0.5) * axisY.v};
  f.axis1 = axisX;
  f.axis2 = axisY;
  return f;
}

Vec3 directionFromAngles(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

View windowView(Vec2 lower, Vec2 upper, int width, double theta, double phi) {
  View view;
  view.toViewer = directionFromAngles(theta, phi);
  const double pixel = (upper.u - lower.u) / width;
  view.width = width;
  view.height = std::max(1, static_cast<int>(std::lround((upper.v - lower.v) / pixel)));
  // Image rows run down the screen: y grows towards lower v.
  view.origin = {lower.u, upper.v};
  view.axisX = {pixel, 0};
  view.axisY = {0, -pixel};
  return view;
}

Image rgbImage(int width, int height) {
  Image image;
  image.width = std::max(0, width);
  image.height = std::max(0, height);
  image.channels = 3;
  image.pixels.assign(std::size_t(image.width) * image.height * 3, 0.0f);
  return image;
}

Rgb rgbAt(const Image& image, int x, int y) { return {image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)}; }

void setRgb(Image& image, int x, int y, const Rgb& value) {
  for (int c = 0; c < 3; ++c) image.at(x, y, c) = static_cast<float>(value[c]);
}

Rgb environmentReflection(const Material& material, const Lighting& lighting) {
  if (!material.hasMirror || lighting.maxBounces <= 0) return {0, 0, 0};
  return {material.mirror[0] * lighting.environment[0], material.mirror[1] * lighting.environment[1],
          material.mirror[2] * lighting.environment[2]};
}

Rgb flatBaseRadiance(const Material& base, const Vec3& toViewer, const Lighting& lighting) {
  Rgb out = directRadiance(base, {0, 0, 1}, toViewer, lighting);
  const Rgb reflected = environmentReflection(base, lighting);
  for (int c = 0; c < 3; ++c) out[c] += reflected[c];
  return out;
}

Rgb directRadiance(const Material& material, const Vec3& normal, const Vec3& toViewer, const Lighting& lighting) {
  const double cosLight = dot(normal, lighting.toLight);
  if (cosLight <= 0) return {0, 0, 0};
  const Vec3 half = normalised({toViewer.u + lighting.toLight.u, toViewer.v + lighting.toLight.v,
                                toViewer.w + lighting.toLight.w});
  const double n = material.shininess;
  const double lobe = (n + 2) / (8 * std::numbers::pi) * std::pow(std::max(dot(normal, half), 0.0), n);
  Rgb out;
  for (int c = 0; c < 3; ++c)
    out[c] = (material.albedo[c] / std::numbers::pi + material.specular[c] * lobe) * cosLight * lighting.radiance[c];
  return out;
}

namespace {

bool sameVec(const Vec3& a, const Vec3& b) { return a.u == b.u && a.v == b.v && a.w == b.w; }

void appendReflectance(const std::vector<Material>& materials, std::vector<double>& out) {
  for (const Material& m : materials) {
    out.insert(out.end(), std::begin(m.albedo), std::end(m.albedo));
    out.insert(out.end(), std::begin(m.specular), std::end(m.specular));
    out.push_back(m.shininess);
  }
}

bool sameReflectance(const std::vector<Material>& materials, const std::vector<double>& known) {
  if (known.size() != 7 * materials.size()) return false;
  const double* k = known.data();
  for (const Material& m : materials) {
    for (int c = 0; c < 3; ++c)
      if (k[c] != m.albedo[c] || k[3 + c] != m.specular[c]) return false;
    if (k[6] != m.shininess) return false;
    k += 7;
  }
  return true;
}

// The per-thread store, emptied unless it holds this view, light and materials' entries.
RadianceMemo::Store& storeFor(const std::vector<Material>& materials, const Vec3& toViewer, const Lighting& lighting) {
  thread_local RadianceMemo::Store store;
  if (!sameVec(store.toViewer, toViewer) || !sameVec(store.toLight, lighting.toLight) ||
      store.lightRadiance != lighting.radiance || !sameReflectance(materials, store.reflectance)) {
    store.toViewer = toViewer;
    store.toLight = lighting.toLight;
    store.lightRadiance = lighting.radiance;
    store.reflectance.clear();
    appendReflectance(materials, store.reflectance);
    store.count = store.next = 0;
    ++store.generation;
  }
  return store;
}

}  // namespace

RadianceMemo::RadianceMemo(const std::vector<Material>& materials, const Vec3& toViewer, const Lighting& lighting)
    : materials_(materials), toViewer_(toViewer), lighting_(lighting),
      store_(storeFor(materials, toViewer, lighting)), generation_(store_.generation) {}

Rgb RadianceMemo::operator()(std::size_t material, const Vec3& normal) {
  // A memo made in between under another view or light (a mirror bounce's) emptied the store.
  if (store_.generation != generation_) generation_ = storeFor(materials_, toViewer_, lighting_).generation;
  for (int i = 0; i < store_.count; ++i) {
    const Entry& e = store_.entries[i];
    if (e.material == material && sameVec(e.normal, normal)) return e.radiance;
  }
  Entry& slot = store_.entries[store_.next];
  slot = {material, normal, directRadiance(materials_[material], normal, toViewer_, lighting_)};
  store_.next = (store_.next + 1) % kEntries;
  store_.count = std::max(store_.count, store_.next == 0 ? kEntries : store_.next);
  return slot.radiance;
}

Vec3 reflect(const Vec3& toViewer, const Vec3& normal) {
  const double d = 2 * dot(toViewer, normal);
  return normalised({d * normal.u - toViewer.u, d * normal.v - toViewer.v, d * normal.w - toViewer.w});
}

ImageError imageError(const Image& image, const Image& reference) {
  ImageError e;
  const std::size_t pixels = std::size_t(reference.width) * reference.height;
  if (image.width != reference.width || image.height != reference.height || image.channels != 3 ||
      reference.channels != 3 || pixels == 0) {
    e.rmse = e.relativeMse = e.p99 = e.max = std::numeric_limits<double>::infinity();
    return e;
  }
  double squared = 0, referenceSquared = 0;
  std::vector<double> pixelError(pixels);
  for (std::size_t i = 0; i < pixels; ++i) {
    double worst = 0;
    for (int c = 0; c < 3; ++c) {
      const double d = double(image.pixels[i * 3 + c]) - reference.pixels[i * 3 + c];
      squared += d * d;
      referenceSquared += double(reference.pixels[i * 3 + c]) * reference.pixels[i * 3 + c];
      worst = std::max(worst, std::abs(d));
    }
    pixelError[i] = worst;
  }
  e.rmse = std::sqrt(squared / (3.0 * pixels));
  e.relativeMse = referenceSquared > 0 ? squared / referenceSquared : 0;
  std::sort(pixelError.begin(), pixelError.end());
  e.p99 = pixelError[std::min(pixels - 1, static_cast<std::size_t>(std::ceil(0.99 * pixels)) - 1)];
  e.max = pixelError.back();
  return e;
}

}  // namespace bake::grooves
