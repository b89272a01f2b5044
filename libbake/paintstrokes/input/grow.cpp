// Strokes grown on a mesh: seed 002's furry models ("this method works particularly well for fur"),
// made from a triangle mesh instead of control points typed by hand.
//
// Roots are scattered over the surface with probability proportional to triangle area: a triangle
// is chosen by binary search in the prefix sums of the areas, then a point uniformly inside it by the
// square-root barycentric mapping (Osada et al. 2002, "Shape distributions", section 4.2). Each stroke
// grows along the interpolated vertex normal (area-weighted face normals when the mesh has none),
// tilted and lengthened at random by `jitter`, and bends towards `bendDirection` on a parabola
// p(t) = root + L (t d + bend t^2 g), so the tip is displaced by bend * L. Radius tapers linearly,
// colour runs linearly from root to tip. For the seed's self-shadowing (paragraph "Each control point
// of a paintstroke contains a user-specified global normal and depth value") the global normal is the
// root's surface normal and the depth falls from 1 at the root (inside the fur) to 0 at the tip (its
// outer surface).
//
// Everything random comes from one std::mt19937_64 seeded by `seed`, drawn in a fixed order in a
// single thread, so the strokes are identical on every run and for any thread count.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bake/io/image.h"
#include "bake/io/mesh.h"
#include "bake/paintstrokes/generators.h"
#include "bake_formats/paintstrokes.h"
#include "paintstrokes/input/generator_math.h"

namespace bake::paintstrokes {
namespace {

using namespace detail;

// "vertex:NAME" / "texture:PATH" / "vertex" / "": the kind and its argument.
struct Source {
  enum class Kind { None, Vertex, Texture } kind = Kind::None;
  std::string argument;
};

Result<Source> parseSource(const std::string& text, const std::string& field, bool vertexNeedsName) {
  Source source;
  if (text.empty()) return source;
  const auto startsWith = [&](const char* prefix) { return text.rfind(prefix, 0) == 0; };
  if (startsWith("texture:")) {
    source.kind = Source::Kind::Texture;
    source.argument = text.substr(8);
  } else if (startsWith("vertex:") && vertexNeedsName) {
    source.kind = Source::Kind::Vertex;
    source.argument = text.substr(7);
  } else if (text == "vertex" && !vertexNeedsName) {
    source.kind = Source::Kind::Vertex;
    source.argument = "COLOR_0";
  } else {
    return badSetting(field, std::string("must be \"\", ") + (vertexNeedsName ? "\"vertex:NAME\"" : "\"vertex\"") +
                                 " or \"texture:PATH\", not \"" + text + "\"");
  }
  if (source.argument.empty()) return badSetting(field, "\"" + text + "\" names nothing after the colon");
  return source;
}

double triangleArea(const Vec3d& a, const Vec3d& b, const Vec3d& c) { return 0.5 * length(cross(sub(b, a), sub(c, a))); }

Vec3d toVec3d(const Vec3f& v) { return {v[0], v[1], v[2]}; }

// Area-weighted vertex normals (the unnormalised face normal's length is twice the area), for meshes
// that carry none. A vertex only on zero-area faces keeps a zero normal; roots never land there.
std::vector<Vec3d> vertexNormals(const TriangleMesh& mesh) {
  std::vector<Vec3d> normals(mesh.vertexCount(), Vec3d{0, 0, 0});
  for (const Triangle& t : mesh.triangles) {
    const Vec3d a = toVec3d(mesh.positions[t[0]]), b = toVec3d(mesh.positions[t[1]]), c = toVec3d(mesh.positions[t[2]]);
    const Vec3d n = cross(sub(b, a), sub(c, a));
    for (std::uint32_t v : t) normals[v] = add(normals[v], n);
  }
  for (Vec3d& n : normals) n = normalized(n, {0, 0, 0});
  return normals;
}

// A per-vertex attribute of a glTF input as floats (`components` per vertex), its values checked.
Result<std::vector<float>> vertexValues(const TriangleMesh& mesh, const std::string& name, int minComponents,
                                        const std::string& meshName, const std::string& field, int& components) {
  const auto it = std::find_if(mesh.extraAttributes.begin(), mesh.extraAttributes.end(),
                               [&](const glb::Attribute& a) { return a.name == name; });
  if (it == mesh.extraAttributes.end()) {
    return invalidInput("has no vertex attribute " + name + " (" + field +
                            " asks for it; only glTF inputs carry named vertex attributes and colours)",
                        {meshName, field});
  }
  if (it->components < minComponents || it->count() != mesh.vertexCount()) {
    return invalidInput("vertex attribute " + name + " has " + std::to_string(it->components) + " components for " +
                            std::to_string(it->count()) + " vertices (" + std::to_string(minComponents) +
                            " or more for each of " + std::to_string(mesh.vertexCount()) + " needed)",
                        {meshName, name});
  }
  components = it->components;
  std::vector<float> values = it->toFloats();
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i]) || values[i] < 0) {
      return invalidInput(name + " is " + std::to_string(values[i]) + " (a scale must be finite and >= 0)",
                          {meshName, "vertex " + std::to_string(i / std::size_t(components))});
    }
  }
  return values;
}

