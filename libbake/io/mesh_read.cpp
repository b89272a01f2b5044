// Reading triangle meshes (io/mesh.h). OBJ, OFF, PLY and STL are parsed by OpenMesh's reader
// modules, but into our own importer that records a plain polygon soup: OpenMesh's mesh kernel would
// drop faces that break manifoldness, silently, and a baker must see every face it was given.
//
// OpenMesh's parsers report almost nothing about malformed input (a bad number just desynchronises the
// stream, a PLY header without end_header even hangs), so each text format gets a light pre-scan that
// stops at the first malformed line and names it (io/mesh_scan.h; one mesh_scan_<format>.cpp per
// format). Binary files get size checks before and a count comparison after parsing; validateMesh then
// catches what slips through (NaN coordinates, bad indices). glTF/GLB goes to io/gltf.h. Finally
// polygons are fan-triangulated and, on request, welded.
//
// Decisions worth knowing:
// - Faces with fewer than three vertices in the file (OFF "0", "2 4 5", OBJ "f 1 2", PLY lists of
//   length < 3) are errors naming the line: none of these formats defines them as polygons.
// - Faces that list a vertex twice are cleaned: repeats are removed (as OpenMesh's OBJ reader does)
//   and a face left with fewer than three distinct vertices is dropped and counted in
//   MeshReadStats::degenerateFacesRemoved. Zero-area faces with distinct vertices are kept.
// - OBJ attributes belong to face corners. A position used with different normals or texture
//   coordinates becomes several vertices (MeshReadStats::verticesSplit); an attribute given for only
//   some corners is dropped (MeshReadStats::incompleteAttributesDropped).
// - STL has no shared vertices; OpenMesh's STL reader joins corners at equal positions (an exact weld)
//   and skips triangles that collapse by it, which we count as removed degenerate faces.
// - Element names in errors: "line N" (1-based) for text files, "face N" / "triangle N" / "vertex N"
//   (0-based, in file order) otherwise.
#include "bake/io/mesh.h"

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/Options.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <optional>
#include <streambuf>
#include <string_view>

#include "bake/core/atomic_file.h"
#include "bake/core/input_file.h"
#include "bake/core/limits.h"
#include "core/path.h"
#include "core/private_copy.h"
#include "io/gltf.h"
#include "io/mesh_place.h"
#include "io/mesh_scan.h"
#include "mesh/weld.h"

namespace bake {
namespace fs = std::filesystem;

namespace {

using meshscan::isBinaryStl;
using meshscan::Prescan;
using meshscan::prescanObj;
using meshscan::prescanOff;
using meshscan::prescanPly;
using meshscan::prescanStl;

// ---------------------------------------------------------------------------------------------------
// The importer OpenMesh's readers feed: a polygon soup with per-corner attributes.

struct Corner {
  std::uint32_t vertex = 0;
  bool hasNormal = false;
  bool hasTexcoord = false;
  Vec3f normal{};
  Vec2f texcoord{};
};

struct PolygonSoup {
  std::vector<Vec3f> positions;
  std::vector<Vec3d> precisePositions;     // the same in double, as precise as the parser gave them
  std::vector<Corner> corners;
  std::vector<std::size_t> polygonStarts;  // into corners; a polygon ends where the next starts
  std::size_t facesOffered = 0;            // every face the reader passed, kept or not
  std::size_t degenerateFaces = 0;         // fewer than three distinct vertices: dropped
  std::vector<Corner> vertexAttributes;    // per-vertex formats: attributes of every vertex
};

// Where the reader's normals and texture coordinates belong. OBJ sets them per face corner just before
// adding the face; OFF and PLY set them once per vertex before any face. (A corner-scope face that
// OpenMesh skips, having fewer than 3 distinct vertices, leaves its attributes pending for the next
// face; they only matter if that face uses the same vertex without giving the attribute itself.)
enum class AttributeScope { PerVertex, PerCorner };

class SoupImporter final : public OpenMesh::IO::BaseImporter {
 public:
  using VertexHandle = OpenMesh::VertexHandle;
  using FaceHandle = OpenMesh::FaceHandle;
  using HalfedgeHandle = OpenMesh::HalfedgeHandle;
  using EdgeHandle = OpenMesh::EdgeHandle;

