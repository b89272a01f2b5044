// Writes the BAKE_grooves package (formats/grooves.md) of a scene and its grid (seed 000 §4.1-§4.2).
//
// Geometry is stored cell-local in fp32 (never fp16): each primitive and record keeps the integer
// column and row of its anchor cell (the cell holding its start point, or its point) and every
// position as the offset from that cell's corner, computed in double before the one rounding to
// float. The error is then at most half an fp32 ulp of a cell-sized offset, whatever the domain's
// size, and a reader rebuilds positions relative to any cell with exact integer cell offsets. Arcs
// stay arcs (centre, radius, start angle, sweep). Arrays are std430 records (bake_formats/grooves.h)
// in bufferViews starting at multiples of 256 bytes, so each uploads as it is.
#include "grooves/package/package.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/parallel.h"

namespace bake::grooves {
namespace {

using nlohmann::json;
namespace fmt = format::grooves;

// The cell frame of the grid: anchors and cell-local offsets.
struct CellFrame {
  Vec2 origin, size;

  void anchorOf(Vec2 x, std::int32_t anchor[2]) const {
    auto index = [](double t) { return std::int32_t(std::clamp(std::floor(t), -2147483647.0, 2147483647.0)); };
    anchor[0] = index((x.u - origin.u) / size.u);
    anchor[1] = index((x.v - origin.v) / size.v);
  }
  void local(Vec2 x, const std::int32_t anchor[2], float* out) const {
    out[0] = float(x.u - (origin.u + double(anchor[0]) * size.u));
    out[1] = float(x.v - (origin.v + double(anchor[1]) * size.v));
  }
};

// An array of `count` items made by make(i), written straight into the blob in parallel.
template <class T, class Make>
glb::Blob packedBlob(std::size_t count, unsigned threads, Make make) {
  glb::Blob blob;
  blob.alignment = fmt::kBufferAlignment;
  blob.bytes.assign(std::max<std::size_t>(1, count) * sizeof(T), 0);  // one zeroed item when empty
  std::uint8_t* bytes = blob.bytes.data();
  parallelFor(count, threads, [&](std::size_t i) {
    const T item = make(i);
    std::memcpy(bytes + i * sizeof(T), &item, sizeof(T));
  }, 4096);
  return blob;
}

template <class T>
glb::Blob blobOf(const std::vector<T>& items) {
  return glb::blobOf(items, fmt::kBufferAlignment);
}

std::uint32_t primitiveFlags(const Primitive& p) {
  std::uint32_t flags = 0;
  if (p.kind == Primitive::Kind::Arc) flags |= fmt::kPrimitiveArc;
  if (p.cornerAtStart) flags |= fmt::kPrimitiveCornerAtStart;
  if (p.endAtStart) flags |= fmt::kPrimitiveEndAtStart;
  if (p.endAtEnd) flags |= fmt::kPrimitiveEndAtEnd;
  return flags;
}

fmt::Primitive packPrimitive(const GrooveScene& scene, std::size_t index, const CellFrame& frame) {
  const Primitive& p = scene.primitives[index];
  const PrimitiveJoints joints = jointsOf(scene, index);
  fmt::Primitive out{};
  frame.anchorOf(p.a, out.anchor);
  out.groove = static_cast<std::uint32_t>(p.groove);
  out.flags = primitiveFlags(p);
  frame.local(p.a, out.anchor, out.ends);
  frame.local(p.b, out.anchor, out.ends + 2);
  if (p.kind == Primitive::Kind::Arc) {
    frame.local(p.centre, out.anchor, out.arc);
    out.arc[2] = float(p.radius);
    out.arc[3] = float(p.startAngle);
    out.measure[0] = float(p.sweep);
  }
  out.measure[1] = float(p.arcStart);
  out.measure[2] = float(p.length);
  frame.local(joints.start.point, out.anchor, out.jointPoints);
  frame.local(joints.end.point, out.anchor, out.jointPoints + 2);
  out.jointNormals[0] = float(joints.start.normal.u);
  out.jointNormals[1] = float(joints.start.normal.v);
  out.jointNormals[2] = float(joints.end.normal.u);
  out.jointNormals[3] = float(joints.end.normal.v);
  return out;
}

fmt::Record packRecord(const SpecialRecord& r, const CellFrame& frame) {
  fmt::Record out{};
  frame.anchorOf(r.point, out.anchor);
  out.info[0] = static_cast<std::uint32_t>(r.kind);
  out.info[1] = r.primitive[0];
  out.info[2] = r.primitive[1];
  frame.local(r.point, out.anchor, out.point);
  frame.local(r.lower, out.anchor, out.box);
  frame.local(r.upper, out.anchor, out.box + 2);
  return out;
}

std::uint32_t perturbationKind(const Perturbation& p) {
  switch (p.kind) {
    case Perturbation::Kind::Scale: return fmt::kPerturbationScale;
    case Perturbation::Kind::Offset: return fmt::kPerturbationOffset;
    default: return fmt::kPerturbationNone;
  }
}

fmt::Groove packGroove(const Groove& g) {
  fmt::Groove out{};
  out.indices[0] = static_cast<std::uint32_t>(g.profile);
  out.indices[1] = static_cast<std::uint32_t>(g.material);
  out.indices[2] = static_cast<std::uint32_t>(g.firstPrimitive);
  out.indices[3] = static_cast<std::uint32_t>(g.primitiveCount);
  out.kind[0] = g.closed ? fmt::kGrooveClosed : 0;
  out.kind[1] = perturbationKind(g.perturbation);
  out.perturbation[0] = float(g.perturbation.amplitude);
  out.perturbation[1] = float(g.perturbation.wavelength);
  out.perturbation[2] = float(g.perturbation.phase);
  out.bounds[0] = float(g.wmax);
  out.bounds[1] = float(g.hmax);
  out.bounds[2] = float(g.dmax);
  return out;
}

void packProfiles(const GrooveScene& scene, std::vector<fmt::Profile>& profiles, std::vector<float>& points) {
  for (const Profile& profile : scene.profiles) {
    fmt::Profile out{};
    out.points[0] = static_cast<std::uint32_t>(points.size() / 2);
    out.points[1] = static_cast<std::uint32_t>(profile.points.size());
    out.points[2] = profile.symmetric ? 1 : 0;
    out.bounds[0] = float(profile.wmax);
    out.bounds[1] = float(profile.hmax);
    out.bounds[2] = float(profile.dmax);
    for (const Vec2& p : profile.points) {
      points.push_back(float(p.u));
      points.push_back(float(p.v));
    }
    profiles.push_back(out);
  }
}

fmt::Material packMaterial(const Material& m) {
  fmt::Material out{};
  for (int c = 0; c < 3; ++c) {
    out.albedo[c] = float(m.albedo[c]);
    out.specular[c] = float(m.specular[c]);
    out.mirror[c] = m.hasMirror ? float(m.mirror[c]) : 0.0f;
  }
  out.albedo[3] = float(m.shininess);
  out.specular[3] = m.hasMirror ? 1.0f : 0.0f;
  return out;
}

// The preview plane: the domain as a quad in the glTF XY plane (x = u, y = v, z = 0), facing +z.
glb::Mesh previewPlane(const GrooveScene& scene) {
  const float U = float(scene.domain[0]), V = float(scene.domain[1]);
  const std::vector<float> positions = {0, 0, 0, U, 0, 0, U, V, 0, 0, V, 0};
  const std::vector<float> normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  const std::vector<float> texcoords = {0, 0, 1, 0, 1, 1, 0, 1};
  glb::Primitive primitive;
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, positions));
  primitive.attributes.push_back(glb::Attribute::fromFloats("NORMAL", 3, normals));
  primitive.attributes.push_back(glb::Attribute::fromFloats("TEXCOORD_0", 2, texcoords));
  primitive.indices = {0, 1, 2, 0, 2, 3};
  primitive.material = 0;
  glb::Mesh mesh;
  mesh.name = "groove domain";
  mesh.primitives.push_back(std::move(primitive));
  return mesh;
}