// Texture lookups at TEXCOORD_0 with bilinear filtering and glTF's default repeat wrap; v = 0 is
// the image's top row (glTF's convention, and readImage's row order).
struct Texture {
  Image image;
  bool srgb = false;  // 8/16-bit colour images are sRGB-encoded by convention; floats are linear

  double texel(int x, int y, int c) const {
    x = ((x % image.width) + image.width) % image.width;
    y = ((y % image.height) + image.height) % image.height;
    return image.at(x, y, std::min(c, image.channels - 1));
  }
  double sample(double u, double v, int c) const {
    const double x = u * image.width - 0.5, y = v * image.height - 0.5;
    const double x0 = std::floor(x), y0 = std::floor(y), fx = x - x0, fy = y - y0;
    const int ix = int(std::fmod(x0, image.width)), iy = int(std::fmod(y0, image.height));
    return (1 - fy) * ((1 - fx) * texel(ix, iy, c) + fx * texel(ix + 1, iy, c)) +
           fy * ((1 - fx) * texel(ix, iy + 1, c) + fx * texel(ix + 1, iy + 1, c));
  }
};

double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

Result<Texture> readTexture(const std::string& path, const TriangleMesh& mesh, const std::string& meshName,
                            const std::string& field) {
  if (mesh.texcoords.empty()) {
    return invalidInput("has no texture coordinates (TEXCOORD_0), which " + field + " needs to sample " + path,
                        {meshName, field});
  }
  BAKE_ASSIGN_OR_RETURN(Image image, readImage(path));
  if (image.width < 1 || image.height < 1 || image.channels < 1) return invalidInput("is an empty image", {path, ""});
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    if (!std::isfinite(image.pixels[i]) || image.pixels[i] < 0) {
      const std::size_t texel = i / std::size_t(image.channels);
      return invalidInput("value " + std::to_string(image.pixels[i]) + " is not finite and >= 0",
                          {path, "pixel (" + std::to_string(texel % std::size_t(image.width)) + ", " +
                                     std::to_string(texel / std::size_t(image.width)) + ")"});
    }
  }
  Texture texture;
  texture.srgb = image.sourceType == PixelType::U8 || image.sourceType == PixelType::U16;
  texture.image = std::move(image);
  return texture;
}

// Where and what the scale factors of one root come from, resolved against the mesh once.
struct Scales {
  std::vector<float> lengthValues, radiusValues, colourValues;
  int colourComponents = 0;
  std::optional<Texture> lengthTexture, colourTexture;
};

double interpolate(const std::vector<float>& values, int components, int c, const Triangle& t, const Vec3d& w) {
  return w[0] * values[t[0] * std::size_t(components) + c] + w[1] * values[t[1] * std::size_t(components) + c] +
         w[2] * values[t[2] * std::size_t(components) + c];
}