  explicit SoupImporter(AttributeScope scope) : scope_(scope) {}

  PolygonSoup& soup() {
    if (scope_ == AttributeScope::PerVertex) soup_.vertexAttributes = vertexAttributes_;
    return soup_;
  }
  // The first face that referred to a vertex that does not exist, if any.
  const std::optional<std::string>& problem() const { return problem_; }

  VertexHandle add_vertex(const OpenMesh::Vec3f& point) override {
    return addVertex({point[0], point[1], point[2]}, {point[0], point[1], point[2]});
  }
  VertexHandle add_vertex(const OpenMesh::Vec3d& point) override {
    return addVertex({float(point[0]), float(point[1]), float(point[2])}, {point[0], point[1], point[2]});
  }
  VertexHandle add_vertex() override { return addVertex({}, {}); }
  void set_point(VertexHandle vertex, const OpenMesh::Vec3f& point) override {
    if (!isValid(vertex)) return;
    soup_.positions[vertex.idx()] = {point[0], point[1], point[2]};
    soup_.precisePositions[vertex.idx()] = {point[0], point[1], point[2]};
  }

  void set_normal(VertexHandle vertex, const OpenMesh::Vec3f& normal) override {
    if (Corner* attributes = attributesFor(vertex)) {
      attributes->hasNormal = true;
      attributes->normal = {normal[0], normal[1], normal[2]};
    }
  }
  void set_normal(VertexHandle vertex, const OpenMesh::Vec3d& normal) override {
    set_normal(vertex, OpenMesh::Vec3f(float(normal[0]), float(normal[1]), float(normal[2])));
  }
  void set_texcoord(VertexHandle vertex, const OpenMesh::Vec2f& texcoord) override {
    if (Corner* attributes = attributesFor(vertex)) {
      attributes->hasTexcoord = true;
      attributes->texcoord = {texcoord[0], texcoord[1]};
    }
  }

  VertexHandle addVertex(const Vec3f& point, const Vec3d& precise) {
    soup_.positions.push_back(point);
    soup_.precisePositions.push_back(precise);
    vertexAttributes_.emplace_back();
    return VertexHandle(int(soup_.positions.size() - 1));
  }

  FaceHandle add_face(const VHandles& indices) override {
    const std::size_t faceNumber = soup_.facesOffered++;
    std::vector<VertexHandle> distinct;
    for (VertexHandle vertex : indices) {
      if (!isValid(vertex)) {
        if (!problem_) {
          problem_ = "face " + std::to_string(faceNumber) + " refers to vertex " +
                     std::to_string(vertex.idx()) + ", but there are " +
                     std::to_string(soup_.positions.size()) + " vertices";
        }
        pending_.clear();
        return FaceHandle();
      }
      if (std::find(distinct.begin(), distinct.end(), vertex) == distinct.end()) distinct.push_back(vertex);
    }
    if (distinct.size() < 3) {
      ++soup_.degenerateFaces;
      pending_.clear();
      return FaceHandle();
    }
    soup_.polygonStarts.push_back(soup_.corners.size());
    for (VertexHandle vertex : distinct) soup_.corners.push_back(cornerFor(vertex));
    pending_.clear();
    return FaceHandle(int(soup_.polygonStarts.size() - 1));
  }

  size_t n_vertices() const override { return soup_.positions.size(); }
  size_t n_faces() const override { return soup_.polygonStarts.size(); }
  size_t n_edges() const override { return 0; }

