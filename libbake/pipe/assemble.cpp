// Scene assembly (pipe/assemble.h): the generic merge. Each object's package is read, adapted by its
// technique's rules (<module>/pipe/assemble.cpp: the scene's material, unread data unreferenced), and
// then copied into the scene package: only the bufferViews, images, textures and samplers its
// materials reach (all of the package's data when unused data are kept), renumbered, with its meshes,
// materials and nodes, the nodes under one new node per object. Vertex data are not copied as
// bufferViews: the reader decodes the meshes and the writer lays them out again.
#include "pipe/assemble.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <system_error>

#include "pipe/assemble_parts.h"
#include "pipe/technique_hooks.h"

namespace bake::pipe {
namespace detail {

using nlohmann::json;

Status ObjectInput::error(const std::string& message) const {
  return invalidInput("object '" + object.name + "': " + message, {file, ""});
}

bool hasExtension(const json& material, const char* extension) {
  return material.is_object() && material.contains("extensions") && material["extensions"].is_object() &&
         material["extensions"].contains(extension) && material["extensions"][extension].is_object();
}

int materialWith(const glb::Package& package, const char* extension) {
  for (std::size_t m = 0; m < package.materials.size(); ++m)
    if (hasExtension(package.materials[m], extension)) return int(m);
  return -1;
}

int indexAt(const json& object, const char* key) {
  if (!object.is_object() || !object.contains(key) || !object[key].is_number_integer()) return -1;
  return object[key].get<int>();
}

ExtensionReferences BufferViewTable::references(const json& extension) const {
  ExtensionReferences references;
  if (!viewsKey) return references;
  const json& views = extension.value(viewsKey, json::object());
  for (const char* key : arrayKeys)
    if (views.contains(key)) references.blobs.push_back(indexAt(views, key));
  return references;
}

void BufferViewTable::renumber(json& extension, const Renumbering& renumbering) const {
  if (!viewsKey || !extension.contains(viewsKey)) return;
  json& views = extension[viewsKey];
  for (const char* key : arrayKeys)
    if (views.contains(key)) views[key] = Renumbering::at(renumbering.blobs, indexAt(views, key));
}

ExtensionReferences referencesOf(const TechniqueRules& rules, const json& extension) {
  ExtensionReferences references = rules.bufferViews.references(extension);
  if (!rules.references) return references;
  ExtensionReferences more = rules.references(extension);
  references.blobs.insert(references.blobs.end(), more.blobs.begin(), more.blobs.end());
  references.images.insert(references.images.end(), more.images.begin(), more.images.end());
  references.textures.insert(references.textures.end(), more.textures.begin(), more.textures.end());
  return references;
}

void renumberReferences(const TechniqueRules& rules, json& extension, const Renumbering& renumbering) {
  rules.bufferViews.renumber(extension, renumbering);
  if (rules.renumber) rules.renumber(extension, renumbering);
}

}  // namespace detail

namespace {

using nlohmann::json;
namespace fs = std::filesystem;
using detail::ObjectInput;
using detail::Renumbering;
using detail::TechniqueRules;

constexpr const char* kLightsExtension = "KHR_lights_punctual";

// The texture-info objects of a standard glTF material ({"index": texture}).
std::vector<json*> textureInfos(json& material) {
  std::vector<json*> infos;
  if (!material.is_object()) return infos;
  for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"})
    if (material.contains(key) && material[key].is_object()) infos.push_back(&material[key]);
  if (material.contains("pbrMetallicRoughness") && material["pbrMetallicRoughness"].is_object()) {
    json& pbr = material["pbrMetallicRoughness"];
    for (const char* key : {"baseColorTexture", "metallicRoughnessTexture"})
      if (pbr.contains(key) && pbr[key].is_object()) infos.push_back(&pbr[key]);
  }
  return infos;
}

// What a package's materials reach, in its own numbering.
struct Reached {
  std::set<int> blobs, images, textures, samplers;