glb::Mesh toGlbMesh(const TriangleMesh& mesh, const std::vector<Vec3d>& normals, const std::string& name) {
  std::vector<float> positions, normalFloats;
  positions.reserve(mesh.vertexCount() * 3);
  normalFloats.reserve(mesh.vertexCount() * 3);
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
    for (int c = 0; c < 3; ++c) positions.push_back(mesh.positions[v][c]);
    // A vertex on zero-area faces only has no normal; glTF wants unit normals, so give it +z.
    const Vec3d n = normalized(normals[v], {0, 0, 1});
    for (int c = 0; c < 3; ++c) normalFloats.push_back(float(n[c]));
  }
  glb::Primitive primitive;
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, positions));
  primitive.attributes.push_back(glb::Attribute::fromFloats("NORMAL", 3, normalFloats));
  for (const Triangle& t : mesh.triangles) primitive.indices.insert(primitive.indices.end(), t.begin(), t.end());
  glb::Mesh out;
  out.name = name;
  out.primitives.push_back(std::move(primitive));
  return out;
}

}  // namespace

Status checkGrowSettings(const GrowSettings& s) {
  if (s.mesh.empty()) return badSetting("mesh", "is missing (the mesh to grow strokes on)");
  if (s.count < 1 || s.count > kMaxGeneratedStrokes) {
    return badSetting("count", "must be within 1 .. " + std::to_string(kMaxGeneratedStrokes) + ", not " + std::to_string(s.count));
  }
  if (!(s.length > 0) || !std::isfinite(s.length)) return badSetting("length", "must be a finite number > 0");
  if (!(s.radius > 0) || !std::isfinite(s.radius)) return badSetting("radius", "must be a finite number > 0");
  if (!(s.tipRadius > 0) || !(s.tipRadius <= 100)) return badSetting("tipRadius", "must be within (0, 100]");
  if (!(s.bend >= 0) || !(s.bend <= 1)) return badSetting("bend", "must be within [0, 1]");
  if (s.bend > 0 && !(length(s.bendDirection) > 1e-12 && std::isfinite(length(s.bendDirection)))) {
    return badSetting("bendDirection", "must be a finite, non-zero vector when bend > 0");
  }
  if (s.pointsPerStroke < 2 || s.pointsPerStroke > 64) return badSetting("pointsPerStroke", "must be within 2 .. 64");
  if (!isUnit(s.rootColour)) return badSetting("rootColour", "every component must be within [0, 1]");
  if (!isUnit(s.tipColour)) return badSetting("tipColour", "every component must be within [0, 1]");
  // Below 1 so that a jittered direction never leaves the root's side of the surface (d . n >= 1 -
  // jitter) and a jittered length stays positive.
  if (!(s.jitter >= 0) || !(s.jitter < 1)) return badSetting("jitter", "must be within [0, 1)");
  if (s.style >= format::paintstrokes::kMaxStyles) {
    return badSetting("style", "must be a style index below " + std::to_string(format::paintstrokes::kMaxStyles));
  }
  BAKE_RETURN_IF_ERROR(parseSource(s.lengthFrom, "lengthFrom", true).status());
  BAKE_RETURN_IF_ERROR(parseSource(s.colourFrom, "colourFrom", false).status());
  return Status::ok();
}