  // Everything below is either half-edge plumbing (only the .om reader uses it) or data we do not
  // keep: colours, face normals, status bits, 3D texture coordinates, materials.
  HalfedgeHandle add_edge(VertexHandle, VertexHandle) override { return HalfedgeHandle(); }
  FaceHandle add_face(HalfedgeHandle) override { return FaceHandle(); }
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<OpenMesh::Vec2f>&) override {}
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(FaceHandle, int) override {}
  void set_halfedge(VertexHandle, HalfedgeHandle) override {}
  void set_color(VertexHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec4f&) override {}
  void set_status(VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(HalfedgeHandle, HalfedgeHandle) override {}
  void set_face(HalfedgeHandle, FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec4f&) override {}
  void set_status(FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}

 private:
  bool isValid(VertexHandle vertex) const {
    return vertex.idx() >= 0 && std::size_t(vertex.idx()) < soup_.positions.size();
  }

  // Per-vertex scope: the vertex's own slot. Per-corner scope: a slot for the face being assembled.
  Corner* attributesFor(VertexHandle vertex) {
    if (!isValid(vertex)) return nullptr;
    if (scope_ == AttributeScope::PerVertex) return &vertexAttributes_[vertex.idx()];
    for (Corner& corner : pending_) {
      if (corner.vertex == std::uint32_t(vertex.idx())) return &corner;
    }
    pending_.push_back({std::uint32_t(vertex.idx())});
    return &pending_.back();
  }

  Corner cornerFor(VertexHandle vertex) const {
    Corner corner;
    if (scope_ == AttributeScope::PerVertex) {
      corner = vertexAttributes_[vertex.idx()];
    } else {
      for (const Corner& pending : pending_) {
        if (pending.vertex == std::uint32_t(vertex.idx())) corner = pending;
      }
    }
    corner.vertex = std::uint32_t(vertex.idx());
    return corner;
  }

  AttributeScope scope_;
  PolygonSoup soup_;
  std::vector<Corner> vertexAttributes_;  // per-vertex scope
  std::vector<Corner> pending_;           // per-corner scope: attributes for the next face
  std::optional<std::string> problem_;
};

// ---------------------------------------------------------------------------------------------------
// Calling OpenMesh.

// OpenMesh's log streams buffer partial lines; flushing while disabled discards them instead of letting
// them surface after re-enabling.
class QuietOpenMeshLogs {
 public:
  QuietOpenMeshLogs() {
    for (int i = 0; i < 3; ++i) {
      wasEnabled_[i] = stream(i).is_enabled();
      stream(i).disable();
    }
  }
  ~QuietOpenMeshLogs() {
    for (int i = 0; i < 3; ++i) {
      stream(i).flush();
      if (wasEnabled_[i]) stream(i).enable();
    }
  }
  QuietOpenMeshLogs(const QuietOpenMeshLogs&) = delete;
  QuietOpenMeshLogs& operator=(const QuietOpenMeshLogs&) = delete;

 private:
  static OpenMesh::mostream& stream(int i) { return i == 0 ? omerr() : i == 1 ? omlog() : omout(); }
  bool wasEnabled_[3] = {};
};

// The reader modules are process-wide singletons that keep per-file state, and the log switches are
// global: one OpenMesh read at a time.
std::mutex& openMeshMutex() {
  static std::mutex mutex;
  return mutex;
}

enum class MeshFormat { Obj, Off, Ply, Stl, Gltf, Unknown };

// The bytes already read, as the std::istream OpenMesh's readers take: the file is opened once
// (a FIFO could not be opened twice), and nothing is copied.
class MemoryStreamBuffer : public std::streambuf {
 public:
  explicit MemoryStreamBuffer(std::string_view bytes) {
    char* begin = const_cast<char*>(bytes.data());
    setg(begin, begin, begin + bytes.size());
  }