  void add(const Reached& other) {
    blobs.insert(other.blobs.begin(), other.blobs.end());
    images.insert(other.images.begin(), other.images.end());
    textures.insert(other.textures.begin(), other.textures.end());
    samplers.insert(other.samplers.begin(), other.samplers.end());
  }
};

Reached reachedBy(const glb::Package& package, const TechniqueRules& rules) {
  Reached reached;
  for (json material : package.materials) {  // a copy: textureInfos hands out pointers
    for (json* info : textureInfos(material)) reached.textures.insert(detail::indexAt(*info, "index"));
    if (!detail::hasExtension(material, rules.extension)) continue;
    const detail::ExtensionReferences references = detail::referencesOf(rules, material["extensions"][rules.extension]);
    reached.blobs.insert(references.blobs.begin(), references.blobs.end());
    reached.images.insert(references.images.begin(), references.images.end());
    reached.textures.insert(references.textures.begin(), references.textures.end());
  }
  for (int texture : reached.textures) {
    if (texture < 0 || std::size_t(texture) >= package.textures.size()) continue;
    reached.images.insert(detail::indexAt(package.textures[std::size_t(texture)], "source"));
    reached.samplers.insert(detail::indexAt(package.textures[std::size_t(texture)], "sampler"));
  }
  for (int image : reached.images) {
    if (image < 0 || std::size_t(image) >= package.images.size()) continue;
    reached.blobs.insert(detail::indexAt(package.images[std::size_t(image)], "bufferView"));
  }
  return reached;
}

// Whatever the package's materials reach, and every image, texture and sampler it holds.
Reached everything(const glb::Package& package, const TechniqueRules& rules) {
  Reached reached = reachedBy(package, rules);
  for (std::size_t k = 0; k < package.images.size(); ++k) {
    reached.images.insert(int(k));
    reached.blobs.insert(detail::indexAt(package.images[k], "bufferView"));
  }
  for (std::size_t k = 0; k < package.textures.size(); ++k) reached.textures.insert(int(k));
  for (std::size_t k = 0; k < package.samplers.size(); ++k) reached.samplers.insert(int(k));
  return reached;
}

// Gives each reached index (ascending) the next free index of the assembled package. -1 entries
// (a missing optional reference) are skipped; an index past the package's list is an error.
Result<std::vector<int>> assign(const std::set<int>& reached, std::size_t size, std::size_t next, const char* what,
                                const ObjectInput& input) {
  std::vector<int> map(size, -1);
  for (int old : reached) {
    if (old < 0) continue;
    if (std::size_t(old) >= size)
      return input.error(std::string(what) + " " + std::to_string(old) + " is referenced but does not exist");
    map[std::size_t(old)] = int(next++);
  }
  return map;
}

void renumberTextureInfos(json& material, const Renumbering& renumbering) {
  for (json* info : textureInfos(material)) (*info)["index"] = Renumbering::at(renumbering.textures, detail::indexAt(*info, "index"));
}

// Copies the reached blobs, images, samplers and textures; returns the renumbering.
Result<Renumbering> copyData(const glb::Package& package, const Reached& reached, const TechniqueRules& rules,
                             const ObjectInput& input, glb::Package& out) {
  Renumbering r;
  BAKE_ASSIGN_OR_RETURN(r.blobs, assign(reached.blobs, package.blobs.size(), out.blobs.size(), "bufferView", input));
  BAKE_ASSIGN_OR_RETURN(r.images, assign(reached.images, package.images.size(), out.images.size(), "image", input));
  BAKE_ASSIGN_OR_RETURN(r.textures, assign(reached.textures, package.textures.size(), out.textures.size(), "texture", input));
  BAKE_ASSIGN_OR_RETURN(r.samplers, assign(reached.samplers, package.samplers.size(), out.samplers.size(), "sampler", input));
  for (std::size_t k = 0; k < package.blobs.size(); ++k)
    if (r.blobs[k] >= 0) out.blobs.push_back({package.blobs[k].bytes, std::max(rules.blobAlignment, package.blobs[k].alignment)});
  for (std::size_t k = 0; k < package.images.size(); ++k) {
    if (r.images[k] < 0) continue;
    json image = package.images[k];
    if (image.contains("bufferView")) image["bufferView"] = Renumbering::at(r.blobs, detail::indexAt(image, "bufferView"));
    out.images.push_back(std::move(image));
  }
  for (std::size_t k = 0; k < package.samplers.size(); ++k)
    if (r.samplers[k] >= 0) out.samplers.push_back(package.samplers[k]);
  for (std::size_t k = 0; k < package.textures.size(); ++k) {
    if (r.textures[k] < 0) continue;
    json texture = package.textures[k];
    if (texture.contains("source")) texture["source"] = Renumbering::at(r.images, detail::indexAt(texture, "source"));
    if (texture.contains("sampler")) texture["sampler"] = Renumbering::at(r.samplers, detail::indexAt(texture, "sampler"));
    out.textures.push_back(std::move(texture));
  }
  return r;
}

// The package's top-level nodes: its scene's roots, else every node that is no node's child.
std::vector<int> topNodes(const glb::Package& package) {
  if (!package.sceneRoots.empty()) return package.sceneRoots;
  std::vector<bool> isChild(package.nodes.size(), false);
  for (const glb::Node& node : package.nodes)
    for (int child : node.children)
      if (child >= 0 && std::size_t(child) < package.nodes.size()) isChild[std::size_t(child)] = true;
  std::vector<int> roots;
  for (std::size_t n = 0; n < package.nodes.size(); ++n)
    if (!isChild[n]) roots.push_back(int(n));
  return roots;
}

// Meshes, materials and nodes, the nodes under a new node for the object; cameras and lights dropped.
void copyStructure(glb::Package package, const Renumbering& renumbering, const TechniqueRules& rules,
                   const ObjectInput& input, glb::Package& out) {
  const int meshOffset = int(out.meshes.size()), materialOffset = int(out.materials.size()),
            nodeOffset = int(out.nodes.size());
  for (json material : package.materials) {
    renumberTextureInfos(material, renumbering);
    if (detail::hasExtension(material, rules.extension))
      detail::renumberReferences(rules, material["extensions"][rules.extension], renumbering);
    out.materials.push_back(std::move(material));
  }
  for (glb::Mesh& mesh : package.meshes) {
    for (glb::Primitive& primitive : mesh.primitives) {
      if (primitive.material >= 0) primitive.material += materialOffset;
      primitive.dracoCompressed = false;
    }
    out.meshes.push_back(std::move(mesh));
  }
  if (package.nodes.empty()) {  // as the writer does: one node per mesh
    for (std::size_t m = 0; m < package.meshes.size(); ++m) {
      glb::Node node;
      node.mesh = int(m);
      package.nodes.push_back(std::move(node));
    }
  }
  std::size_t cameras = 0;
  for (glb::Node node : package.nodes) {
    if (node.mesh >= 0) node.mesh += meshOffset;
    for (int& child : node.children) child += nodeOffset;
    if (node.camera >= 0) ++cameras;
    node.camera = -1;
    node.extensions.erase(kLightsExtension);
    out.nodes.push_back(std::move(node));
  }
  if (cameras > 0 || !package.cameras.empty())
    input.drop(std::to_string(std::max(cameras, package.cameras.size())) + " camera(s) (the scene's cameras frame the view)");

  glb::Node object;
  object.name = input.object.name;
  object.translation = input.object.position;
  object.rotation = input.object.rotation;
  object.scale = {input.object.scale, input.object.scale, input.object.scale};
  for (int root : topNodes(package)) object.children.push_back(root + nodeOffset);
  out.sceneRoots.push_back(int(out.nodes.size()));
  out.nodes.push_back(std::move(object));
}

// Root extensions: the technique's merged by its rules; lights dropped; any other copied when the
// assembled package has none of that name or the same one.
Status mergeRootExtensions(const glb::Package& package, const TechniqueRules& rules, const ObjectInput& input,
                           glb::Package& out) {
  for (const auto& [name, body] : package.extensions.items()) {
    if (name == kLightsExtension) {
      input.drop("lights (" + std::string(kLightsExtension) + ")");
    } else if (name == rules.extension && rules.mergeRoot) {
      BAKE_RETURN_IF_ERROR(rules.mergeRoot(out.extensions, package, input));
    } else if (!out.extensions.contains(name)) {
      out.extensions[name] = body;
    } else if (out.extensions[name] != body) {
      return unsupported("object '" + input.object.name + "': root extension " + name +
                             " differs from another package's and cannot be merged",
                         {input.file, "extensions." + name});
    }
  }
  for (const std::string& required : package.extensionsRequired) {
    if (required == kLightsExtension || required == "KHR_draco_mesh_compression") continue;
    if (std::find(out.extensionsRequired.begin(), out.extensionsRequired.end(), required) == out.extensionsRequired.end())
      out.extensionsRequired.push_back(required);
  }
  return {};
}

Result<glb::Package> readPackage(const fs::path& path, const Object& object, AssembleReport& report) {
  auto package = glb::read(path);
  if (!package.isOk()) {
    const Status& status = package.status();
    return Status(status.code(), "object '" + object.name + "': " + status.message(),
                  {status.where().file.empty() ? path.string() : status.where().file, status.where().element});
  }
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (!ec) report.inputBytes += size;
  return package;
}

Status assembleObject(const Scene& scene, std::size_t index, const fs::path& path, const AssembleSettings& settings,
                      AssembleReport& report, glb::Package& out) {
  const Object& object = scene.objects[index];
  const ObjectInput input{scene, object, scene.materialOf(object), path.string(), settings.keepUnused, report};
  const TechniqueRules& rules = *hooksOf(object.technique)->assemble;
  BAKE_ASSIGN_OR_RETURN(glb::Package package, readPackage(path, object, report));
  const Reached original = settings.keepUnused ? everything(package, rules) : Reached{};
  BAKE_RETURN_IF_ERROR(rules.adapt(package, input));
  Reached reached = reachedBy(package, rules);
  reached.add(original);
  BAKE_ASSIGN_OR_RETURN(const Renumbering renumbering, copyData(package, reached, rules, input, out));
  BAKE_RETURN_IF_ERROR(mergeRootExtensions(package, rules, input, out));
  copyStructure(std::move(package), renumbering, rules, input, out);
  return {};
}

// A node at `eye` looking down its local -Z toward `target`, +Y up as near the world's +Y as the
// direction allows (glTF cameras and lights both point down -Z).
glb::Node nodeLookingAt(const std::array<double, 3>& eye, const std::array<double, 3>& target) {
  std::array<double, 3> back{}, up{0, 1, 0}, right{}, trueUp{};
  double length = 0;
  for (int k = 0; k < 3; ++k) {
    back[k] = eye[k] - target[k];
    length += back[k] * back[k];
  }
  for (double& b : back) b /= std::sqrt(length);
  if (std::abs(back[1]) > 0.999) up = {0, 0, -1};
  const auto cross = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  right = cross(up, back);
  const double r = std::sqrt(right[0] * right[0] + right[1] * right[1] + right[2] * right[2]);
  for (double& x : right) x /= r;
  trueUp = cross(back, right);
  glb::Node node;
  node.matrix = std::array<double, 16>{right[0], right[1], right[2], 0, trueUp[0], trueUp[1], trueUp[2], 0,
                                       back[0],  back[1],  back[2],  0, eye[0],    eye[1],    eye[2],    1};
  return node;
}

// The scene's cameras as glTF perspective cameras on nodes of their own, so a viewer opens the
// assembled scene in the view the scene was planned for; the first is the one bakeplay takes.
void addCameras(const Scene& scene, glb::Package& out) {
  for (const Camera& camera : scene.cameras) {
    glb::Node node = nodeLookingAt(camera.eye, camera.target);
    node.name = camera.name.empty() ? "camera" : camera.name;
    node.camera = int(out.cameras.size());
    out.cameras.push_back({{"type", "perspective"},
                           {"name", node.name},
                           {"perspective",
                            {{"yfov", camera.yfovDegrees * std::acos(-1.0) / 180.0},
                             {"aspectRatio", double(camera.width) / camera.height},
                             {"znear", 0.01}}}});
    out.sceneRoots.push_back(int(out.nodes.size()));
    out.nodes.push_back(std::move(node));
  }
}

// The scene's lights as KHR_lights_punctual lights on nodes of their own (the packages' own lights are
// dropped); the first is the one bakeplay takes. A spot's cone is its outer angle (no inner fade) and
// its exponent goes to extras.spotExponent, which bakeplay reads (seed 004's OpenGL spot).
void addLights(const Scene& scene, glb::Package& out) {
  if (scene.lights.empty()) return;
  json lights = json::array();
  for (const SceneLight& light : scene.lights) {
    glb::Node node = light.type == "point" ? glb::Node{} : nodeLookingAt(light.position, light.target);
    if (light.type == "point") node.translation = light.position;
    node.name = light.name.empty() ? "light" : light.name;
    json entry = {{"type", light.type}, {"name", node.name}, {"color", light.colour}, {"intensity", light.intensity}};
    if (light.type == "spot") {
      entry["spot"] = {{"innerConeAngle", 0.0}, {"outerConeAngle", light.cutoffDegrees * std::acos(-1.0) / 180.0}};
      entry["extras"] = {{"spotExponent", light.exponent}};
    }
    node.extensions[kLightsExtension] = {{"light", lights.size()}};
    lights.push_back(entry);
    out.sceneRoots.push_back(int(out.nodes.size()));
    out.nodes.push_back(std::move(node));
  }
  out.extensions[kLightsExtension] = {{"lights", lights}};
}

}  // namespace

Result<glb::Package> assemble(const Scene& scene, const std::vector<fs::path>& packages, const AssembleSettings& settings,
                              AssembleReport* report) {
  if (packages.size() != scene.objects.size())
    return internalError("assemble: " + std::to_string(packages.size()) + " packages for " +
                         std::to_string(scene.objects.size()) + " objects");
  AssembleReport local;
  AssembleReport& out = report ? *report : local;
  glb::Package assembled;
  for (std::size_t k = 0; k < scene.objects.size(); ++k)
    BAKE_RETURN_IF_ERROR(assembleObject(scene, k, packages[k], settings, out, assembled));
  addCameras(scene, assembled);
  addLights(scene, assembled);
  return assembled;
}

}  // namespace bake::pipe
