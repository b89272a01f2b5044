// Grooves renderer (seed 000; formats/grooves.md). Per package drawn: decode and check the
// BAKE_grooves arrays with libbake's reader, then upload every bufferView as it is into one immutable
// storage buffer (each at an offset aligned for GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT and the
// format's 256 bytes) and the grid header and counts into an 80-byte std140 uniform block. Per
// instance: the mesh (POSITION, NORMAL and TANGENT when present, TEXCOORD_0) and the variant of shaders/grooves/
// its package needs:
// mirrors compiled in only when a material mirrors, the special-case lookup only when the grid has
// records, arrays sized to the package's longest profile and (up to 24) its primitive count. With
// area sampling, pixels that a driver's loop cap cut short are shaded again in retry passes.
#include "render/grooves.h"

#include <GL/glcorearb.h>
#include <bake_formats/grooves.h>

#include <algorithm>
#include <cstring>

#include "grooves/package/package.h"

namespace bake::play {
namespace {

namespace fmt = format::grooves;

constexpr int kPositionLocation = 0, kNormalLocation = 1, kTexcoordLocation = 2, kTangentLocation = 3;
constexpr GLuint kHeaderBinding = 0;
// Primitives kept per footprint (the shader's fixed arrays; a footprint over more is shaded from the
// package's far level, or counted as truncated in a version 1 package that has none).
constexpr std::size_t kMaxFound = fmt::kMaxFoundPerFootprint;
// The per-frame counts of far_level.glsl: far, truncated, classes dropped.
constexpr std::size_t kFrameCounts = 3;
// The area sampling arena of shaders/grooves/area_polygon.glsl (packages with special cases only):
// kAreaSlots flags, then kAreaSlots x kAreaSlotFloats floats (40 MiB) that the shader cuts into as
// many slots as fit (one invocation's cells, pieces and polygons: about 32,800 floats with 24
// primitives found and 8-point profiles, so about 320 slots). A pixel sampled by area while every
// slot is taken is line sampled instead. Each slot layout (package defines) has an arena of its own.
constexpr GLuint kAreaScratchBinding = fmt::kAreaScratchBinding;
constexpr std::size_t kAreaSlots = 512, kAreaSlotFloats = 20480;
// After the slot flags, the shader's areaCounts: special-case fragments sampled by area, line sampled
// for want of a slot, line sampled because a driver's loop cap cut the area sample short.
// The fourth: cut short in the first pass and shaded again in a retry pass (counted there too).
constexpr std::size_t kAreaCountsOffset = kAreaSlots * sizeof(std::uint32_t), kAreaCounts = 4;
// The retry buffer of shaders/grooves/area_retry.glsl (std430): per node of the parts' quadtree of
// each pixel of the second list, a vec4 (kRetryNodes per pixel, kRetryList pixels), two list
// lengths, two lists of kRetryList pixels, then one mark per pixel of the target. Pixels cut short
// by a driver's loop cap are shaded again one draw each, scissored to the pixel; those cut short
// again are shaded by nodes of the quadtree of their footprint (down to sixty-fourths,
// kAreaMaxSplitLevel, the CPU's deepest split too), only the children of nodes cut short, each node
// beam by beam (kAreaEyeBeams draws, the most beams of the eye's mirror pieces) or, without traced
// beams, whole and from quarters on; then a last draw per pixel sums its leaves.
constexpr GLuint kAreaRetryBinding = fmt::kAreaRetryBinding;
constexpr int kAreaMaxSplitLevel = 3, kAreaEyeBeams = 6;
constexpr std::size_t kRetryList = 4096;
constexpr std::size_t kRetryNodes = ((std::size_t(1) << (2 * (kAreaMaxSplitLevel + 1))) - 1) / 3;  // 85
constexpr std::size_t kRetryCountsOffset = kRetryList * kRetryNodes * 4 * sizeof(float);
constexpr std::size_t kRetryListOffset = kRetryCountsOffset + 2 * sizeof(std::uint32_t);
constexpr std::size_t kRetryMaskOffset = kRetryListOffset + 2 * kRetryList * sizeof(std::uint32_t);
// Where a level's nodes start among the vec4 (area_retry.glsl retryNode): level by level, each
// level pixel by pixel.
constexpr std::size_t retryLevelStart(int level) {
  return ((std::size_t(1) << (2 * level)) - 1) / 3 * kRetryList;
}

// The std140 GrooveHeader block of shaders/grooves/package.glsl.
struct HeaderBlock {
  float domainCell[4];
  float originBounds[4];
  float bounds[4];
  std::int32_t cells[4];
  std::int32_t counts[4];
  float farCell[4];          // the far level's cell size u, v; 0, 0
  std::int32_t farCells[4];  // its columns, rows, classes (0: no far level), 0
};
static_assert(sizeof(HeaderBlock) == 112);

HeaderBlock headerBlock(const grooves::GroovePackage& package) {
  const grooves::GroovePackageHeader& h = package.header;
  HeaderBlock block{};
  block.counts[0] = std::int32_t(package.primitives.size());
  block.counts[1] = std::int32_t(package.records.size());
  block.domainCell[0] = float(h.domain[0]);
  block.domainCell[1] = float(h.domain[1]);
  block.domainCell[2] = float(h.cellSize[0]);
  block.domainCell[3] = float(h.cellSize[1]);
  block.originBounds[0] = float(h.origin[0]);
  block.originBounds[1] = float(h.origin[1]);
  block.bounds[0] = float(h.wmax);
  block.bounds[1] = float(h.hmax);
  block.bounds[2] = float(h.dmax);
  block.cells[0] = std::int32_t(h.cells[0]);
  block.cells[1] = std::int32_t(h.cells[1]);
  block.cells[2] = h.wrapRepeat ? 1 : 0;
  block.cells[3] = std::int32_t(h.baseMaterial);
  block.farCell[0] = float(h.farCellSize[0]);
  block.farCell[1] = float(h.farCellSize[1]);
  block.farCells[0] = std::int32_t(h.farCells[0]);
  block.farCells[1] = std::int32_t(h.farCells[1]);
  block.farCells[2] = std::int32_t(package.farClasses.size());
  return block;
}

// The bufferView index of each array, in the order of fmt::kArrayKeys (decodeGroovePackage has
// checked that they exist); -1 for the far level's arrays of a version 1 package.
std::array<long long, fmt::kArrayCount> viewIndices(const nlohmann::json& extension) {
  std::array<long long, fmt::kArrayCount> views{};
  const nlohmann::json& named = extension[fmt::kBufferViews];
  for (std::size_t k = 0; k < fmt::kArrayCount; ++k)
    views[k] = named.contains(fmt::kArrayKeys[k]) ? named[fmt::kArrayKeys[k]].get<long long>() : -1;
  return views;
}

std::size_t alignUp(std::size_t x, std::size_t alignment) { return (x + alignment - 1) / alignment * alignment; }

// The defines of the variant a package needs.
std::vector<std::string> packageDefines(const grooves::GroovePackage& p, bool areaSampling, bool areaReflections) {
  std::vector<std::string> defines;
  const bool mirrors = std::any_of(p.materials.begin(), p.materials.end(), [](const fmt::Material& m) { return m.specular[3] > 0.5f; });
  if (mirrors) defines.push_back("HAS_MIRRORS");
  if (!p.records.empty()) defines.push_back("HAS_SPECIAL_CASES");
  if (!p.records.empty() && areaSampling) {
    defines.push_back("HAS_AREA_SAMPLING");
    defines.push_back("AREA_SLOTS " + std::to_string(kAreaSlots));
    defines.push_back("AREA_RETRY_LIST " + std::to_string(kRetryList));
    defines.push_back("AREA_RETRY_NODES " + std::to_string(kRetryNodes));
    defines.push_back("AREA_MAX_SPLIT_LEVEL " + std::to_string(kAreaMaxSplitLevel));
    defines.push_back("AREA_EYE_BEAMS " + std::to_string(kAreaEyeBeams));
    if (mirrors && areaReflections) defines.push_back("AREA_REFLECTIONS");
  }
  std::uint32_t longest = 3;
  for (const fmt::Profile& profile : p.profiles) longest = std::max(longest, profile.points[1]);
  defines.push_back("MAX_PROFILE_POINTS " + std::to_string(longest));
  // A footprint never finds more primitives than the package holds: small packages get small arrays.
  const std::size_t found = std::clamp<std::size_t>(p.primitives.size(), 1, kMaxFound);
  defines.push_back("MAX_FOUND " + std::to_string(found));
  defines.push_back("MAX_CLASSES " + std::to_string(fmt::kMaxClassesPerFootprint));
  defines.push_back("MAX_REACH " + std::to_string(fmt::kMaxReach));
  return defines;
}

void setMatrix4(unsigned program, const char* name, const Mat4& m) {
  glProgramUniformMatrix4fv(program, glGetUniformLocation(program, name), 1, GL_FALSE, m.data());
}

}  // namespace

GroovesRenderer::~GroovesRenderer() {
  for (const Upload& upload : uploads_) {
    const GLuint buffers[] = {upload.storage, upload.header};
    glDeleteBuffers(2, buffers);
  }
  for (const auto& [defines, buffer] : areaScratch_) glDeleteBuffers(1, &buffer);
  if (areaRetry_ != 0) glDeleteBuffers(1, &areaRetry_);
  if (frameCounts_ != 0) glDeleteBuffers(1, &frameCounts_);
}

// The arena of a slot layout, zeroed (every slot free), made once for all packages with that layout.
unsigned GroovesRenderer::areaScratchFor(const std::vector<std::string>& packageDefines) {
  unsigned& buffer = areaScratch_[packageDefines];
  if (buffer != 0) return buffer;
  const std::size_t bytes =
      kAreaCountsOffset + kAreaCounts * sizeof(std::uint32_t) + kAreaSlots * kAreaSlotFloats * sizeof(float);
  glCreateBuffers(1, &buffer);
  glNamedBufferStorage(buffer, GLsizeiptr(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
  const std::uint32_t zero = 0;
  glClearNamedBufferData(buffer, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  bytes_ += bytes;
  return buffer;
}

// The retry buffer sized for a width x height target, its lists emptied and its marks zeroed.
void GroovesRenderer::clearAreaRetry(int width, int height) {
  const std::size_t pixels = std::size_t(std::max(width, 1)) * std::size_t(std::max(height, 1));
  const std::size_t bytes = kRetryMaskOffset + pixels * sizeof(std::uint32_t);
  if (bytes != retryBytes_) {
    if (areaRetry_ != 0) glDeleteBuffers(1, &areaRetry_);
    bytes_ -= retryBytes_;
    glCreateBuffers(1, &areaRetry_);
    glNamedBufferStorage(areaRetry_, GLsizeiptr(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
    retryBytes_ = bytes;
    bytes_ += bytes;
  }
  const std::uint32_t zero = 0;
  glClearNamedBufferSubData(areaRetry_, GL_R32UI, GLintptr(kRetryCountsOffset), GLsizeiptr(bytes - kRetryCountsOffset),
                            GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

Status GroovesRenderer::prepare(const Scene& scene, const std::vector<std::size_t>& instances,
                                gl::ShaderLibrary& shaders) {
  // Keyed by (package, material): an assembled scene package holds one groove grid per material.
  std::map<std::pair<std::size_t, int>, std::size_t> uploadOfPackage;
  std::map<std::pair<std::size_t, int>, std::vector<std::string>> definesOfPackage;
  GLint storageAlignment = 256;
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &storageAlignment);
  const std::size_t alignment = std::max<std::size_t>(fmt::kBufferAlignment, std::size_t(std::max(1, storageAlignment)));
  for (std::size_t index : instances) {
    const Instance& instance = scene.instances[index];
    const glb::Package& package = scene.packages[instance.package];
    const std::string file = scene.files.empty() ? "" : scene.files[instance.package];
    const glb::Primitive& primitive = scene.primitive(instance);
    const Location where{file, "mesh " + std::to_string(instance.mesh) + " primitive " + std::to_string(instance.primitive)};
    if (!primitive.find("TEXCOORD_0")) return invalidInput(std::string(fmt::kExtension) + " needs TEXCOORD_0 on the mesh", where);

    const auto key = std::make_pair(instance.package, primitive.material);
    if (!uploadOfPackage.count(key)) {
      const nlohmann::json& extension = scene.material(instance)["extensions"][fmt::kExtension];
      BAKE_ASSIGN_OR_RETURN(const grooves::GroovePackage decoded, grooves::decodeGrooveExtension(package, extension, file));
      const auto views = viewIndices(extension);
      Upload upload;
      std::size_t total = 0;
      // An array the package lacks (no far level) is bound to 16 zero bytes.
      for (std::size_t k = 0; k < fmt::kArrayCount; ++k) {
        upload.offset[k] = total;
        upload.size[k] = views[k] >= 0 ? package.blobs[std::size_t(views[k])].bytes.size() : 16;
        total = alignUp(total + upload.size[k], alignment);
      }
      std::vector<std::uint8_t> bytes(total, 0);
      for (std::size_t k = 0; k < fmt::kArrayCount; ++k)
        if (views[k] >= 0)
          std::memcpy(bytes.data() + upload.offset[k], package.blobs[std::size_t(views[k])].bytes.data(), upload.size[k]);
      glCreateBuffers(1, &upload.storage);
      glNamedBufferStorage(upload.storage, GLsizeiptr(bytes.size()), bytes.data(), 0);
      const HeaderBlock header = headerBlock(decoded);
      glCreateBuffers(1, &upload.header);
      glNamedBufferStorage(upload.header, sizeof header, &header, 0);
      bytes_ += bytes.size() + sizeof header;
      uploadOfPackage[key] = uploads_.size();
      definesOfPackage[key] = packageDefines(decoded, options_.areaSampling, options_.areaReflections);
      if (frameCounts_ == 0) {
        glCreateBuffers(1, &frameCounts_);
        glNamedBufferStorage(frameCounts_, kFrameCounts * sizeof(std::uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
        bytes_ += kFrameCounts * sizeof(std::uint32_t);
      }
      uploads_.push_back(upload);
    }

    gl::Variant variant{{"grooves/grooves.vert", "grooves/grooves.frag", "", "", ""}, definesOfPackage[key]};
    std::map<std::string, int> locations = {{"POSITION", kPositionLocation}, {"TEXCOORD_0", kTexcoordLocation}};
    if (primitive.find("NORMAL")) {
      variant.defines.push_back("HAS_NORMALS");
      locations["NORMAL"] = kNormalLocation;
      if (const glb::Attribute* tangent = primitive.find("TANGENT"); tangent && tangent->components == 4) {
        variant.defines.push_back("HAS_TANGENTS");
        locations["TANGENT"] = kTangentLocation;
      }
    }
    if (options_.shadingInputs) variant.defines.push_back("SHADING_INPUTS");
    Item item;
    BAKE_ASSIGN_OR_RETURN(item.program, shaders.program(variant));
    BAKE_ASSIGN_OR_RETURN(item.mesh, GpuPrimitive::upload(primitive, locations));
    item.world = instance.world;
    item.upload = uploadOfPackage[key];
    item.areaSampling = std::count(variant.defines.begin(), variant.defines.end(), "HAS_AREA_SAMPLING") > 0;
    if (item.areaSampling) item.areaScratch = areaScratchFor(definesOfPackage[key]);
    items_.push_back(std::move(item));
  }
  return {};
}

// One draw of an item: its uniforms and buffers, then the mesh. `retry`: the pass
// (area_retry.glsl: 0 the first, 1 a retry of whole footprints, 2 by parts); `number` is the
// item's draw number in the frame.
void GroovesRenderer::drawItem(const Item& item, const FrameContext& frame, int number, const RetryPass& retry) const {
  const unsigned program = item.program;
  glUseProgram(program);
  setMatrix4(program, "uModel", item.world);
  setMatrix4(program, "uViewProj", multiply(frame.projection, frame.view));
  const Mat3 normal = normalMatrix(item.world);
  glProgramUniformMatrix3fv(program, glGetUniformLocation(program, "uNormalMatrix"), 1, GL_FALSE, normal.data());
  glProgramUniform3fv(program, glGetUniformLocation(program, "uLightDir"), 1, frame.light.direction.data());
  glProgramUniform3fv(program, glGetUniformLocation(program, "uLightColour"), 1, frame.light.colour.data());
  glProgramUniform3fv(program, glGetUniformLocation(program, "uCameraPos"), 1, frame.camera.eye.data());
  glProgramUniform1i(program, glGetUniformLocation(program, "uMaxBounces"), options_.maxBounces);
  glProgramUniform3fv(program, glGetUniformLocation(program, "uEnvironment"), 1, frame.light.environment.data());
  if (item.areaSampling) {
    glProgramUniform1i(program, glGetUniformLocation(program, "uAreaRetry"), retry.kind);
    glProgramUniform1i(program, glGetUniformLocation(program, "uAreaPartLevel"), retry.level);
    glProgramUniform1i(program, glGetUniformLocation(program, "uAreaPart"), retry.part);
    glProgramUniform1i(program, glGetUniformLocation(program, "uAreaBeam"), retry.beam);
    glProgramUniform1i(program, glGetUniformLocation(program, "uRetrySlot"), retry.slot);
    glProgramUniform1i(program, glGetUniformLocation(program, "uRetryRootLevel"), retry.rootLevel);
    glProgramUniform1i(program, glGetUniformLocation(program, "uRetryDraw"), number);
    glProgramUniform1i(program, glGetUniformLocation(program, "uRetryStride"), std::max(frame.width, 1));
    glProgramUniform1i(program, glGetUniformLocation(program, "uForceRetries"), options_.forceRetries);
  }
  const Upload& upload = uploads_[item.upload];
  for (std::size_t k = 0; k < fmt::kArrayCount; ++k)
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, GLuint(k), upload.storage, GLintptr(upload.offset[k]),
                      GLsizeiptr(upload.size[k]));
  glBindBufferBase(GL_UNIFORM_BUFFER, kHeaderBinding, upload.header);
  if (item.areaScratch != 0) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kAreaScratchBinding, item.areaScratch);
  if (areaRetry_ != 0) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kAreaRetryBinding, areaRetry_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, fmt::kFrameCountsBinding, frameCounts_);
  item.mesh.draw();
}

// The pixels of list `list` (0: shade again whole, 1: by parts) as (x, y), in the list's order (the
// slots of list 1).
std::vector<std::array<int, 2>> GroovesRenderer::retryList(int list) const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::uint32_t count = 0;
  glGetNamedBufferSubData(areaRetry_, GLintptr(kRetryCountsOffset + std::size_t(list) * sizeof count), sizeof count, &count);
  count = std::min<std::uint32_t>(count, kRetryList);  // the shader lists no more
  std::vector<std::uint32_t> packed(count);
  if (count > 0)
    glGetNamedBufferSubData(areaRetry_, GLintptr(kRetryListOffset + std::size_t(list) * kRetryList * sizeof(std::uint32_t)),
                            GLsizeiptr(count * sizeof(std::uint32_t)), packed.data());
  std::vector<std::array<int, 2>> pixels;
  for (const std::uint32_t p : packed) pixels.push_back({int(p & 0xffffu), int(p >> 16)});
  return pixels;
}

// The slots of `pixels` in raster order, so that which pixels the draw budget reaches does not
// depend on the order the shader listed them in (threads race for the list).
std::vector<std::size_t> rasterOrder(const std::vector<std::array<int, 2>>& pixels) {
  std::vector<std::size_t> order(pixels.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::array{pixels[a][1], pixels[a][0]} < std::array{pixels[b][1], pixels[b][0]};
  });
  return order;
}

// Every item that samples by area, drawn again for one retry pass, scissored to its pixel; each pass
// sees the marks and sums of the ones before. False, drawing nothing, once the frame's retry draws
// are spent (the sum passes are not counted: one per pixel listed by parts).
bool GroovesRenderer::drawRetryPass(const FrameContext& frame, std::array<int, 2> pixel, const RetryPass& retry) {
  if (retry.kind != 3 && retryDrawsSpent_ >= options_.retryDraws) return false;
  if (retry.kind != 3) ++retryDrawsSpent_;
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glScissor(pixel[0], pixel[1], 1, 1);
  ++retryPasses_;
  for (std::size_t i = 0; i < items_.size(); ++i)
    if (items_[i].areaSampling) drawItem(items_[i], frame, int(i) + 1, retry);
  return true;
}

// The children of the nodes at `level` (of the pixels in the second list, `pixels` of them) that a
// draw cut short (their w, area_retry.glsl), from one read of the level's nodes.
std::vector<GroovesRenderer::RetryNode> GroovesRenderer::childrenOfCutNodes(int level, const std::vector<RetryNode>& nodes,
                                                                            std::size_t pixels) const {
  std::vector<float> sums(4 * (pixels << (2 * level)));
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(areaRetry_, GLintptr(retryLevelStart(level) * 4 * sizeof(float)),
                          GLsizeiptr(sums.size() * sizeof(float)), sums.data());
  std::vector<RetryNode> children;
  const int side = 1 << level;
  for (const RetryNode& node : nodes) {
    if (sums[4 * ((node.slot << (2 * level)) + std::size_t(node.part)) + 3] == 0) continue;
    const int x = node.part % side, y = node.part / side;
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) children.push_back({node.slot, (2 * y + dy) * 2 * side + 2 * x + dx});
  }
  return children;
}

// The pixels listed again by the whole retries, shaded by nodes of their footprint's quadtree: the
// root level, then the children of each node cut short, level by level; then the sum pass of every
// pixel whose nodes were all drawn. A node is drawn beam by beam (with traced beams) or whole.
void GroovesRenderer::drawRetriesByParts(const FrameContext& frame, const std::vector<std::array<int, 2>>& pixels) {
  const float zero = 0.0f;
  glClearNamedBufferSubData(areaRetry_, GL_R32F, 0, GLintptr(kRetryCountsOffset), GL_RED, GL_FLOAT, &zero);
  const bool byBeams = options_.areaReflections;
  const int beams = byBeams ? kAreaEyeBeams : 1;
  // Without traced beams there is nothing to take one by one: whole nodes, from quarters on.
  const int root = byBeams ? 0 : 1;
  const std::vector<std::size_t> order = rasterOrder(pixels);
  std::vector<RetryNode> nodes;
  for (const std::size_t slot : order)
    for (int part = 0; part < 1 << (2 * root); ++part) nodes.push_back({slot, part});
  std::vector<bool> unfinished(pixels.size(), false);
  for (int level = root; !nodes.empty(); ++level) {
    for (const RetryNode& node : nodes)
      for (int beam = 0; beam < beams; ++beam)
        if (!drawRetryPass(frame, pixels[node.slot], {2, level, node.part, int(node.slot), byBeams ? beam : -1, root}))
          unfinished[node.slot] = true;
    if (level == kAreaMaxSplitLevel) break;
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    nodes = childrenOfCutNodes(level, nodes, pixels.size());
    std::vector<bool> again(pixels.size(), false);
    for (const RetryNode& node : nodes) again[node.slot] = true;
    retriedByParts_ += std::uint32_t(std::count(again.begin(), again.end(), true));
  }
  for (const std::size_t slot : order) {
    if (!unfinished[slot]) drawRetryPass(frame, pixels[slot], {3, 0, 0, int(slot), -1, root});
    else ++retriesUnfinished_;  // keeps the line sample of its whole retry
  }
}

// The pixels the first pass listed, shaded again one at a time, then those listed again by parts;
// up to the frame's retry draws (GroovesOptions::retryDraws), in raster order. Depth is tested
// (LEQUAL: the same fragments as the first pass) but not written.
void GroovesRenderer::drawRetryPasses(const FrameContext& frame) {
  const std::vector<std::array<int, 2>> whole = retryList(0);
  if (whole.empty()) return;
  GLint depthFunc = GL_LESS, scissorBox[4] = {};
  GLboolean depthMask = GL_TRUE;
  const GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);
  glGetIntegerv(GL_DEPTH_FUNC, &depthFunc);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
  glGetIntegerv(GL_SCISSOR_BOX, scissorBox);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_SCISSOR_TEST);
  for (const std::size_t k : rasterOrder(whole))
    if (!drawRetryPass(frame, whole[k], {1, 1, 0, 0})) ++retriesUnfinished_;  // keeps its first line sample
  const std::vector<std::array<int, 2>> byParts = retryList(1);
  if (!byParts.empty()) drawRetriesByParts(frame, byParts);
  glDepthFunc(GLenum(depthFunc));
  glDepthMask(depthMask);
  glScissor(scissorBox[0], scissorBox[1], scissorBox[2], scissorBox[3]);
  if (!scissor) glDisable(GL_SCISSOR_TEST);
}

void GroovesRenderer::draw(const FrameContext& frame) {
  retryPasses_ = 0;
  retriedByParts_ = 0;
  retriesUnfinished_ = 0;
  retryDrawsSpent_ = 0;
  if (frameCounts_ != 0) {
    const std::uint32_t zero = 0;
    glClearNamedBufferData(frameCounts_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  }
  if (!areaScratch_.empty()) {  // the counts and marks are the frame's own
    const std::uint32_t zero = 0;
    for (const auto& [defines, buffer] : areaScratch_)
      glClearNamedBufferSubData(buffer, GL_R32UI, GLintptr(kAreaCountsOffset), kAreaCounts * sizeof(std::uint32_t),
                                GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    clearAreaRetry(frame.width, frame.height);
  }
  for (std::size_t i = 0; i < items_.size(); ++i) drawItem(items_[i], frame, int(i) + 1, {});
  if (areaRetry_ != 0) drawRetryPasses(frame);
  for (std::size_t k = 0; k < fmt::kArrayCount; ++k) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(k), 0);
  if (!areaScratch_.empty()) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kAreaScratchBinding, 0);
  if (areaRetry_ != 0) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kAreaRetryBinding, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, fmt::kFrameCountsBinding, 0);
  glBindBufferBase(GL_UNIFORM_BUFFER, kHeaderBinding, 0);
}