 protected:
  pos_type seekoff(off_type offset, std::ios_base::seekdir direction, std::ios_base::openmode) override {
    const off_type base = direction == std::ios_base::beg ? 0 : direction == std::ios_base::cur ? gptr() - eback() : egptr() - eback();
    return seekpos(pos_type(base + offset), std::ios_base::in);
  }
  pos_type seekpos(pos_type position, std::ios_base::openmode) override {
    if (off_type(position) < 0 || off_type(position) > egptr() - eback()) return pos_type(off_type(-1));
    setg(eback(), eback() + off_type(position), egptr());
    return position;
  }
};

// OpenMesh's OFF reader learns NOFF/COFF/STOFF from the file's header only when it opens the file by
// name, so OFF bytes go through a private temporary file (still one open of the input).
bool parseOffThroughFile(std::string_view bytes, OpenMesh::IO::Options options, SoupImporter& importer) {
  PrivateCopy copy;
  const std::span<const std::uint8_t> data(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  if (!copy.write(data, "mesh", ".off", "").isOk()) return false;
  std::lock_guard<std::mutex> lock(openMeshMutex());
  QuietOpenMeshLogs quiet;
  return OpenMesh::IO::IOManager().read(copy.path(), importer, options);
}

bool parseWithOpenMesh(std::string_view bytes, MeshFormat format, SoupImporter& importer) {
  OpenMesh::IO::Options options;
  options += OpenMesh::IO::Options::VertexNormal;
  options += OpenMesh::IO::Options::VertexTexCoord;
  if (format == MeshFormat::Off) return parseOffThroughFile(bytes, options, importer);
  // OpenMesh tells binary STL from ASCII by the file; a stream says so through the options.
  if (format == MeshFormat::Stl && isBinaryStl(bytes)) options += OpenMesh::IO::Options::Binary;
  const char* extension = format == MeshFormat::Obj ? "mesh.obj" : format == MeshFormat::Off ? "mesh.off"
                          : format == MeshFormat::Ply ? "mesh.ply" : "mesh.stl";
  MemoryStreamBuffer buffer(bytes);
  std::istream stream(&buffer);
  std::lock_guard<std::mutex> lock(openMeshMutex());
  QuietOpenMeshLogs quiet;
  return OpenMesh::IO::IOManager().read(stream, extension, importer, options);
}

// ---------------------------------------------------------------------------------------------------
// Polygon soup to triangle mesh.

template <class T>
bool sameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// Gives each corner the index of a vertex with its position and attributes: the first attribute
// combination seen for a position keeps the original vertex, later different ones get copies.
// `world` (when wanted): the double positions of mesh.positions, kept in step.
std::vector<std::uint32_t> assignCornerVertices(const PolygonSoup& soup, bool withNormals, bool withTexcoords,
                                                TriangleMesh& mesh, std::vector<Vec3d>* world,
                                                MeshReadStats& stats) {
  std::vector<std::uint32_t> cornerVertex(soup.corners.size());
  if (!withNormals && !withTexcoords) {
    for (std::size_t c = 0; c < soup.corners.size(); ++c) cornerVertex[c] = soup.corners[c].vertex;
    return cornerVertex;
  }
  // Unreferenced vertices keep the attributes a per-vertex format gave them, zeros otherwise.
  if (withNormals) mesh.normals.assign(mesh.positions.size(), Vec3f{});
  if (withTexcoords) mesh.texcoords.assign(mesh.positions.size(), Vec2f{});
  for (std::size_t v = 0; v < soup.vertexAttributes.size(); ++v) {
    if (withNormals && soup.vertexAttributes[v].hasNormal) mesh.normals[v] = soup.vertexAttributes[v].normal;
    if (withTexcoords && soup.vertexAttributes[v].hasTexcoord) {
      mesh.texcoords[v] = soup.vertexAttributes[v].texcoord;
    }
  }
  // Variants of each original vertex as a linked list through `variants`.
  struct Variant {
    std::uint32_t vertex;
    std::int64_t next;
  };
  std::vector<Variant> variants;
  std::vector<std::int64_t> firstVariant(soup.positions.size(), -1);
  auto matches = [&](std::uint32_t vertex, const Corner& corner) {
    return (!withNormals || sameBits(mesh.normals[vertex], corner.normal)) &&
           (!withTexcoords || sameBits(mesh.texcoords[vertex], corner.texcoord));
  };
  for (std::size_t c = 0; c < soup.corners.size(); ++c) {
    const Corner& corner = soup.corners[c];
    std::int64_t* link = &firstVariant[corner.vertex];
    while (*link >= 0 && !matches(variants[*link].vertex, corner)) link = &variants[*link].next;
    if (*link < 0) {
      const bool firstUse = firstVariant[corner.vertex] < 0;
      const std::uint32_t vertex = firstUse ? corner.vertex : std::uint32_t(mesh.positions.size());
      if (!firstUse) {
        mesh.positions.push_back(soup.positions[corner.vertex]);
        if (world) world->push_back(soup.precisePositions[corner.vertex]);
        if (withNormals) mesh.normals.emplace_back();
        if (withTexcoords) mesh.texcoords.emplace_back();
        ++stats.verticesSplit;
      }
      if (withNormals) mesh.normals[vertex] = corner.normal;
      if (withTexcoords) mesh.texcoords[vertex] = corner.texcoord;
      // `link` may point into `variants`, which push_back can move: no use of it after this.
      *link = std::int64_t(variants.size());
      variants.push_back({vertex, -1});
      cornerVertex[c] = vertex;
      continue;
    }
    cornerVertex[c] = variants[*link].vertex;
  }
  return cornerVertex;
}

// An attribute is kept only when every corner has it.
bool attributeIsComplete(const PolygonSoup& soup, bool Corner::*present, MeshReadStats& stats) {
  const std::size_t count = std::size_t(
      std::count_if(soup.corners.begin(), soup.corners.end(), [&](const Corner& c) { return c.*present; }));
  if (count > 0 && count < soup.corners.size()) ++stats.incompleteAttributesDropped;
  return count > 0 && count == soup.corners.size();
}

Result<TriangleMesh> triangulate(PolygonSoup&& soup, const fs::path& path, std::vector<Vec3d>* world,
                                 MeshReadStats& stats) {
  if (soup.positions.size() > std::numeric_limits<std::uint32_t>::max() / 2) {
    return unsupported("too many vertices for 32-bit indices", {path.string(), ""});
  }
  TriangleMesh mesh;
  mesh.positions = soup.positions;
  if (world) *world = soup.precisePositions;
  const bool withNormals = attributeIsComplete(soup, &Corner::hasNormal, stats);
  const bool withTexcoords = attributeIsComplete(soup, &Corner::hasTexcoord, stats);
  const std::vector<std::uint32_t> cornerVertex =
      assignCornerVertices(soup, withNormals, withTexcoords, mesh, world, stats);
  // Fan from each polygon's first corner.
  for (std::size_t p = 0; p < soup.polygonStarts.size(); ++p) {
    const std::size_t begin = soup.polygonStarts[p];
    const std::size_t end =
        p + 1 < soup.polygonStarts.size() ? soup.polygonStarts[p + 1] : soup.corners.size();
    if (end - begin > 3) ++stats.polygonsTriangulated;
    for (std::size_t c = begin + 1; c + 1 < end; ++c) {
      mesh.triangles.push_back({cornerVertex[begin], cornerVertex[c], cornerVertex[c + 1]});
    }
  }
  return mesh;
}

// ---------------------------------------------------------------------------------------------------
// Putting it together.

MeshFormat formatOf(const std::string& extension) {
  if (extension == ".obj") return MeshFormat::Obj;
  if (extension == ".off") return MeshFormat::Off;
  if (extension == ".ply") return MeshFormat::Ply;
  if (extension == ".stl") return MeshFormat::Stl;
  if (extension == ".gltf" || extension == ".glb") return MeshFormat::Gltf;
  return MeshFormat::Unknown;
}

Result<Prescan> prescan(MeshFormat format, std::string_view bytes, const fs::path& path) {
  switch (format) {
    case MeshFormat::Obj: return prescanObj(bytes, path);
    case MeshFormat::Off: return prescanOff(bytes, path);
    case MeshFormat::Ply: return prescanPly(bytes, path);
    case MeshFormat::Stl: return prescanStl(bytes, path);
    default: return internalError("no pre-scan for this format", {path.string(), ""});
  }
}

// After parsing: every declared element must have arrived (binary files end early silently).
Status checkDeclaredCounts(const Prescan& scan, const PolygonSoup& soup, const fs::path& path) {
  if (scan.declaredVertices && soup.positions.size() != *scan.declaredVertices) {
    return invalidInput("the header declares " + std::to_string(*scan.declaredVertices) + " vertices, " +
                            std::to_string(soup.positions.size()) + " were read (truncated file?)",
                        {path.string(), scan.verticesWhere});
  }
  if (scan.declaredFaces && soup.facesOffered != *scan.declaredFaces) {
    return invalidInput("the header declares " + std::to_string(*scan.declaredFaces) + " faces, " +
                            std::to_string(soup.facesOffered) + " were read (truncated file?)",
                        {path.string(), scan.facesWhere});
  }
  return {};
}

// The text's own coordinates, in double, replace OpenMesh's floats where they are what it rounded (a
// homogeneous OBJ "v x y z w" or anything else it changed keeps its float).
void adoptTextCoordinates(const std::vector<std::array<double, 3>>& text, PolygonSoup& soup) {
  if (text.size() != soup.positions.size()) return;
  auto sameFloat = [](double precise, float rounded) {  // within one float step (strtof vs strtod)
    const float nearest = float(precise);
    return nearest == rounded || std::nextafter(nearest, rounded) == rounded;
  };
  for (std::size_t v = 0; v < text.size(); ++v) {
    bool same = true;
    for (int k = 0; k < 3; ++k) same = same && sameFloat(text[v][k], soup.positions[v][k]);
    if (same) soup.precisePositions[v] = text[v];
  }
}

Result<TriangleMesh> readWithOpenMesh(const fs::path& path, MeshFormat format, bool nearOrigin,
                                      MeshReadStats& stats) {
  BAKE_ASSIGN_OR_RETURN(const std::vector<std::uint8_t> bytes, readFileBytes(path));
  if (bytes.empty()) return invalidInput("the file is empty", {path.string(), ""});
  std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  // A text mesh may start with a UTF-8 byte-order mark (a binary STL's free header may hold those bytes).
  if (!(format == MeshFormat::Stl && isBinaryStl(text))) text = withoutByteOrderMark(text);
  BAKE_ASSIGN_OR_RETURN(const Prescan scan, prescan(format, text, path));
  // Before OpenMesh builds anything: the faces the header declares or the scan counted (an OBJ
  // polygon is at least one triangle; the exact count is checked again after triangulation).
  const std::size_t faces = scan.declaredFaces ? *scan.declaredFaces : scan.stlTriangles ? *scan.stlTriangles : scan.objFaces;
  BAKE_RETURN_IF_ERROR(checkBudget(Budget::Triangles, faces, "faces", {path.string(), scan.facesWhere}));

  SoupImporter importer(format == MeshFormat::Obj ? AttributeScope::PerCorner : AttributeScope::PerVertex);
  if (!parseWithOpenMesh(text, format, importer)) {
    return invalidInput("OpenMesh could not parse the file", {path.string(), ""});
  }
  if (importer.problem()) return invalidInput(*importer.problem(), {path.string(), ""});
  PolygonSoup& soup = importer.soup();
  BAKE_RETURN_IF_ERROR(checkDeclaredCounts(scan, soup, path));

  stats.degenerateFacesRemoved += soup.degenerateFaces + scan.degenerateFaces;
  if (scan.stlTriangles) {
    stats.degenerateFacesRemoved += *scan.stlTriangles - std::min(*scan.stlTriangles, soup.facesOffered);
  }
  if (!nearOrigin) return triangulate(std::move(soup), path, nullptr, stats);
  adoptTextCoordinates(scan.positions, soup);
  WorldPositions world;
  BAKE_ASSIGN_OR_RETURN(TriangleMesh mesh, triangulate(std::move(soup), path, &world.vertices, stats));
  placeNearOrigin(world, mesh);
  return mesh;
}

Status checkFinite(const float* values, int count, const std::string& name, std::size_t vertex,
                   const char* what) {
  for (int i = 0; i < count; ++i) {
    if (!std::isfinite(values[i])) {
      return invalidInput(std::string(what) + " is not finite", {name, "vertex " + std::to_string(vertex)});
    }
  }
  return {};
}

}  // namespace

Status validateMesh(const TriangleMesh& mesh, const std::string& name) {
  const std::size_t vertexCount = mesh.positions.size();
  if (!mesh.normals.empty() && mesh.normals.size() != vertexCount) {
    return invalidInput("there are " + std::to_string(mesh.normals.size()) + " normals for " +
                            std::to_string(vertexCount) + " vertices",
                        {name, ""});
  }
  if (!mesh.texcoords.empty() && mesh.texcoords.size() != vertexCount) {
    return invalidInput("there are " + std::to_string(mesh.texcoords.size()) + " texture coordinates for " +
                            std::to_string(vertexCount) + " vertices",
                        {name, ""});
  }
  for (std::size_t v = 0; v < vertexCount; ++v) {
    BAKE_RETURN_IF_ERROR(checkFinite(mesh.positions[v].data(), 3, name, v, "position"));
    if (!mesh.normals.empty()) {
      BAKE_RETURN_IF_ERROR(checkFinite(mesh.normals[v].data(), 3, name, v, "normal"));
    }
    if (!mesh.texcoords.empty()) {
      BAKE_RETURN_IF_ERROR(checkFinite(mesh.texcoords[v].data(), 2, name, v, "texture coordinate"));
    }
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (std::uint32_t index : mesh.triangles[t]) {
      if (index >= vertexCount) {
        return invalidInput("vertex index " + std::to_string(index) + " is out of range (" +
                                std::to_string(vertexCount) + " vertices)",
                            {name, "triangle " + std::to_string(t)});
      }
    }
  }
  return {};
}

Result<TriangleMesh> readMesh(const fs::path& path, const MeshReadOptions& options, MeshReadStats* stats) {
  MeshReadStats localStats;
  MeshReadStats& counts = stats ? *stats : localStats;
  counts = {};
  if (!std::isfinite(options.weldTolerance) || options.weldTolerance < 0.0) {
    return usageError("the weld tolerance must be a finite, non-negative number");
  }
  const std::string extension = lowercaseExtension(path);
  const MeshFormat format = formatOf(extension);
  if (format == MeshFormat::Unknown) {
    const std::string what = extension.empty() ? "a file without extension" : "extension '" + extension + "'";
    return unsupported("unknown mesh format: " + what + " (expected .obj, .ply, .off, .stl, .gltf or .glb)",
                       {path.string(), ""});
  }

  TriangleMesh mesh;
  if (format == MeshFormat::Gltf) {
    BAKE_ASSIGN_OR_RETURN(mesh, readGltfMesh(path, &counts, options.nearOrigin));
  } else {
    BAKE_ASSIGN_OR_RETURN(mesh, readWithOpenMesh(path, format, options.nearOrigin, counts));
  }
  if (mesh.triangles.empty()) {
    return invalidInput(counts.degenerateFacesRemoved
                            ? "every face is degenerate (fewer than 3 distinct vertices)"
                            : "the file contains no faces",
                        {path.string(), ""});
  }
  BAKE_RETURN_IF_ERROR(checkBudget(Budget::Triangles, mesh.triangles.size(), "triangles", {path.string(), ""}));
  BAKE_RETURN_IF_ERROR(validateMesh(mesh, path.string()));

  if (options.weld) {
    const WeldStats weld = weldVertices(mesh, options.weldTolerance);
    counts.verticesWelded += weld.verticesWelded;
    counts.degenerateFacesRemoved += weld.degenerateTrianglesRemoved;
    if (mesh.triangles.empty()) {
      return invalidInput("every triangle collapsed when welding vertices", {path.string(), ""});
    }
  }
  return mesh;
}

}  // namespace bake