std::vector<fmt::FarClass> packFarClasses(const FarLevel& far) {
  std::vector<fmt::FarClass> out;
  for (const FarClass& c : far.classes) {
    fmt::FarClass packed{};
    packed.info[0] = c.profile;
    packed.info[1] = c.material;
    packed.info[2] = c.representative;
    packed.direction[0] = float(c.direction.u);
    packed.direction[1] = float(c.direction.v);
    packed.direction[2] = float(c.halfWidth);
    out.push_back(packed);
  }
  return out;
}

json namesOf(const auto& items) {
  json names = json::array();
  for (const auto& item : items) names.push_back(item.name);
  return names;
}

}  // namespace

Result<glb::Package> buildGroovePackage(const GrooveScene& scene, const GrooveGrid& grid, unsigned threads) {
  if (grid.cellStart.size() != grid.cellCount() + 1 || grid.recordStart.size() != grid.cellCount() + 1)
    return internalError("grooves package: the grid's cell starts do not match its cell count");
  const CellFrame frame{grid.origin, grid.cellSize};
  threads = resolveThreadCount(threads);
  std::vector<fmt::Groove> grooves;
  for (const Groove& g : scene.grooves) grooves.push_back(packGroove(g));
  std::vector<fmt::Profile> profiles;
  std::vector<float> points;
  packProfiles(scene, profiles, points);
  std::vector<fmt::Material> materials;
  for (const Material& m : scene.materials) materials.push_back(packMaterial(m));

  glb::Package package;
  // Required: a preview plane whose grooves live only in the extension's arrays: a tool that does not know
  // BAKE_grooves must refuse the file rather than keep a plain plane (docs/architecture.md, "Required
  // extensions").
  package.extensionsRequired = {fmt::kExtension};
  // Blob i is bufferView i, in the order of fmt::kArrayKeys.
  package.blobs.reserve(fmt::kArrayCount);
  package.blobs.push_back(blobOf(grid.cellStart));
  package.blobs.push_back(blobOf(grid.primitiveRefs));
  package.blobs.push_back(blobOf(grid.recordStart));
  package.blobs.push_back(blobOf(grid.recordRefs));
  package.blobs.push_back(packedBlob<fmt::Record>(grid.records.size(), threads,
                                                  [&](std::size_t r) { return packRecord(grid.records[r], frame); }));
  package.blobs.push_back(packedBlob<fmt::Primitive>(scene.primitives.size(), threads,
                                                     [&](std::size_t i) { return packPrimitive(scene, i, frame); }));
  package.blobs.push_back(blobOf(grooves));
  package.blobs.push_back(blobOf(profiles));
  package.blobs.push_back(blobOf(points));
  package.blobs.push_back(blobOf(materials));
  const std::vector<fmt::FarClass> farClasses = packFarClasses(grid.far);
  package.blobs.push_back(blobOf(farClasses));
  package.blobs.push_back(blobOf(grid.far.table));
  json views = json::object();
  for (std::size_t k = 0; k < fmt::kArrayCount; ++k) views[fmt::kArrayKeys[k]] = k;
  json extension = {
      {"version", fmt::kVersion},
      {"domain", {scene.domain[0], scene.domain[1]}},
      {"wrap", scene.wrapRepeat ? fmt::kWrapRepeat : fmt::kWrapNone},
      {"grid", {{"cells", {grid.cells[0], grid.cells[1]}},
                {"cellSize", {grid.cellSize.u, grid.cellSize.v}},
                {"origin", {grid.origin.u, grid.origin.v}}}},
      {"wmax", scene.wmax},
      {"hmax", scene.hmax},
      {"dmax", scene.dmax},
      {"baseMaterial", scene.baseMaterial},
      {fmt::kCounts, {{"cells", grid.cellCount()},
                  {"primitiveRefs", grid.primitiveRefs.size()},
                  {"recordRefs", grid.recordRefs.size()},
                  {"records", grid.records.size()},
                  {"primitives", scene.primitives.size()},
                  {"grooves", grooves.size()},
                  {"profiles", profiles.size()},
                  {"profilePoints", points.size() / 2},
                  {"materials", materials.size()},
                  {fmt::kFarClasses, farClasses.size()},
                  {fmt::kFarTable, grid.far.table.size()}}},
      {"strides", {{"records", sizeof(fmt::Record)},
                   {"primitives", sizeof(fmt::Primitive)},
                   {"grooves", sizeof(fmt::Groove)},
                   {"profiles", sizeof(fmt::Profile)},
                   {"profilePoints", fmt::kProfilePointSize},
                   {"materials", sizeof(fmt::Material)},
                   {fmt::kFarClasses, sizeof(fmt::FarClass)},
                   {fmt::kFarTable, fmt::kFarTableEntrySize}}},
      {fmt::kBufferViews, views},
      {fmt::kFar, {{"cells", {grid.far.cells[0], grid.far.cells[1]}}, {"cellSize", {grid.far.cellSize.u, grid.far.cellSize.v}}}},
      {"profileNames", namesOf(scene.profiles)},
      {"materialNames", namesOf(scene.materials)}};
  if (!scene.units.empty()) extension["units"] = scene.units;

  const Material& base = scene.materials.at(scene.baseMaterial);
  package.materials.push_back({{"name", "grooves"},
                               {"pbrMetallicRoughness", {{"baseColorFactor", {base.albedo[0], base.albedo[1], base.albedo[2], 1.0}},
                                                         {"metallicFactor", 0.0},
                                                         {"roughnessFactor", 0.5}}},
                               {"extensions", {{fmt::kExtension, extension}}}});
  package.meshes.push_back(previewPlane(scene));
  return package;
}

}  // namespace bake::grooves