nlohmann::json GroovesRenderer::statistics() const {
  if (frameCounts_ == 0) return nullptr;  // nothing drawn
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::uint32_t frame[kFrameCounts] = {};
  glGetNamedBufferSubData(frameCounts_, 0, sizeof frame, frame);
  nlohmann::json s = {{"grooveFarFragments", frame[0]},
                      {"grooveTruncatedFragments", frame[1]},
                      {"grooveClassesDroppedFragments", frame[2]}};
  if (areaScratch_.empty()) return s;  // no package with special cases, or area sampling off
  std::uint32_t counts[kAreaCounts] = {};
  for (const auto& [defines, buffer] : areaScratch_) {
    std::uint32_t own[kAreaCounts] = {};
    glGetNamedBufferSubData(buffer, GLintptr(kAreaCountsOffset), sizeof own, own);
    for (std::size_t k = 0; k < kAreaCounts; ++k) counts[k] += own[k];
  }
  // A listed pixel the retry draws did not finish was counted as deferred by the pass that listed
  // it; its outcome is its line sample.
  s["grooveAreaFragments"] = counts[0] + counts[1] + counts[2] + retriesUnfinished_;
  s["grooveAreaLineSampledNoSlot"] = counts[1];
  s["grooveAreaLineSampledLoopCap"] = counts[2] + retriesUnfinished_;
  s["grooveAreaRetried"] = counts[3] + retriedByParts_;
  s["grooveAreaRetryPasses"] = retryPasses_;
  s["grooveAreaRetriesUnfinished"] = retriesUnfinished_;
  s["grooveAreaArenas"] = areaScratch_.size();
  return s;
}