Result<StrokeSet> growOnMesh(const GrowSettings& settings, const Budgets& budgets, glb::Mesh* grownOn) {
  BAKE_RETURN_IF_ERROR(checkGrowSettings(settings));
  BAKE_ASSIGN_OR_RETURN(const Source lengthSource, parseSource(settings.lengthFrom, "lengthFrom", true));
  BAKE_ASSIGN_OR_RETURN(const Source colourSource, parseSource(settings.colourFrom, "colourFrom", false));
  const std::string& meshName = settings.mesh;
  const std::uint64_t points = std::uint64_t(settings.count) * std::uint64_t(settings.pointsPerStroke);
  if (points > budgets.controlPoints) {
    return invalidInput(std::to_string(points) + " control points (count x pointsPerStroke) exceed the budget of " +
                            std::to_string(budgets.controlPoints) + " (raise it with --budget control-points=N)",
                        {"", "count"});
  }

  // The reader checks the process-wide triangle budget against the header before parsing; the
  // caller's budgets are checked here as well (they may be tighter, e.g. in a library user).
  BAKE_ASSIGN_OR_RETURN(const TriangleMesh mesh, readMesh(settings.mesh));
  if (mesh.triangleCount() > budgets.triangles) {
    return invalidInput(std::to_string(mesh.triangleCount()) + " triangles exceed the budget of " +
                            std::to_string(budgets.triangles) + " (raise it with --budget triangles=N)",
                        {meshName, ""});
  }
  BAKE_RETURN_IF_ERROR(validateMesh(mesh, meshName));
  if (mesh.triangles.empty()) return invalidInput("has no triangles to grow strokes on", {meshName, ""});

  // Prefix sums of the triangle areas: the root distribution.
  std::vector<double> cumulative(mesh.triangleCount());
  double total = 0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    total += triangleArea(toVec3d(mesh.positions[tri[0]]), toVec3d(mesh.positions[tri[1]]), toVec3d(mesh.positions[tri[2]]));
    cumulative[t] = total;
  }
  if (!(total > 0) || !std::isfinite(total)) {
    return invalidInput("has no surface area to grow strokes on (every triangle is degenerate)", {meshName, ""});
  }

  std::vector<Vec3d> normals;
  if (mesh.normals.empty()) {
    normals = vertexNormals(mesh);
  } else {
    for (const Vec3f& n : mesh.normals) normals.push_back(toVec3d(n));
  }

  Scales scales;
  int lengthComponents = 1, radiusComponents = 1;
  if (lengthSource.kind == Source::Kind::Vertex) {
    BAKE_ASSIGN_OR_RETURN(scales.lengthValues,
                          vertexValues(mesh, lengthSource.argument, 1, meshName, "lengthFrom", lengthComponents));
  } else if (lengthSource.kind == Source::Kind::Texture) {
    BAKE_ASSIGN_OR_RETURN(scales.lengthTexture, readTexture(lengthSource.argument, mesh, meshName, "lengthFrom"));
  }
  if (colourSource.kind == Source::Kind::Vertex) {
    BAKE_ASSIGN_OR_RETURN(scales.colourValues,
                          vertexValues(mesh, colourSource.argument, 3, meshName, "colourFrom", scales.colourComponents));
  } else if (colourSource.kind == Source::Kind::Texture) {
    BAKE_ASSIGN_OR_RETURN(scales.colourTexture, readTexture(colourSource.argument, mesh, meshName, "colourFrom"));
  }
  // A glTF _RADIUS attribute, when the mesh has one, scales the radius (no setting needed: it is
  // there only for this).
  const bool hasRadius = std::any_of(mesh.extraAttributes.begin(), mesh.extraAttributes.end(),
                                     [](const glb::Attribute& a) { return a.name == "_RADIUS"; });
  if (hasRadius) {
    BAKE_ASSIGN_OR_RETURN(scales.radiusValues, vertexValues(mesh, "_RADIUS", 1, meshName, "_RADIUS", radiusComponents));
  }

  StrokeSet set;
  set.styles.resize(settings.style + 1);  // a complete set on its own; runGenerator keeps only the strokes
  set.strokes.reserve(settings.count);
  Random random(settings.seed);
  const int n = settings.pointsPerStroke;
  for (std::size_t i = 0; i < settings.count; ++i) {
    // Draws, always all of them and in this order, whatever the options: a root's strokes do not
    // change when another option (jitter, bend) does.
    const double pick = random.uniform() * total;
    const double r1 = random.uniform(), r2 = random.uniform();
    const Vec3d tilt = random.inBall();
    const double stretch = random.uniform(-1, 1);

    const std::size_t t = std::min<std::size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin(), cumulative.size() - 1);
    const Triangle& tri = mesh.triangles[t];
    const double s = std::sqrt(r1);
    const Vec3d w{1 - s, s * (1 - r2), s * r2};
    const Vec3d a = toVec3d(mesh.positions[tri[0]]), b = toVec3d(mesh.positions[tri[1]]), c = toVec3d(mesh.positions[tri[2]]);
    const Vec3d root = add(add(scale(a, w[0]), scale(b, w[1])), scale(c, w[2]));
    const Vec3d faceNormal = normalized(cross(sub(b, a), sub(c, a)), {0, 0, 1});
    // Interpolated normals can cancel (a crease with opposite normals); the face's normal then.
    const Vec3d normal = normalized(
        add(add(scale(normals[tri[0]], w[0]), scale(normals[tri[1]], w[1])), scale(normals[tri[2]], w[2])), faceNormal);

    double lengthScale = 1, radiusScale = 1;
    Vec3d colourScale{1, 1, 1};
    const bool needUv = scales.lengthTexture || scales.colourTexture;
    const Vec3d uv = needUv ? Vec3d{w[0] * mesh.texcoords[tri[0]][0] + w[1] * mesh.texcoords[tri[1]][0] + w[2] * mesh.texcoords[tri[2]][0],
                                    w[0] * mesh.texcoords[tri[0]][1] + w[1] * mesh.texcoords[tri[1]][1] + w[2] * mesh.texcoords[tri[2]][1], 0}
                            : Vec3d{0, 0, 0};
    if (!scales.lengthValues.empty()) lengthScale = interpolate(scales.lengthValues, lengthComponents, 0, tri, w);
    if (scales.lengthTexture) lengthScale = scales.lengthTexture->sample(uv[0], uv[1], 0);
    if (!scales.radiusValues.empty()) radiusScale = interpolate(scales.radiusValues, radiusComponents, 0, tri, w);
    if (!scales.colourValues.empty()) {
      for (int k = 0; k < 3; ++k) colourScale[k] = interpolate(scales.colourValues, scales.colourComponents, k, tri, w);
    }
    if (scales.colourTexture) {
      for (int k = 0; k < 3; ++k) {
        const double v = scales.colourTexture->sample(uv[0], uv[1], k);
        colourScale[k] = scales.colourTexture->srgb ? srgbToLinear(std::min(v, 1.0)) : v;
      }
    }
    // A zero scale (a bald patch painted black) grows nothing there.
    const double strokeLength = settings.length * lengthScale * (1 + settings.jitter * stretch);
    if (!(strokeLength > settings.length * 1e-9) || !(radiusScale > 0)) continue;

    const Vec3d direction = normalized(add(normal, scale(tilt, settings.jitter)), normal);
    const Vec3d bend = scale(normalized(settings.bendDirection, {0, 0, 0}), settings.bend);
    Stroke stroke;
    stroke.style = settings.style;
    stroke.points.resize(std::size_t(n));
    for (int k = 0; k < n; ++k) {
      const double u = double(k) / (n - 1);
      StrokePoint& p = stroke.points[std::size_t(k)];
      p.position = add(root, scale(add(scale(direction, u), scale(bend, u * u)), strokeLength));
      p.radius = settings.radius * radiusScale * (1 + (settings.tipRadius - 1) * u);
      for (int ch = 0; ch < 3; ++ch) {
        p.colour[ch] = std::clamp(
            (settings.rootColour[ch] + (settings.tipColour[ch] - settings.rootColour[ch]) * u) * colourScale[ch], 0.0, 1.0);
      }
      p.globalNormal = normal;
      p.depth = 1 - u;
    }
    set.strokes.push_back(std::move(stroke));
  }
  if (grownOn) *grownOn = toGlbMesh(mesh, normals, std::filesystem::path(meshName).stem().string());
  return set;
}

}  // namespace bake::paintstrokes