std::vector<std::string> GroovesRenderer::warnings() const {
  const nlohmann::json s = statistics();
  if (s.is_null()) return {};
  std::vector<std::string> out;
  const auto truncated = s["grooveTruncatedFragments"].get<std::uint32_t>();
  if (truncated > 0)
    out.push_back("grooves: " + std::to_string(truncated) + " fragments of the last frame had more than " +
                  std::to_string(kMaxFound) +
                  " primitives under their footprint and the package has no far level (BAKE_grooves version 1): "
                  "the grooves past that were dropped; bake it again with this groovebake");
  const auto dropped = s["grooveClassesDroppedFragments"].get<std::uint32_t>();
  if (dropped > 0)
    out.push_back("grooves: " + std::to_string(dropped) + " fragments of the last frame had grooves in more than " +
                  std::to_string(fmt::kMaxClassesPerFootprint) +
                  " directions under their footprint: the directions past that were dropped");
  if (!s.contains("grooveAreaFragments")) return out;
  const auto noSlot = s["grooveAreaLineSampledNoSlot"].get<std::uint32_t>();
  const auto loopCap = s["grooveAreaLineSampledLoopCap"].get<std::uint32_t>();
  if (noSlot + loopCap == 0) return out;
  out.push_back("grooves: " + std::to_string(noSlot + loopCap) + " of " + s["grooveAreaFragments"].dump() +
                " special-case fragments of the last frame were line sampled instead of sampled by area (" +
                std::to_string(noSlot) + " found no free scratch slot, " + std::to_string(loopCap) +
                " were cut short by the driver's cap on loop iterations, as llvmpipe has, and not finished by the "
                "retry passes" +
                (s["grooveAreaRetriesUnfinished"].get<std::uint32_t>() > 0
                     ? ", " + s["grooveAreaRetriesUnfinished"].dump() + " of them for want of retry draws (--groove-retries " +
                           std::to_string(options_.retryDraws) + ")"
                     : std::string()) +
                ")");
  return out;
}

std::size_t GroovesRenderer::gpuBytes() const {
  std::size_t total = bytes_;
  for (const Item& item : items_) total += item.mesh.uploadedBytes();
  return total;
}

std::unique_ptr<TechniqueRenderer> groovesRenderer() { return std::make_unique<GroovesRenderer>(); }

}  // namespace bake::play
